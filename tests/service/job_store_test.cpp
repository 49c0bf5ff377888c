// What every job store must do, run against each: the SQLite store in a temporary directory and
// the PostgreSQL store on a cluster of its own (postgres_server.h). Rows, results and meshes; the
// shared queue's claims, leases, heartbeats and attempts; cancels from any replica.
#include "radiant/server/job_store.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "postgres_server.h"
#include "radiant/server/postgres_job_store.h"
#include "radiant/server/sqlite_job_store.h"
#include "service_scenes.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant::server;
using namespace std::chrono_literals;

constexpr int kMaxAttempts = 2;

using radiant::test::shared_postgres;

class JobStoreContract : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        name_ = "store_" + std::to_string(getpid()) + "_" + std::to_string(++count_);
        if (postgresql()) {
            const std::string missing = radiant::test::postgres_missing();
            if (!missing.empty()) GTEST_SKIP() << missing;
            shared_postgres().create_database(name_);
        } else {
            dir_ = fs::temp_directory_path() / (name_ + "_" + info->name());
            fs::remove_all(dir_);
        }
        store_ = open();
    }
    void TearDown() override {
        replicas_.clear();
        store_.reset();
        if (!dir_.empty()) fs::remove_all(dir_);
    }

    bool postgresql() const { return GetParam() == "postgresql"; }
    std::unique_ptr<JobStore> open() const {
        if (postgresql()) return std::make_unique<PostgresJobStore>(shared_postgres().uri(name_));
        return std::make_unique<SqliteJobStore>(dir_);
    }
    JobStore& store() { return *store_; }
    /// The store as another replica sees it: its own connection on PostgreSQL; on SQLite, which
    /// one process owns, the same store.
    JobStore& replica() {
        if (!postgresql()) return *store_;
        replicas_.push_back(open());
        return *replicas_.back();
    }
    /// Stops the store (a process that died) and opens it again.
    void restart() {
        store_.reset();
        store_ = open();
    }

    static JobRecord job(const std::string& key = "") {
        JobRecord j;
        j.id = new_job_id();
        j.scene_json = radiant::test::tiny_room();
        j.idempotency_key = key;
        j.created = now_millis();
        return j;
    }
    JobRecord inserted() {
        JobRecord j = job();
        store().insert(j);
        return j;
    }

private:
    static inline int count_ = 0;
    std::string name_;
    fs::path dir_;
    std::unique_ptr<JobStore> store_;
    std::vector<std::unique_ptr<JobStore>> replicas_;
};

TEST_P(JobStoreContract, JobsAreFoundAndListedNewestFirstInPages) {
    std::vector<JobRecord> jobs;
    for (int i = 0; i < 5; ++i) jobs.push_back(inserted());
    const auto found = store().find(jobs[2].id);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->status, JobStatus::queued);
    EXPECT_EQ(found->scene_json, jobs[2].scene_json);
    EXPECT_EQ(found->created, jobs[2].created);
    EXPECT_TRUE(store().find(jobs[2].id, false)->scene_json.empty());
    EXPECT_FALSE(store().find("no-such-job"));

    const auto first = store().list(2, "");
    ASSERT_EQ(first.size(), 2u);
    EXPECT_EQ(first[0].id, jobs[4].id);
    EXPECT_EQ(first[1].id, jobs[3].id);
    EXPECT_TRUE(first[0].scene_json.empty());
    const auto rest = store().list(10, first[1].id);
    ASSERT_EQ(rest.size(), 3u);
    EXPECT_EQ(rest[2].id, jobs[0].id);
    EXPECT_EQ(store().count_by_status().at(JobStatus::queued), 5u);
}

TEST_P(JobStoreContract, ASecondJobWithOneIdempotencyKeyIsARefusedRow) {
    const JobRecord first = job("key-1");
    store().insert(first);
    try {
        store().insert(job("key-1"));
        FAIL() << "a second job with one idempotency key was stored";
    } catch (const StoreError& e) {
        EXPECT_FALSE(e.unwritable()) << e.what();
    }
    EXPECT_EQ(store().find_by_idempotency_key("key-1")->id, first.id);
    EXPECT_FALSE(store().find_by_idempotency_key("key-2"));
    EXPECT_TRUE(store().health().writable);
}

