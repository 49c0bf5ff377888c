#include "radiant/server/job_queue.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <stdexcept>
#include <utility>

#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant::server {

namespace {

/// Least time between two snapshots of a running job: at most two `radiosity` events a second
/// reach a client, and the engine builds a display mesh no more often than that.
constexpr double kSnapshotSeconds = 0.5;
/// Running jobs' progress reaches the store at most this often (it is also in memory at once).
constexpr auto kProgressWritePeriod = std::chrono::seconds(1);

JobProgress job_progress(const Progress& p, std::uint64_t sequence) {
    JobProgress q;
    q.sequence = sequence;
    q.stage = p.stage;
    q.fraction = p.fraction;
    q.iterations = p.iterations;
    q.unshot_fraction = p.unshot_fraction;
    q.error_estimate = p.error_estimate;
    q.elapsed_seconds = p.elapsed_seconds;
    q.rays = p.rays;
    return q;
}

}  // namespace

/// Shared between a worker (and the engine's threads, through the observer) and HTTP sessions.
/// The observer calls only swap small values and pointers under the job's mutex, so the solver
/// never waits for a client. Lock order: JobQueue::mutex_ before LiveJob::mutex, never the
/// reverse.
struct JobQueue::LiveJob final : SolveObserver {
    explicit LiveJob(JobRecord r)
        : id(r.id), record(std::move(r)), last_event_id(record.progress.sequence) {}

    void on_progress(const Progress& p) noexcept override {
        const std::lock_guard lock(mutex);
        record.progress = job_progress(p, ++last_event_id);
    }

    void on_snapshot(const Snapshot& s) noexcept override {
        const std::lock_guard lock(mutex);
        SnapshotInfo info;
        info.version = s.version;
        info.mesh_version = s.mesh_version;
        info.final = s.final;
        // One `mesh` event per mesh version, before the first `radiosity` event that uses it.
        const bool same_mesh = snapshot && snapshot->info().mesh_version == s.mesh_version;
        info.mesh_event_id = same_mesh ? snapshot->info().mesh_event_id : ++last_event_id;
        info.radiosity_event_id = ++last_event_id;
        // The engine repeats its latest values by handing over the same mesh again.
        const bool same_values = same_mesh && s.mesh && snapshot->source() == s.mesh.get();
        info.values_event_id =
            same_values ? snapshot->info().values_event_id : info.radiosity_event_id;
        info.progress = job_progress(s.progress, record.progress.sequence);
        info.sensors = s.sensors;
        snapshot = std::make_shared<const JobSnapshot>(id, std::move(info), s.mesh);
        // Linking reports no progress for seconds; the status still shows the time going by.
        record.progress.elapsed_seconds =
            std::max(record.progress.elapsed_seconds, s.progress.elapsed_seconds);
    }

    JobRecord copy() const {
        const std::lock_guard lock(mutex);
        return record;
    }

    std::shared_ptr<const JobSnapshot> latest() const {
        const std::lock_guard lock(mutex);
        return snapshot;
    }

    const std::string id;
    CancellationToken token;
    std::atomic<bool> user_cancelled{false};  ///< false + token cancelled: shutdown
    mutable std::mutex mutex;
    JobRecord record;    ///< guarded by mutex; never holds the scene text
    RunningScene scene;  ///< guarded by mutex
    /// Guarded by mutex: the job's event ids (progress, mesh, radiosity) come from one counter.
    std::uint64_t last_event_id = 0;
    std::shared_ptr<const JobSnapshot> snapshot;  ///< guarded by mutex
    std::uint64_t stored_sequence = 0;            ///< progress the store has; writer thread only
};

