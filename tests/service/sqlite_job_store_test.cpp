// What only the SQLite job store does (job_store_test.cpp holds what every store does): the lock
// on its directory, private files, attempts counted across process deaths, cancels that survive a
// restart, and a full store reported unwritable.
#include "radiant/server/sqlite_job_store.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "service_scenes.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant::server;

class SqliteJobStoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("radiant_store_test_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static JobRecord job(std::string scene = radiant::test::tiny_room()) {
        JobRecord j;
        j.id = new_job_id();
        j.scene_json = std::move(scene);
        j.created = now_millis();
        return j;
    }
    static unsigned mode(const fs::path& p) {
        struct stat st {};
        EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
        return st.st_mode & 0777;
    }

    fs::path dir_;
};

TEST_F(SqliteJobStoreTest, ASecondStoreOnTheDirectoryIsRefused) {
    {
        SqliteJobStore first(dir_);
        try {
            SqliteJobStore second(dir_);
            FAIL() << "a second store opened the locked directory";
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            const std::string pid = std::to_string(getpid());
            EXPECT_NE(what.find("in use by another radiantd"), std::string::npos) << what;
            EXPECT_NE(what.find(pid), std::string::npos) << what;
        }
    }
    SqliteJobStore again(dir_);  // the lock goes with its holder
}

TEST_F(SqliteJobStoreTest, DirectoryIsPrivateAndFilesTooEvenWhenTheyWereNot) {
    const mode_t old_umask = ::umask(022);
    fs::create_directories(dir_);
    fs::permissions(dir_, fs::perms(0755));
    {
        SqliteJobStore store(dir_);
        store.insert(job());
    }
    // An older store's world-readable database is made private too.
    fs::permissions(dir_ / "radiant.db", fs::perms(0644));
    fs::permissions(dir_, fs::perms(0755));
    {
        SqliteJobStore store(dir_);
        store.insert(job());  // WAL and shared-memory files exist while the store is open
        EXPECT_EQ(mode(dir_), 0700u);
        for (const char* name :
             {"radiant.db", "radiant.db-wal", "radiant.db-shm", "radiant.lock"}) {
            ASSERT_TRUE(fs::exists(dir_ / name)) << name;
            EXPECT_EQ(mode(dir_ / name), 0600u) << name;
        }
    }
    ::umask(old_umask);
}

TEST_F(SqliteJobStoreTest, AJobWhoseProcessDiedTwiceFailsWithTheReason) {
    const JobRecord j = job();
    const JobRecord released = job();
    {
        SqliteJobStore store(dir_);
        store.insert(j);
        store.insert(released);
        store.mark_running(j.id, now_millis());  // the process dies during the solve
        // A clean shutdown gives its attempt back, however often it happens.
        for (int i = 0; i < 3; ++i) {
            store.mark_running(released.id, now_millis());
            store.release(released.id);
        }
    }
    {
        SqliteJobStore store(dir_);
        const UnfinishedJobs first = store.requeue_unfinished(2);
        EXPECT_EQ(first.requeued.size(), 2u);
        EXPECT_TRUE(first.failed.empty());
        store.mark_running(j.id, now_millis());  // and dies again
    }
    SqliteJobStore store(dir_);
    const UnfinishedJobs second = store.requeue_unfinished(2);
    ASSERT_EQ(second.failed, std::vector<std::string>{j.id});
    EXPECT_EQ(second.requeued, std::vector<std::string>{released.id});
    const auto failed = store.find(j.id, false);
    EXPECT_EQ(failed->status, JobStatus::failed);
    EXPECT_NE(failed->error.find("died"), std::string::npos) << failed->error;
    EXPECT_GT(failed->finished, 0);
}

TEST_F(SqliteJobStoreTest, AnAcceptedCancelSurvivesTheProcess) {
    const JobRecord j = job();
    {
        SqliteJobStore store(dir_);
        store.insert(j);
        store.mark_running(j.id, now_millis());
        store.request_cancel(j.id);  // answered 202; the process dies before the solve stops
    }
    SqliteJobStore store(dir_);
    const UnfinishedJobs unfinished = store.requeue_unfinished(2);
    EXPECT_EQ(unfinished.cancelled, std::vector<std::string>{j.id});
    EXPECT_TRUE(unfinished.requeued.empty());
    EXPECT_EQ(store.find(j.id, false)->status, JobStatus::cancelled);
}

TEST_F(SqliteJobStoreTest, AFullStoreIsUnwritable) {
    JobStoreOptions options;
    options.max_bytes = 256 << 10;
    SqliteJobStore store(dir_, options);
    // A refused row (one idempotency key twice) is not a full store.
    JobRecord keyed = job();
    keyed.idempotency_key = new_job_id();  // any key, used twice
    store.insert(keyed);
    keyed.id = new_job_id();
    try {
        store.insert(keyed);
        FAIL() << "a second job with one idempotency key was stored";
    } catch (const StoreError& e) {
        EXPECT_FALSE(e.unwritable());
    }
    EXPECT_TRUE(store.health().writable);
    bool full = false;
    for (int i = 0; i < 100 && !full; ++i) {
        try {
            store.insert(job(std::string(32 << 10, 'x')));
        } catch (const StoreError& e) {
            EXPECT_TRUE(e.unwritable());
            full = true;
        }
    }
    ASSERT_TRUE(full);
    const StoreHealth health = store.health();
    EXPECT_FALSE(health.writable);
    EXPECT_NE(health.reason.find("full"), std::string::npos) << health.reason;
}

}  // namespace