TEST_P(JobStoreContract, AFinishedJobKeepsItsResultMeshProgressAndWarnings) {
    const JobRecord j = inserted();
    JobProgress progress;
    progress.sequence = 42;
    progress.fraction = 1;
    progress.rays = 1234;
    StoredMesh mesh;
    mesh.info.version = 3;
    mesh.info.mesh_version = 2;
    mesh.info.mesh_event_id = 40;
    mesh.info.radiosity_event_id = 41;
    mesh.info.final = true;
    mesh.blob = std::string("\0\x01\xff binary \0 mesh", 17);  // zero bytes survive
    store().save_warnings(j.id, nlohmann::json::array({{{"code", "w"}}}));
    store().finish(j.id, JobStatus::done, now_millis(), progress, "", R"({"status":"converged"})",
                   mesh);

    const auto done = store().find(j.id, false);
    EXPECT_EQ(done->status, JobStatus::done);
    EXPECT_GT(done->finished, 0);
    EXPECT_EQ(done->progress.sequence, 42u);
    EXPECT_EQ(done->progress.rays, 1234u);
    EXPECT_EQ(done->warnings.size(), 1u);
    EXPECT_EQ(store().result(j.id), R"({"status":"converged"})");
    const auto stored = store().mesh(j.id);
    ASSERT_TRUE(stored);
    EXPECT_EQ(stored->blob, mesh.blob);
    EXPECT_EQ(stored->info.version, 3u);
    EXPECT_EQ(stored->info.mesh_version, 2u);
    EXPECT_EQ(stored->info.mesh_event_id, 40u);
    EXPECT_EQ(stored->info.radiosity_event_id, 41u);
    EXPECT_TRUE(stored->info.final);
    EXPECT_FALSE(store().result(inserted().id));
    EXPECT_EQ(store().count_by_status().at(JobStatus::done), 1u);
}

TEST_P(JobStoreContract, ClaimsTakeTheOldestWaitingJobAndNoJobTwice) {
    const JobRecord older = inserted();
    const JobRecord newer = inserted();
    const auto first = store().claim("a", 60s, kMaxAttempts);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->id, older.id);
    EXPECT_EQ(first->status, JobStatus::running);
    EXPECT_EQ(first->scene_json, older.scene_json);  // the runner needs the scene
    EXPECT_GT(first->started, 0);
    const auto second = replica().claim("b", 60s, kMaxAttempts);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->id, newer.id);
    EXPECT_FALSE(replica().claim("c", 60s, kMaxAttempts)) << "both jobs are held";
    EXPECT_EQ(store().find(older.id, false)->status, JobStatus::running);
}

TEST_P(JobStoreContract, ConcurrentReplicasClaimEveryJobExactlyOnce) {
    constexpr int kJobs = 40;
    for (int i = 0; i < kJobs; ++i) inserted();
    std::vector<JobStore*> replicas;
    for (int r = 0; r < 4; ++r) replicas.push_back(&replica());
    std::mutex mutex;
    std::multiset<std::string> claimed;
    std::vector<std::thread> threads;
    for (int r = 0; r < 4; ++r) {
        threads.emplace_back([&, r] {
            const std::string owner = "replica-" + std::to_string(r);
            while (const auto job = replicas[r]->claim(owner, 60s, kMaxAttempts)) {
                const std::lock_guard lock(mutex);
                claimed.insert(job->id);
            }
        });
    }
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(claimed.size(), static_cast<std::size_t>(kJobs));
    EXPECT_EQ(std::set<std::string>(claimed.begin(), claimed.end()).size(), claimed.size())
        << "a job was claimed twice";
    EXPECT_EQ(store().count_by_status().at(JobStatus::running), static_cast<std::size_t>(kJobs));
}

TEST_P(JobStoreContract, AHeartbeatKeepsTheLeaseAndAnExpiredOneIsClaimedAgain) {
    const JobRecord j = inserted();
    ASSERT_TRUE(store().claim("a", 300ms, kMaxAttempts));
    JobProgress seen;
    seen.sequence = 50;  // event ids a client may have seen from replica a
    store().save_progress(j.id, seen);
    for (int beat = 0; beat < 6; ++beat) {  // 600 ms, twice the lease
        std::this_thread::sleep_for(100ms);
        const LeaseRenewal renewal = store().renew_lease(j.id, "a", 300ms);
        EXPECT_TRUE(renewal.held);
        EXPECT_FALSE(renewal.cancel_requested);
    }
    EXPECT_FALSE(replica().claim("b", 300ms, kMaxAttempts)) << "a live lease was taken";

    std::this_thread::sleep_for(400ms);  // replica a dies: no heartbeat
    const auto again = replica().claim("b", 60s, kMaxAttempts);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->id, j.id);
    EXPECT_GE(again->progress.sequence, 1000050u) << "event ids must continue above the old run's";
    EXPECT_FALSE(store().renew_lease(j.id, "a", 300ms).held) << "a's late heartbeat";
    EXPECT_TRUE(store().renew_lease(j.id, "b", 60s).held);
}

