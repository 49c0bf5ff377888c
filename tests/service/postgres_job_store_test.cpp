// What only the PostgreSQL job store does (job_store_test.cpp holds what every store does): its
// schema versioned and migrated once however many replicas start, and clear errors when the
// server is unreachable or newer.
#include "radiant/server/postgres_job_store.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "postgres_server.h"

namespace {

using namespace radiant::server;
using radiant::test::shared_postgres;

class PostgresJobStoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        const std::string missing = radiant::test::postgres_missing();
        if (!missing.empty()) GTEST_SKIP() << missing;
        database_ = "pg_store_" + std::to_string(getpid()) + "_" + std::to_string(++count_);
        shared_postgres().create_database(database_);
    }
    std::string uri() const { return shared_postgres().uri(database_); }

    std::string database_;

private:
    static inline int count_ = 0;
};

TEST_F(PostgresJobStoreTest, ReplicasStartingTogetherMigrateTheSchemaOnce) {
    std::vector<std::unique_ptr<PostgresJobStore>> replicas(3);
    std::vector<std::thread> starts;
    for (auto& replica : replicas) {
        starts.emplace_back([&] { replica = std::make_unique<PostgresJobStore>(uri()); });
    }
    for (std::thread& t : starts) t.join();
    for (const auto& replica : replicas) {
        ASSERT_TRUE(replica);
        EXPECT_EQ(replica->schema_version(), PostgresJobStore::kSchemaVersion);
    }
    // One version row, however many replicas migrated.
    shared_postgres().execute(database_,
                              "DO $$ BEGIN IF (SELECT COUNT(*) FROM radiant_schema) <> 1 THEN"
                              " RAISE EXCEPTION 'schema rows'; END IF; END $$");
}

TEST_F(PostgresJobStoreTest, ASchemaNewerThanThisBuildIsRefused) {
    { PostgresJobStore first(uri()); }
    shared_postgres().execute(database_, "UPDATE radiant_schema SET version = 99");
    try {
        PostgresJobStore store(uri());
        FAIL() << "a radiantd opened a schema newer than its own";
    } catch (const StoreError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("version 99"), std::string::npos) << what;
        EXPECT_NE(what.find("upgrade radiantd"), std::string::npos) << what;
    }
}

TEST_F(PostgresJobStoreTest, AnUnreachableServerIsAnUnwritableStoreWithTheReason) {
    try {
        PostgresJobStore store("host=/nonexistent-radiant-socket-dir dbname=radiant user=radiant");
        FAIL() << "a store opened without a server";
    } catch (const StoreError& e) {
        EXPECT_TRUE(e.unwritable());
        EXPECT_NE(std::string(e.what()).find("cannot connect to PostgreSQL"), std::string::npos)
            << e.what();
    }
}

}  // namespace
