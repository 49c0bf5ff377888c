// Three radiantd replicas on one PostgreSQL store, end to end (issue 31): jobs submitted to any
// replica at random all end done exactly once, with the same result as any other solve of the
// scene, although the replica running a job is killed (SIGKILL) twice.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon.h"
#include "daemon_fixture.h"
#include "postgres_server.h"
#include "service_scenes.h"

namespace {

using boost::beast::http::verb;
using nlohmann::json;
using namespace std::chrono_literals;
using radiant::test::Daemon;
using radiant::test::http_call;
using radiant::test::shared_postgres;

class ReplicasTest : public radiant::test::DaemonFixture {
protected:
    void SetUp() override {
        const std::string missing = radiant::test::postgres_missing();
        if (!missing.empty()) GTEST_SKIP() << missing;
        DaemonFixture::SetUp();
        database_ = "replicas_" + std::to_string(getpid());
        shared_postgres().create_database(database_);
    }

    /// A replica named `name`; a short lease, so that a killed replica's job moves on soon.
    std::unique_ptr<Daemon> start(const std::string& name) {
        return std::make_unique<Daemon>(
            dir_ / name,
            std::vector<std::string>{"--store", shared_postgres().url(database_), "--replica", name,
                                     "--lease-seconds", "2", "--workers", "1"},
            log());
    }
    /// `sql`'s first row on the shared database.
    std::vector<std::string> query(const std::string& sql) const {
        return shared_postgres().query_row(database_, sql);
    }

    std::string database_;
};

/// Solves in about a tenth of a second, always to the same answer (no time limit), so that
/// every solve of it can be compared; a replica killed while the queue is full holds one.
std::string room() { return radiant::test::tiny_room(); }

TEST_F(ReplicasTest, ThirtyJobsEndDoneOnceThoughTheReplicaRunningOneIsKilledTwice) {
    std::vector<std::unique_ptr<Daemon>> replicas;
    std::vector<std::string> names = {"r0", "r1", "r2"};
    for (const std::string& name : names) replicas.push_back(start(name));

    const unsigned seed = static_cast<unsigned>(std::random_device{}());
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 random(seed);
    std::vector<std::string> ids;
    for (int i = 0; i < 30; ++i) {
        ids.push_back(post(*replicas[random() % replicas.size()], room()));
    }

    std::vector<std::string> killed_jobs;
    for (int kill = 0; kill < 2; ++kill) {
        // A job running now, and the replica running it (its lease owner).
        std::vector<std::string> running;
        const auto deadline = std::chrono::steady_clock::now() + 30s;
        while (running.empty() && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(random() % 200));
            running = query(
                "SELECT id, lease_owner FROM jobs WHERE status = 'running' ORDER BY random()"
                " LIMIT 1");
        }
        ASSERT_EQ(running.size(), 2u) << "no job ran";
        const auto victim = std::find(names.begin(), names.end(), running[1]);
        ASSERT_NE(victim, names.end()) << running[1];
        const std::size_t index = static_cast<std::size_t>(victim - names.begin());
        replicas[index]->stop(SIGKILL);
        // The job it held when it died (maybe a later one than `running`: jobs are short).
        const std::vector<std::string> held = query(
            "SELECT id FROM jobs WHERE status = 'running' AND lease_owner = '" + running[1] + "'");
        ASSERT_EQ(held.size(), 1u) << "the killed replica held no job";
        killed_jobs.push_back(held[0]);
        // A fresh replica takes the dead one's place (a new name: a new process).
        names[index] = "r" + std::to_string(names.size() + kill);
        replicas[index] = start(names[index]);
        // The same job is not killed twice: each kill costs it an attempt.
        ASSERT_EQ(wait_for(*replicas[(index + 1) % 3], held[0], "done", 30)["status"], "done");
    }

    json reference;
    for (const std::string& id : ids) {
        const Daemon& any = *replicas[random() % replicas.size()];
        ASSERT_EQ(wait_for(any, id, "done", 60)["status"], "done") << id;
        const auto result = http_call(any.port(), verb::get, "/v1/jobs/" + id + "/result");
        ASSERT_EQ(result.status, 200u) << id;
        const json doc = json::parse(result.body);
        const double average = doc["sensors"][0]["average"].get<double>();
        if (reference.is_null()) reference = average;
        EXPECT_NEAR(average, reference.get<double>(), 1e-9 * std::abs(reference.get<double>()))
            << id;
    }
    // One result per job; the killed jobs ran twice, every other one once.
    EXPECT_EQ(query("SELECT COUNT(*) FROM results")[0], "30");
    EXPECT_EQ(query("SELECT COUNT(*) FROM jobs WHERE status = 'done'")[0], "30");
    for (const std::string& id : killed_jobs) {
        EXPECT_EQ(query("SELECT attempts FROM jobs WHERE id = '" + id + "'")[0], "2") << id;
    }
    EXPECT_EQ(query("SELECT COUNT(*) FROM jobs WHERE attempts <> 1")[0], "2");
}

}  // namespace