TEST_P(JobStoreContract, ARunWhoseLeaseAnotherClaimTookCanNoLongerWriteTheJob) {
    const JobRecord j = inserted();
    // Two workers of one replica ("r"): the first is cut off from the store past its lease, the
    // second claims the job again. Only the lease token tells their writes apart.
    const auto cut_off = store().claim("r", 50ms, kMaxAttempts);
    ASSERT_TRUE(cut_off);
    std::this_thread::sleep_for(100ms);
    JobStore& other = replica();
    const auto owner = other.claim("r", 60s, kMaxAttempts);
    ASSERT_TRUE(owner);
    ASSERT_EQ(owner->id, j.id);
    EXPECT_GT(owner->lease_token, cut_off->lease_token);
    JobProgress progress;
    progress.sequence = owner->progress.sequence + 5;
    other.save_progress(j.id, progress, owner->lease_token);
    SnapshotInfo info;
    info.values_event_id = info.radiosity_event_id = progress.sequence;
    other.save_snapshot(j.id, info, std::string("owner's mesh"), owner->lease_token);

    // The cut-off run comes back and writes as if it still ran the job: all refused.
    JobProgress stale;
    stale.sequence = 3;
    store().save_progress(j.id, stale, cut_off->lease_token);
    store().save_warnings(j.id, nlohmann::json::array({"stale"}), cut_off->lease_token);
    SnapshotInfo stale_info;
    stale_info.values_event_id = stale_info.radiosity_event_id = 2;
    store().save_snapshot(j.id, stale_info, std::string("stale mesh"), cut_off->lease_token);
    EXPECT_FALSE(store().renew_lease(j.id, "r", 60s, cut_off->lease_token).held);
    EXPECT_FALSE(store().finish(j.id, JobStatus::done, now_millis(), stale, "",
                                std::string("stale result"), std::nullopt, cut_off->lease_token));
    store().release(j.id, cut_off->lease_token);

    const auto seen = store().find(j.id, false);
    EXPECT_EQ(seen->status, JobStatus::running);
    EXPECT_EQ(seen->progress.sequence, progress.sequence);
    EXPECT_EQ(seen->warnings, nlohmann::json::array());
    EXPECT_FALSE(store().result(j.id));
    const auto snapshot = store().running_snapshot(j.id, 0);
    ASSERT_TRUE(snapshot);
    EXPECT_EQ(snapshot->blob, "owner's mesh");
    // The owner's own writes go on.
    EXPECT_TRUE(other.renew_lease(j.id, "r", 60s, owner->lease_token).held);
    EXPECT_TRUE(other.finish(j.id, JobStatus::done, now_millis(), progress, "",
                             std::string("owner's result"), std::nullopt, owner->lease_token));
    EXPECT_EQ(store().result(j.id), "owner's result");
}

TEST_P(JobStoreContract, AJobWhoseRunnerDiesMaxAttemptsTimesFailsWithTheReason) {
    const JobRecord j = inserted();
    for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
        const auto claimed =
            replica().claim("runner-" + std::to_string(attempt), 50ms, kMaxAttempts);
        ASSERT_TRUE(claimed) << "attempt " << attempt;
        EXPECT_EQ(claimed->id, j.id);
        std::this_thread::sleep_for(100ms);  // the runner dies and its lease runs out
    }
    EXPECT_FALSE(replica().claim("last", 60s, kMaxAttempts)) << "a job past its attempts ran";
    const auto failed = store().find(j.id, false);
    EXPECT_EQ(failed->status, JobStatus::failed);
    EXPECT_NE(failed->error.find("started 2 times"), std::string::npos) << failed->error;
    EXPECT_GT(failed->finished, 0);
}

TEST_P(JobStoreContract, ACancelFromAnyReplicaReachesTheRunnerAndOutlivesIt) {
    const JobRecord running = inserted();
    const JobRecord orphan = inserted();
    ASSERT_EQ(store().claim("a", 60s, kMaxAttempts)->id, running.id);
    ASSERT_EQ(store().claim("b", 50ms, kMaxAttempts)->id, orphan.id);
    JobStore& other = replica();
    other.request_cancel(running.id);
    other.request_cancel(orphan.id);
    const LeaseRenewal renewal = store().renew_lease(running.id, "a", 60s);
    EXPECT_TRUE(renewal.held);
    EXPECT_TRUE(renewal.cancel_requested);
    // b dies before it saw the cancel: the job ends cancelled instead of running again.
    std::this_thread::sleep_for(100ms);
    EXPECT_FALSE(other.claim("c", 60s, kMaxAttempts));
    EXPECT_EQ(store().find(orphan.id, false)->status, JobStatus::cancelled);
}

TEST_P(JobStoreContract, AJobWhoseLeaseExpiredRunsAgainAfterARestart) {
    const JobRecord j = inserted();
    ASSERT_TRUE(store().claim("a", 50ms, kMaxAttempts));
    std::this_thread::sleep_for(100ms);
    restart();
    const UnfinishedJobs unfinished = store().requeue_unfinished(kMaxAttempts);
    EXPECT_EQ(unfinished.requeued, std::vector<std::string>{j.id});
    EXPECT_EQ(store().find(j.id, false)->status, JobStatus::queued);
}