JobQueue::JobQueue(JobStore& store, Metrics& metrics, JobQueueOptions options)
    : store_(store), metrics_(metrics), options_(options) {
    for (const std::string& id : store_.requeue_unfinished()) {
        std::optional<JobRecord> record = store_.find(id, false);
        if (!record) continue;
        auto job = std::make_shared<LiveJob>(std::move(*record));
        queue_.push_back(job);
        live_.emplace(id, job);
        spdlog::info("job {} queued again after restart", id);
    }
    const std::size_t workers = std::max<std::size_t>(1, options_.workers);
    for (std::size_t i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
    workers_.emplace_back([this] { write_progress(); });
}

JobQueue::~JobQueue() { shutdown(); }

SubmitOutcome JobQueue::submit(const std::string& scene_json, const std::string& idempotency_key) {
    auto replay = [&]() -> std::optional<SubmitOutcome> {
        if (idempotency_key.empty()) return std::nullopt;
        const auto existing = store_.find_by_idempotency_key(idempotency_key);
        if (!existing) return std::nullopt;
        return SubmitOutcome{SubmitOutcome::Kind::replayed, *find(existing->id)};
    };
    if (auto replayed = replay()) return *replayed;

    const std::lock_guard lock(mutex_);
    if (stopping_) return {SubmitOutcome::Kind::shutting_down, {}};
    if (queue_.size() >= options_.queue_limit) return {SubmitOutcome::Kind::queue_full, {}};
    JobRecord record;
    record.id = new_job_id();
    record.status = JobStatus::queued;
    record.scene_json = scene_json;
    record.idempotency_key = idempotency_key;
    record.created = now_millis();
    try {
        store_.insert(record);
    } catch (const std::runtime_error&) {
        // Two requests with one key raced; the unique index let the first one in.
        if (auto replayed = replay()) return *replayed;
        throw;
    }
    record.scene_json.clear();
    auto job = std::make_shared<LiveJob>(record);
    queue_.push_back(job);
    live_.emplace(record.id, job);
    wake_.notify_one();
    spdlog::info("job {} queued ({} waiting)", record.id, queue_.size());
    return {SubmitOutcome::Kind::accepted, std::move(record)};
}

std::optional<JobRecord> JobQueue::find(const std::string& id) const {
    {
        std::shared_ptr<LiveJob> job;
        {
            const std::lock_guard lock(mutex_);
            const auto it = live_.find(id);
            if (it != live_.end()) job = it->second;
        }
        if (job) return job->copy();
    }
    return store_.find(id, false);
}

std::shared_ptr<const JobSnapshot> JobQueue::snapshot(const std::string& id) const {
    {
        std::shared_ptr<LiveJob> job;
        {
            const std::lock_guard lock(mutex_);
            const auto it = live_.find(id);
            if (it != live_.end()) job = it->second;
        }
        if (job) return job->latest();
    }
    std::optional<StoredMesh> stored = store_.mesh(id);
    if (!stored) return nullptr;
    std::optional<CompactMesh> mesh = decode(stored->blob);
    if (!mesh) throw std::runtime_error("job store: the mesh of job " + id + " is damaged");
    if (const auto job = store_.find(id, false)) stored->info.progress = job->progress;
    return std::make_shared<const JobSnapshot>(id, std::move(stored->info), std::move(*mesh));
}

RunningScene JobQueue::running_scene(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    const auto it = live_.find(id);
    if (it == live_.end()) return {};
    const std::lock_guard job_lock(it->second->mutex);
    return it->second->scene;
}

std::optional<JobRecord> JobQueue::cancel(const std::string& id) {
    {
        const std::lock_guard lock(mutex_);
        const auto it = live_.find(id);
        if (it != live_.end()) {
            const std::shared_ptr<LiveJob> job = it->second;
            const auto queued = std::find(queue_.begin(), queue_.end(), job);
            if (queued != queue_.end()) {
                // Never started: cancelled at once, with no result.
                queue_.erase(queued);
                live_.erase(it);
                const std::lock_guard job_lock(job->mutex);
                job->record.status = JobStatus::cancelled;
                job->record.finished = now_millis();
                store_.finish(id, JobStatus::cancelled, job->record.finished, job->record.progress,
                              "", std::nullopt);
                spdlog::info("job {} queued -> cancelled", id);
                return job->record;
            }
            // Running: the engine polls the token and returns its best result within a second;
            // the worker then records the job as cancelled.
            job->user_cancelled = true;
            job->token.cancel();
            spdlog::info("job {} cancel requested", id);
            return job->copy();
        }
    }
    return find(id);
}

std::size_t JobQueue::queue_length() const {
    const std::lock_guard lock(mutex_);
    return queue_.size();
}

bool JobQueue::shutting_down() const {
    const std::lock_guard lock(mutex_);
    return stopping_;
}

void JobQueue::shutdown() {
    std::vector<std::thread> workers;
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        // Queued jobs stay queued in the store; running ones stop and stay "running" there, so
        // the next process runs both again.
        for (auto& [id, job] : live_) job->token.cancel();
        workers.swap(workers_);
    }
    wake_.notify_all();
    progress_wake_.notify_all();
    for (std::thread& t : workers) t.join();
}

void JobQueue::write_progress() {
    std::unique_lock lock(mutex_);
    while (!progress_wake_.wait_for(lock, kProgressWritePeriod, [this] { return stopping_; })) {
        std::vector<std::pair<std::string, JobProgress>> changed;
        for (const auto& [id, job] : live_) {
            const std::lock_guard job_lock(job->mutex);
            if (job->record.status != JobStatus::running) continue;
            if (job->record.progress.sequence == job->stored_sequence) continue;
            job->stored_sequence = job->record.progress.sequence;
            changed.emplace_back(id, job->record.progress);
        }
        lock.unlock();  // the store has its own lock; submissions need not wait for the disk
        for (const auto& [id, progress] : changed) {
            try {
                store_.save_progress(id, progress);
            } catch (const std::exception& e) {
                spdlog::error("job {}: progress not stored: {}", id, e.what());
            }
        }
        lock.lock();
    }
}

