// Three radiantd replicas on one PostgreSQL store, end to end (issue 31): jobs submitted to any
// replica at random all end done exactly once, with the same result as any other solve of the
// scene, although the replica running a job is killed (SIGKILL) twice; and a job's event stream
// is followed, and resumed, on replicas other than the one solving it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
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
#include "sse.h"

namespace {

using boost::beast::http::verb;
using nlohmann::json;
using namespace std::chrono_literals;
using radiant::test::Daemon;
using radiant::test::http_call;
using radiant::test::parse_sse;
using radiant::test::shared_postgres;
using radiant::test::SseEvent;

class ReplicasTest : public radiant::test::DaemonFixture {
protected:
    void SetUp() override {
        const std::string missing = radiant::test::postgres_missing();
        if (!missing.empty()) GTEST_SKIP() << missing;
        DaemonFixture::SetUp();
        database_ = "replicas_" + std::to_string(getpid()) + "_" + std::to_string(++count_);
        shared_postgres().create_database(database_);
    }

    /// A replica named `name`; a short lease, so that a killed replica's job moves on soon.
    std::unique_ptr<Daemon> start(const std::string& name, const std::string& lease_seconds = "2",
                                  const std::string& drain_seconds = "20") {
        return std::make_unique<Daemon>(
            dir_ / name,
            std::vector<std::string>{"--store", shared_postgres().url(database_), "--replica", name,
                                     "--lease-seconds", lease_seconds, "--drain-seconds",
                                     drain_seconds, "--workers", "1"},
            log());
    }
    /// `sql`'s first row on the shared database.
    std::vector<std::string> query(const std::string& sql) const {
        return shared_postgres().query_row(database_, sql);
    }

