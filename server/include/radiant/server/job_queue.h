// The job queue: a bounded FIFO of accepted jobs and N worker threads that run radiant::solve.
// Solves never run on I/O threads; the workers only publish progress into shared state, which
// HTTP sessions read when they choose to (slow clients never block a solve).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "radiant/server/job.h"
#include "radiant/server/job_snapshot.h"
#include "radiant/server/job_store.h"
#include "radiant/server/metrics.h"

namespace radiant::server {

struct JobQueueOptions {
    std::size_t workers = 1;       ///< concurrent solves; each solve uses `solve_threads`
    std::size_t queue_limit = 64;  ///< queued (not running) jobs before POST answers 429
    /// Per-job wall-clock cap on top of the scene's own; the result is `stopped` at it.
    std::optional<double> job_seconds;
    /// Per-job memory budget of the solve (SolveOptions::max_memory_bytes); 0: half the physical
    /// memory shared among the workers.
    std::size_t job_memory_bytes = 0;
    int solve_threads = 0;  ///< 0: all cores
    /// On a shared store: this process's name in job leases (default: host name and pid).
    std::string replica;
    /// On a shared store: how long a replica holds a job it no longer renews (it died or was
    /// cut off) before another one takes it. Renewed every second, so a few missed heartbeats
    /// (a slow store, a busy machine) cost nothing; a dead replica's job restarts this late.
    std::chrono::milliseconds lease{10000};
};

/// A solve started this many times whose process died each time is not run again: it fails.
inline constexpr int kMaxJobAttempts = 2;

struct SubmitOutcome {
    enum class Kind { accepted, replayed, queue_full, shutting_down, store_unwritable };
    Kind kind = Kind::accepted;
    JobRecord job;       ///< without scene_json; empty unless accepted or replayed
    std::string reason;  ///< store_unwritable: the store's error
};

/// What a running job's result documents need from its scene.
struct RunningScene {
    std::string name;
    int digits = 4;  ///< settings.digits
};

class JobQueue {
public:
    /// Re-queues what the store holds as queued or running (an earlier process stopped before
    /// finishing them; see JobStore::requeue_unfinished for those it ends instead), then starts
    /// the workers. On a shared store (JobStore::shared) nothing is queued in memory: workers
    /// claim jobs from the store under a lease they renew, so several processes share one queue.
    JobQueue(JobStore& store, Metrics& metrics, JobQueueOptions options);
    /// Calls shutdown().
    ~JobQueue();
    JobQueue(const JobQueue&) = delete;
    JobQueue& operator=(const JobQueue&) = delete;

    /// Stores and queues a scene that already passed proto::parse_scene. With a non-empty
    /// `idempotency_key` that an earlier job used, returns that job instead. Thread-safe.
    SubmitOutcome submit(const std::string& scene_json, const std::string& idempotency_key);

    /// The job without its scene text; live progress for queued and running jobs. Thread-safe.
    std::optional<JobRecord> find(const std::string& id) const;
    /// The latest snapshot: a running job's newest (on a shared store, of a job another process
    /// runs: the one it stored last), a finished job's final one from the store;
    /// null when there is none (queued, or failed before the first mesh). Thread-safe.
    std::shared_ptr<const JobSnapshot> snapshot(const std::string& id) const;
    /// A number that changes whenever job `id` may have changed on another replica, so that an
    /// event stream reads it again only then; nothing when the stream must read it every time
    /// (the job runs here, or the store cannot tell). Thread-safe.
    std::optional<std::uint64_t> change_token(const std::string& id) const;
    /// Scene name and result digits of a running job (a finished one's are in its result).
    /// On a shared store also of a job another process runs (its scene read once). Thread-safe.
    RunningScene running_scene(const std::string& id) const;

