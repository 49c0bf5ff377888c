// Several job queues (as several radiantd would) on one PostgreSQL store: they share one queue,
// run each job once, hear a cancel accepted by another, and take over the job of one that died.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "postgres_fixture.h"
#include "radiant/server/job_queue.h"
#include "radiant/server/postgres_job_store.h"
#include "service_scenes.h"

namespace {

using namespace radiant::server;
using namespace std::chrono_literals;

/// One radiantd as the queue sees it: its own connection to the shared store, and its workers.
struct Replica {
    Replica(const std::string& uri, const std::string& name) : store(uri) {
        JobQueueOptions options;
        options.replica = name;
        options.lease = 2s;  // a dead replica's job moves on within the test's patience
        queue = std::make_unique<JobQueue>(store, metrics, options);
    }
    PostgresJobStore store;
    Metrics metrics;
    std::unique_ptr<JobQueue> queue;
};

class SharedQueueTest : public radiant::test::PostgresFixture {
protected:
    /// Polls `queue` until job `id` is `want` or `seconds` pass; returns its last status.
    static JobStatus wait_for(JobQueue& queue, const std::string& id, JobStatus want,
                              double seconds = 20) {
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        JobStatus status = queue.find(id)->status;
        while (status != want && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(20ms);
            status = queue.find(id)->status;
        }
        return status;
    }
};

TEST_F(SharedQueueTest, JobsSubmittedToEitherReplicaRunOnceAndAreSeenByBoth) {
    Replica a(uri(), "a");
    Replica b(uri(), "b");
    std::vector<std::string> ids;
    for (int i = 0; i < 6; ++i) {
        JobQueue& to = i % 2 ? *b.queue : *a.queue;
        const SubmitOutcome outcome = to.submit(radiant::test::tiny_room(), "");
        ASSERT_EQ(outcome.kind, SubmitOutcome::Kind::accepted);
        ids.push_back(outcome.job.id);
    }
    for (const std::string& id : ids) {
        ASSERT_EQ(wait_for(*a.queue, id, JobStatus::done), JobStatus::done) << id;
        // The replica that ran the job updates its own record just after the store's commit,
        // so it may say `running` a few milliseconds longer than the other one.
        EXPECT_EQ(wait_for(*b.queue, id, JobStatus::done, 5), JobStatus::done) << id;
        EXPECT_TRUE(b.store.result(id)) << "no stored result for " << id;
    }
    EXPECT_EQ(a.store.count_by_status().at(JobStatus::done), ids.size());
    EXPECT_EQ(a.queue->queue_length(), 0u);
}

TEST_F(SharedQueueTest, ACancelAcceptedByOneReplicaStopsTheSolveOnAnother) {
    Replica a(uri(), "a");
    Replica b(uri(), "b");
    const std::string id = a.queue->submit(radiant::test::slow_room(), "").job.id;
    ASSERT_EQ(wait_for(*a.queue, id, JobStatus::running), JobStatus::running);
    // Whichever replica claimed it, the other one takes the cancel.
    std::this_thread::sleep_for(200ms);
    JobQueue& runner = a.queue->running_scene(id).name.empty() ? *b.queue : *a.queue;
    JobQueue& other = &runner == a.queue.get() ? *b.queue : *a.queue;
    ASSERT_FALSE(runner.running_scene(id).name.empty()) << "neither replica runs the job";
    const auto asked = std::chrono::steady_clock::now();
    other.cancel(id);
    EXPECT_EQ(wait_for(other, id, JobStatus::cancelled, 10), JobStatus::cancelled);
    // A heartbeat a second, then the engine's own stop within a second.
    EXPECT_LT(std::chrono::steady_clock::now() - asked, 4s);
    EXPECT_TRUE(a.store.result(id)) << "the best result so far is kept";
}

TEST_F(SharedQueueTest, AQueuedJobCancelledOnAnyReplicaEndsAtOnceAndNeverRuns) {
    Replica a(uri(), "a");
    Replica b(uri(), "b");
    // Both replicas' only workers are busy, so the next job waits in the shared queue.
    const std::string busy1 = a.queue->submit(radiant::test::slow_room(), "").job.id;
    const std::string busy2 = b.queue->submit(radiant::test::slow_room(), "").job.id;
    ASSERT_EQ(wait_for(*a.queue, busy1, JobStatus::running), JobStatus::running);
    ASSERT_EQ(wait_for(*a.queue, busy2, JobStatus::running), JobStatus::running);
    const std::string queued = a.queue->submit(radiant::test::tiny_room(), "").job.id;
    EXPECT_EQ(b.queue->queue_length(), 1u);
    const auto answer = b.queue->cancel(queued);
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, JobStatus::cancelled);
    EXPECT_EQ(a.queue->find(queued)->status, JobStatus::cancelled);
    EXPECT_FALSE(a.store.result(queued));
    EXPECT_EQ(b.queue->queue_length(), 0u);
}

TEST_F(SharedQueueTest, TheJobOfAReplicaThatDiedIsFinishedByAnother) {
    PostgresJobStore dead(uri());
    JobRecord job;
    job.id = new_job_id();
    job.scene_json = radiant::test::tiny_room();
    job.created = now_millis();
    dead.insert(job);
    // A replica claims the job, then dies (kill -9): no heartbeat, no release.
    ASSERT_EQ(dead.claim("dead", 500ms, kMaxJobAttempts)->id, job.id);
    Replica b(uri(), "b");
    EXPECT_EQ(wait_for(*b.queue, job.id, JobStatus::done, 20), JobStatus::done);
    EXPECT_TRUE(b.store.result(job.id));
}

}  // namespace