    std::string database_;

private:
    static inline int count_ = 0;
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
    std::vector<std::string> killed_jobs;
    int replaced = 0;
    for (int kill = 0; kill < 2; ++kill) {
        // Half the jobs before each kill: 30 short jobs at once could all be done before the
        // second kill found one running.
        for (int i = 0; i < 15; ++i) {
            ids.push_back(post(*replicas[random() % replicas.size()], room()));
        }
        // Kill the replica running a job. A short job may end between the query and the kill,
        // leaving its replica idle when it dies: then it held nothing, and the next one is tried.
        std::vector<std::string> held;
        std::size_t index = 0;
        for (int attempt = 0; attempt < 5 && held.empty(); ++attempt) {
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
            index = static_cast<std::size_t>(victim - names.begin());
            replicas[index]->stop(SIGKILL);
            // The job it held when it died (maybe a later one than `running`).
            held = query("SELECT id FROM jobs WHERE status = 'running' AND lease_owner = '" +
                         running[1] + "'");
            // A fresh replica takes the dead one's place (a new name: a new process).
            names[index] = "r" + std::to_string(names.size() + replaced++);
            replicas[index] = start(names[index]);
        }
        ASSERT_EQ(held.size(), 1u) << "no killed replica held a job";
        killed_jobs.push_back(held[0]);
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

TEST_F(ReplicasTest, ASigtermedReplicaHandsItsRunningJobToAnotherAtOnce) {
    // A lease far longer than the test: only a hand-back lets the other replica take the job.
    const std::unique_ptr<Daemon> a = start("a", "600", "0.5");
    const std::string id = post(*a, radiant::test::slow_room(3));
    ASSERT_EQ(wait_for(*a, id, "running")["status"], "running");
    ASSERT_EQ(query("SELECT lease_owner FROM jobs WHERE id = '" + id + "'")[0], "a");
    const std::unique_ptr<Daemon> b = start("b", "600", "0.5");
    // Both report the start the claim stored (the database's clock), not a's own.
    EXPECT_EQ(job(*a, id)["started"], job(*b, id)["started"]);
    EXPECT_EQ(a->stop(SIGTERM), 0) << "a drained past its deadline and stopped cleanly";
    EXPECT_EQ(wait_for(*b, id, "done", 30)["status"], "done");
    EXPECT_EQ(query("SELECT lease_owner FROM jobs WHERE id = '" + id + "'")[0], "");
    EXPECT_EQ(query("SELECT COUNT(*) FROM results WHERE job_id = '" + id + "'")[0], "1");
    // a's cut-short run is no failed attempt: b's is the only one counted.
    EXPECT_EQ(query("SELECT attempts FROM jobs WHERE id = '" + id + "'")[0], "1");
    EXPECT_NE(radiant::test::read_text(log()).find("job " + id + " claimed by b"),
              std::string::npos);
}

TEST_F(ReplicasTest, AReplicaIsReadyOnlyWhileItsDatabaseAnswers) {
    const std::unique_ptr<Daemon> r = start("r");
    EXPECT_EQ(http_call(r->port(), verb::get, "/readyz").status, 200u);
    const auto metrics = http_call(r->port(), verb::get, "/metrics");
    EXPECT_NE(metrics.body.find("radiant_queue_length{replica=\"r\"} 0"), std::string::npos)
        << metrics.body;
    // The database refuses this replica's connections, as when it is down or cut off.
    shared_postgres().execute("postgres",
                              "ALTER DATABASE " + database_ + " ALLOW_CONNECTIONS false");
    shared_postgres().execute("postgres",
                              "SELECT pg_terminate_backend(pid) FROM pg_stat_activity"
                              " WHERE datname = '" +
                                  database_ + "'");
    const auto down = http_call(r->port(), verb::get, "/readyz");
    EXPECT_EQ(down.status, 503u);
    const json error = json::parse(down.body)["error"];
    EXPECT_EQ(error["code"], "store_unwritable") << down.body;
    EXPECT_NE(error["message"].get<std::string>().find("job store: "), std::string::npos)
        << down.body;
    EXPECT_EQ(http_call(r->port(), verb::get, "/healthz").status, 200u)
        << "alive all the same: a restart would not bring the database back";
    shared_postgres().execute("postgres",
                              "ALTER DATABASE " + database_ + " ALLOW_CONNECTIONS true");
    EXPECT_EQ(http_call(r->port(), verb::get, "/readyz").status, 200u) << "ready again";
}

TEST_F(ReplicasTest, AStreamOnOneReplicaFollowsAJobSolvedByAnotherAndResumesOnAThird) {
    // Only b runs when the job is submitted, so b solves it; a and c start once it runs.
    const std::unique_ptr<Daemon> b = start("b");
    const std::string id = post(*b, radiant::test::slow_room(6));
    ASSERT_EQ(wait_for(*b, id, "running")["status"], "running");
    ASSERT_EQ(query("SELECT lease_owner FROM jobs WHERE id = '" + id + "'")[0], "b");
    const std::unique_ptr<Daemon> a = start("a");
    const std::unique_ptr<Daemon> c = start("c");
    // While b solves, a's result of the job carries the mesh b stored last.
    json running;
    const auto deadline = std::chrono::steady_clock::now() + 4s;
    do {
        const auto r = http_call(a->port(), verb::get, "/v1/jobs/" + id + "/result?include=mesh");
        running = r.status == 200u ? json::parse(r.body) : json();
        if (!running.contains("mesh")) std::this_thread::sleep_for(50ms);
    } while (!running.contains("mesh") && std::chrono::steady_clock::now() < deadline);
    EXPECT_TRUE(running.contains("mesh")) << "no stored snapshot of the running solve";
    EXPECT_EQ(running["scene"], "tiny-room") << "the scene's name, read from the store";
    EXPECT_EQ(job(*a, id)["status"], "running");

    const auto stream = http_call(a->port(), verb::get, "/v1/jobs/" + id + "/events");
    ASSERT_EQ(stream.status, 200u);
    const std::vector<SseEvent> events = parse_sse(stream.body);
    ASSERT_GE(events.size(), 4u) << stream.body.substr(0, 2000);
    for (std::size_t i = 1; i < events.size(); ++i) {
        EXPECT_LT(events[i - 1].id, events[i].id) << "event " << i << " out of order";
    }
    const SseEvent& done = events.back();
    ASSERT_EQ(done.name, "done");
    EXPECT_EQ(json::parse(done.data)["status"], "done");
    // b's progress and its snapshots, through the store: a mesh before the first radiosity
    // event, radiosity while it ran, and the final one.
    std::size_t progress = 0, running_radiosity = 0;
    std::uint64_t mesh_version = 0, first_running_id = 0, final_id = 0;
    for (const SseEvent& e : events) {
        if (e.name == "progress") ++progress;
        if (e.name == "mesh") mesh_version = json::parse(e.data)["mesh_version"];
        if (e.name != "radiosity") continue;
        const json data = json::parse(e.data);
        EXPECT_EQ(data["mesh_version"], mesh_version) << "a radiosity event before its mesh";
        if (data["final"] == true) {
            final_id = e.id;
        } else if (running_radiosity++ == 0) {
            first_running_id = e.id;
        }
    }
    EXPECT_GE(progress, 2u);
    ASSERT_GE(running_radiosity, 1u) << "no snapshot of the running solve reached replica a";
    ASSERT_GT(final_id, 0u) << "no final radiosity event";

    // A client that saw events up to the first running snapshot resumes on c: it gets only what
    // came after, ending with the same final snapshot and the same `done`.
    const auto resumed = http_call(c->port(), verb::get, "/v1/jobs/" + id + "/events", "",
                                   {{"Last-Event-ID", std::to_string(first_running_id)}});
    ASSERT_EQ(resumed.status, 200u);
    const std::vector<SseEvent> missed = parse_sse(resumed.body);
    ASSERT_FALSE(missed.empty());
    for (const SseEvent& e : missed) EXPECT_GT(e.id, first_running_id) << e.name;
    EXPECT_EQ(missed.back().name, "done");
    EXPECT_EQ(missed.back().id, done.id);
    EXPECT_EQ(missed.back().data, done.data);
    const auto final_event = std::find_if(missed.begin(), missed.end(), [](const SseEvent& e) {
        return e.name == "radiosity" && json::parse(e.data)["final"] == true;
    });
    ASSERT_NE(final_event, missed.end());
    EXPECT_EQ(final_event->id, final_id);
    EXPECT_EQ(query("SELECT attempts FROM jobs WHERE id = '" + id + "'")[0], "1");
}

}  // namespace