    /// Cancels: a queued job becomes cancelled at once; a running solve is asked to stop and
    /// becomes cancelled within about a second, its best result kept. Either way the cancel is
    /// in the store before this returns (throws StoreError when it cannot be). Finished jobs are
    /// left as they are. Returns the job as it is now, or nothing for an unknown id. Thread-safe.
    std::optional<JobRecord> cancel(const std::string& id);

    /// Jobs waiting for a worker (on a shared store: for any process's worker).
    std::size_t queue_length() const;
    bool shutting_down() const;

    /// A graceful stop (SIGTERM): refuses new jobs and takes no more from the queue, lets the
    /// running solves go on for up to `deadline`, then shutdown() hands back those still running.
    /// Returns once the workers are joined. Thread-safe; another thread may call shutdown()
    /// meanwhile to cut the wait short.
    void drain(std::chrono::milliseconds deadline);

    /// Refuses new jobs, stops running solves and hands them back without counting the attempt
    /// (queued again: on a shared store another process takes them at once, else the next
    /// process runs them) and joins the workers. Idempotent.
    void shutdown();

private:
    struct LiveJob;
    void work();
    /// The next job: from the in-memory queue, or claimed from a shared store. Null once
    /// stopping.
    std::shared_ptr<LiveJob> next_job();
    /// Claims a job from the shared store, waiting for one; null once stopping.
    std::shared_ptr<LiveJob> claim_job();
    /// The latest snapshot that another process stored of a job it runs; null when none.
    std::shared_ptr<const JobSnapshot> remote_snapshot(const std::string& id) const;
    /// Writes a running job's snapshot for other processes (its mesh only when its values are
    /// new); the progress writer's thread.
    void store_snapshot(LiveJob& job, const JobSnapshot& snapshot,
                        std::chrono::steady_clock::time_point now);
    /// Renews the leases of this process's running jobs on a shared store; stops the solves whose
    /// lease went to another process, or whose cancel another process accepted.
    void renew_leases();
    void run(const std::shared_ptr<LiveJob>& job);
    /// Stores a finished job's outcome; when the store refuses it, the job fails with the reason,
    /// in the store if a smaller write still fits, else in memory (unstored_).
    void store_outcome(LiveJob& job, const JobRecord& outcome, const std::string& result_json,
                       const std::optional<StoredMesh>& mesh);
    /// A job the store could not follow ends failed in memory; the progress writer stores it
    /// once the store takes writes again.
    void fail_unstored(LiveJob& job, const std::string& why);
    /// Writes running jobs' changed progress to the store about once a second, and retries
    /// outcomes the store refused.
    void write_progress();

    JobStore& store_;
    Metrics& metrics_;
    const JobQueueOptions options_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;           ///< workers: a job was queued, or shutdown
    std::condition_variable progress_wake_;  ///< the progress writer: shutdown
    std::condition_variable solved_;         ///< drain(): a solve ended, or shutdown
    /// drain() began: no new job is accepted or started; running ones go on.
    bool draining_ = false;
    bool stopping_ = false;    ///< shutdown() began: running solves stop too
    std::size_t solving_ = 0;  ///< workers inside run()
    std::deque<std::shared_ptr<LiveJob>> queue_;
    std::unordered_map<std::string, std::shared_ptr<LiveJob>> live_;  ///< queued or running
    /// Finished jobs whose final state the store refused (disk full); without their results.
    std::unordered_map<std::string, JobRecord> unstored_;
    /// Guarded by mutex_: remote_snapshot()'s latest, by job id (at most kMaxRemoteSnapshots).
    mutable std::unordered_map<std::string, std::shared_ptr<const JobSnapshot>> remote_snapshots_;
    /// Guarded by mutex_: running_scene() of jobs other processes run (at most
    /// kMaxRemoteSnapshots), so that each poll of their result does not parse the scene again.
    mutable std::unordered_map<std::string, RunningScene> remote_scenes_;
    std::vector<std::thread> workers_;  ///< solvers and the progress writer
    std::string replica_;               ///< owner name in the shared store's leases
};

}  // namespace radiant::server