void JobQueue::work() {
    for (;;) {
        std::shared_ptr<LiveJob> job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
            if (stopping_) return;
            job = queue_.front();
            queue_.pop_front();
        }
        try {
            run(job);
        } catch (const std::exception& e) {
            // A broken store is logged and the job left as it is; the daemon keeps serving.
            spdlog::error("job {}: {}", job->id, e.what());
        }
        const std::lock_guard lock(mutex_);
        live_.erase(job->id);
    }
}

void JobQueue::run(const std::shared_ptr<LiveJob>& job) {
    const std::string& id = job->id;
    const std::optional<JobRecord> stored = store_.find(id);
    if (!stored) return;
    // The scene was checked on submission; parsing again keeps restarts on the same path. The
    // job turns running together with its scene name, so a running job always has one.
    const proto::ParseOutcome outcome = proto::parse_scene(stored->scene_json);
    {
        const std::lock_guard lock(job->mutex);
        if (outcome.ok()) job->scene = {outcome.scene->name, outcome.scene->settings.digits};
        job->record.status = JobStatus::running;
        job->record.started = now_millis();
    }
    store_.mark_running(id, job->copy().started);
    spdlog::info("job {} queued -> running", id);

    Result result;
    if (!outcome.ok()) {
        result.status = SolveStatus::failed;
        result.error = outcome.problems.front().pointer + ": " + outcome.problems.front().message;
    } else {
        SolveOptions options = options_from(outcome.scene->settings);
        options.threads = options_.solve_threads;
        // Concurrent solves share the machine: each may use its part of half the memory.
        options.max_memory_bytes =
            physical_memory_bytes() / (2 * std::max<std::size_t>(1, options_.workers));
        options.snapshot_interval_seconds = kSnapshotSeconds;
        if (options_.job_seconds) {
            options.max_seconds = std::min(options.max_seconds.value_or(*options_.job_seconds),
                                           *options_.job_seconds);
        }
        try {
            result = solve(*outcome.scene, options, job.get(), &job->token);
        } catch (const std::exception& e) {
            result = Result{};
            result.status = SolveStatus::failed;
            result.error = std::string("internal error: ") + e.what();
        }
    }
    // A solve that converged just as shutdown began is kept; anything cut short runs again.
    if (job->token.cancelled() && !job->user_cancelled && result.status != SolveStatus::converged) {
        spdlog::info("job {} interrupted by shutdown; it runs again after restart", id);
        return;
    }

    const JobStatus status = job->user_cancelled                    ? JobStatus::cancelled
                             : result.status == SolveStatus::failed ? JobStatus::failed
                                                                    : JobStatus::done;
    JobProgress progress;
    std::shared_ptr<const JobSnapshot> final_snapshot;
    int digits = 0;
    {
        const std::lock_guard lock(job->mutex);
        digits = job->scene.digits;
        progress = job->record.progress;
        progress.sequence = ++job->last_event_id;  // after the final snapshot's events
        final_snapshot = job->snapshot;
    }
    if (status == JobStatus::done) progress.fraction = 1;
    progress.iterations = result.stats.iterations;
    progress.unshot_fraction = result.stats.unshot_fraction;
    progress.error_estimate = result.status == SolveStatus::failed
                                  ? std::nullopt
                                  : std::optional<double>(result.stats.error_estimate);
    progress.elapsed_seconds = result.stats.seconds;
    progress.rays = result.stats.rays;
    const UnixMillis finished = now_millis();
    // The mesh is stored as the final snapshot streamed it, apart from the result text.
    std::optional<StoredMesh> mesh;
    if (final_snapshot && final_snapshot->info().final) {
        mesh = StoredMesh{final_snapshot->info(), encode(final_snapshot->mesh())};
    }
    store_.finish(id, status, finished, progress, result.error,
                  proto::result_to_json(result, digits).dump(), mesh);
    metrics_.count_solve(result.stats.seconds, result.stats.rays);
    {
        const std::lock_guard lock(job->mutex);
        job->record.status = status;
        job->record.finished = finished;
        job->record.progress = progress;
        job->record.error = result.error;
    }
    spdlog::info("job {} running -> {} ({}, {:.2f} s)", id, to_string(status),
                 to_string(result.status), result.stats.seconds);
}

}  // namespace radiant::server