TEST_P(JobStoreContract, ARunningJobsSnapshotIsReadByOtherReplicasUntilItFinishes) {
    const JobRecord j = inserted();
    SnapshotInfo info{.version = 1,
                      .mesh_version = 1,
                      .mesh_event_id = 3,
                      .radiosity_event_id = 4,
                      .values_event_id = 4,
                      .final = false,
                      .progress = {},
                      .sensors = nullptr};
    info.progress.sequence = 2;
    info.progress.stage = "shooting";
    const std::string blob("\0mesh\xff one\0", 11);
    store().save_snapshot(j.id, info, blob);
    EXPECT_FALSE(store().running_snapshot(j.id, 0)) << "a queued job has no running snapshot";
    ASSERT_TRUE(store().claim("a", 60s, kMaxAttempts));
    store().save_snapshot(j.id, info, blob);

    JobStore& other = replica();
    auto read = other.running_snapshot(j.id, 0);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->blob, blob);
    EXPECT_EQ(read->info.mesh_event_id, 3u);
    EXPECT_EQ(read->info.radiosity_event_id, 4u);
    EXPECT_EQ(read->info.values_event_id, 4u);
    EXPECT_EQ(read->info.progress.stage, "shooting");
    EXPECT_EQ(other.running_snapshot(j.id, 4)->blob, "") << "a reader that has the values";

    // The engine repeats its values under a newer event id: only the info is written.
    info.version = 2;
    info.radiosity_event_id = 6;
    info.progress.sequence = 5;
    store().save_snapshot(j.id, info, std::nullopt);
    read = other.running_snapshot(j.id, 4);
    EXPECT_EQ(read->info.radiosity_event_id, 6u);
    EXPECT_EQ(read->info.version, 2u);
    EXPECT_EQ(read->blob, "");
    EXPECT_EQ(other.running_snapshot(j.id, 0)->blob, blob);

    // New values with their mesh replace the row.
    info.values_event_id = 8;
    info.radiosity_event_id = 8;
    store().save_snapshot(j.id, info, std::string("two"));
    EXPECT_EQ(other.running_snapshot(j.id, 4)->blob, "two");

    store().finish(j.id, JobStatus::done, now_millis(), info.progress, "", std::nullopt);
    EXPECT_FALSE(other.running_snapshot(j.id, 0)) << "finish() ends the running snapshot";
    store().save_snapshot(j.id, info, blob);
    EXPECT_FALSE(other.running_snapshot(j.id, 0)) << "a late write after the finish";
    EXPECT_FALSE(store().mesh(j.id)) << "the running snapshot is no final mesh";
}

TEST_P(JobStoreContract, TheChangeTokenMovesWhenAnotherReplicaChangesTheJob) {
    const JobRecord j = inserted();
    JobStore& reader = replica();
    if (!postgresql()) {
        EXPECT_FALSE(reader.change_token(j.id)) << "SQLite has one process: nothing to wake";
        return;
    }
    // The feed starts listening with the first call; wait until it does.
    std::optional<std::uint64_t> before;
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (!(before = reader.change_token(j.id)) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(10ms);
    }
    ASSERT_TRUE(before) << "the change feed never listened";
    const auto changed = [&] {
        const auto until = std::chrono::steady_clock::now() + 5s;
        while (reader.change_token(j.id) == before && std::chrono::steady_clock::now() < until) {
            std::this_thread::sleep_for(5ms);
        }
        const bool moved = reader.change_token(j.id) != before;
        before = reader.change_token(j.id);
        return moved;
    };
    ASSERT_TRUE(store().claim("a", 60s, kMaxAttempts));
    EXPECT_TRUE(changed()) << "claim";
    JobProgress progress;
    progress.sequence = 7;
    store().save_progress(j.id, progress);
    EXPECT_TRUE(changed()) << "progress";
    // A heartbeat changes nothing a reader shows, and wakes nobody.
    store().renew_lease(j.id, "a", 60s);
    std::this_thread::sleep_for(200ms);
    EXPECT_EQ(reader.change_token(j.id), before) << "lease renewal";
    SnapshotInfo info;
    info.values_event_id = info.radiosity_event_id = 8;
    store().save_snapshot(j.id, info, std::string("mesh"));
    EXPECT_TRUE(changed()) << "snapshot";
    store().finish(j.id, JobStatus::done, now_millis(), progress, "", std::nullopt);
    EXPECT_TRUE(changed()) << "finish";
}

INSTANTIATE_TEST_SUITE_P(Stores, JobStoreContract, ::testing::Values("sqlite", "postgresql"),
                         [](const auto& store) { return store.param; });

}  // namespace
