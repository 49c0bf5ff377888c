#include "radiant/server/job_queue.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <stdexcept>
#include <utility>

#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant::server {

/// Shared between a worker (and the engine's threads, through on_progress) and HTTP sessions.
/// Lock order: JobQueue::mutex_ before LiveJob::mutex, never the reverse.
struct JobQueue::LiveJob final : SolveObserver {
    explicit LiveJob(JobRecord r) : id(r.id), record(std::move(r)) {}

    void on_progress(const Progress& p) noexcept override {
        const std::lock_guard lock(mutex);
        JobProgress& q = record.progress;
        ++q.sequence;
        q.stage = p.stage;
        q.fraction = p.fraction;
        q.iterations = p.iterations;
        q.unshot_fraction = p.unshot_fraction;
        q.error_estimate = p.error_estimate;
        q.elapsed_seconds = p.elapsed_seconds;
        q.rays = p.rays;
    }

    JobRecord snapshot() const {
        const std::lock_guard lock(mutex);
        return record;
    }

    const std::string id;
    CancellationToken token;
    std::atomic<bool> user_cancelled{false};  ///< false + token cancelled: shutdown
    mutable std::mutex mutex;
    JobRecord record;        ///< guarded by mutex; never holds the scene text
    std::string scene_name;  ///< guarded by mutex
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
        if (job) return job->snapshot();
    }
    return store_.find(id, false);
}

std::string JobQueue::scene_name(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    const auto it = live_.find(id);
    if (it == live_.end()) return {};
    const std::lock_guard job_lock(it->second->mutex);
    return it->second->scene_name;
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
            return job->snapshot();
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
    for (std::thread& t : workers) t.join();
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
        if (outcome.ok()) job->scene_name = outcome.scene->name;
        job->record.status = JobStatus::running;
        job->record.started = now_millis();
    }
    store_.mark_running(id, job->snapshot().started);
    spdlog::info("job {} queued -> running", id);

    Result result;
    if (!outcome.ok()) {
        result.status = SolveStatus::failed;
        result.error = outcome.problems.front().pointer + ": " + outcome.problems.front().message;
    } else {
        SolveOptions options = options_from(outcome.scene->settings);
        options.threads = options_.solve_threads;
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
    JobProgress progress = job->snapshot().progress;
    ++progress.sequence;
    if (status == JobStatus::done) progress.fraction = 1;
    progress.iterations = result.stats.iterations;
    progress.unshot_fraction = result.stats.unshot_fraction;
    progress.error_estimate = result.stats.error_estimate;
    progress.elapsed_seconds = result.stats.seconds;
    progress.rays = result.stats.rays;
    const UnixMillis finished = now_millis();
    store_.finish(id, status, finished, progress, result.error,
                  proto::result_to_json(result).dump());
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
