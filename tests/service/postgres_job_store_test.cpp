// What only the PostgreSQL job store does (job_store_test.cpp holds what every store does): its
// schema versioned and migrated once however many replicas start (and from older versions), and
// clear errors when the server is unreachable or newer.
#include "radiant/server/postgres_job_store.h"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "postgres_fixture.h"

namespace {

using namespace radiant::server;
using radiant::test::shared_postgres;

using PostgresJobStoreTest = radiant::test::PostgresFixture;

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

TEST_F(PostgresJobStoreTest, AVersionOneDatabaseGainsRunningSnapshotsAndLeaseTokensOnStart) {
    { PostgresJobStore first(uri()); }
    // The database as radiantd with schema 1 left it: no snapshots, no change notifications, no
    // lease tokens.
    shared_postgres().execute(database_,
                              "DROP TABLE snapshots; DROP FUNCTION radiant_job_changed CASCADE;"
                              " DROP FUNCTION radiant_snapshot_changed;"
                              " ALTER TABLE jobs DROP COLUMN lease_token;"
                              " UPDATE radiant_schema SET version = 1");
    PostgresJobStore store(uri());
    EXPECT_EQ(store.schema_version(), PostgresJobStore::kSchemaVersion);
    JobRecord job;
    job.id = new_job_id();
    job.scene_json = "{}";
    job.created = now_millis();
    store.insert(job);
    const auto claimed = store.claim("a", std::chrono::seconds(60), 2);
    ASSERT_TRUE(claimed);
    EXPECT_GT(claimed->lease_token, 0);
    SnapshotInfo info;
    info.values_event_id = info.radiosity_event_id = 1;
    store.save_snapshot(job.id, info, std::string("mesh"), claimed->lease_token);
    EXPECT_EQ(store.running_snapshot(job.id, 0)->blob, "mesh");
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
