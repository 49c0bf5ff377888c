#include "radiant/server/job_queue.h"

#include <spdlog/spdlog.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <utility>

#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/proto/warnings_json.h"
#include "radiant/solve.h"

namespace radiant::server {

namespace {

/// Least time between two snapshots of a running job: at most two `radiosity` events a second
/// reach a client, and the engine builds a display mesh no more often than that.
constexpr double kSnapshotSeconds = 0.5;
/// Running jobs' progress reaches the store at most this often (it is also in memory at once);
/// leases on a shared store are renewed as often.
constexpr auto kProgressWritePeriod = std::chrono::seconds(1);
/// On a shared store, a running job's snapshot reaches the store at most this often, for other
/// replicas to stream: its mesh blob may be megabytes, written again only when its values
/// changed (the engine repeats them while it links and gathers).
constexpr auto kSnapshotStorePeriod = std::chrono::seconds(2);
/// Snapshots of jobs that other replicas run, kept decoded for this process's event streams so
/// that each new one costs only its changed part; more than this many are streamed at once
/// only by a very busy replica, which then decodes more often.
constexpr std::size_t kMaxRemoteSnapshots = 32;
/// An idle worker on a shared store asks for a job this often: other processes' submissions do
/// not wake it (a job submitted here does at once).
constexpr auto kClaimPollPeriod = std::chrono::milliseconds(500);

/// "host:pid": unique among the processes sharing a store, and says where a job runs.
std::string default_replica_name() {
    char host[256] = {};
    if (::gethostname(host, sizeof host - 1) != 0) std::snprintf(host, sizeof host, "radiantd");
    return std::string(host) + ":" + std::to_string(::getpid());
}

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
        : id(r.id),
          lease(r.lease_token),
          record(std::move(r)),
          last_event_id(record.progress.sequence) {}

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

    void on_warnings(const std::vector<Warning>& warnings) noexcept override {
        nlohmann::json json = proto::warnings_to_json(warnings);
        const std::lock_guard lock(mutex);
        record.warnings = std::move(json);
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
    /// The claim this run holds on a shared store: its writes carry it, and the store refuses
    /// them once another claim took the job (kUnfenced from the in-memory queue).
    const LeaseToken lease;
    CancellationToken token;
    std::atomic<bool> user_cancelled{false};  ///< false + token cancelled: shutdown
    /// The shared store gave the job to another process: this run stores nothing.
    std::atomic<bool> lease_lost{false};
    mutable std::mutex mutex;
    JobRecord record;    ///< guarded by mutex; never holds the scene text
    RunningScene scene;  ///< guarded by mutex
    /// Guarded by mutex: the job's event ids (progress, mesh, radiosity) come from one counter.
    std::uint64_t last_event_id = 0;
    std::shared_ptr<const JobSnapshot> snapshot;  ///< guarded by mutex
    std::uint64_t stored_sequence = 0;            ///< progress the store has; writer thread only
    /// The snapshot the shared store has (radiosity_event_id, values_event_id), and when it was
    /// written; writer thread only.
    std::uint64_t stored_snapshot_event_id = 0, stored_values_event_id = 0;
    std::chrono::steady_clock::time_point snapshot_stored_at;
    /// The scene text a claim from a shared store brought, for run() (which clears it).
    std::string claimed_scene_json;
};

JobQueue::JobQueue(JobStore& store, Metrics& metrics, JobQueueOptions options)
    : store_(store),
      metrics_(metrics),
      options_(options),
      replica_(options.replica.empty() ? default_replica_name() : options.replica) {
    // On a shared store other processes may be running the unfinished jobs; those whose process
    // died lose their lease, and a claim takes them.
    const UnfinishedJobs unfinished =
        store_.shared() ? UnfinishedJobs{} : store_.requeue_unfinished(kMaxJobAttempts);
    for (const std::string& id : unfinished.cancelled) {
        spdlog::info("job {} cancelled: its cancel was accepted before the restart", id);
    }
    for (const std::string& id : unfinished.failed) {
        spdlog::warn("job {} failed: its process died during each of its {} solves", id,
                     kMaxJobAttempts);
    }
    for (const std::string& id : unfinished.requeued) {
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
        return SubmitOutcome{SubmitOutcome::Kind::replayed, *find(existing->id), {}};
    };
    if (auto replayed = replay()) return *replayed;

    // A shared store counts every process's waiting jobs; asked before the lock, as the store
    // may be a network away.
    const std::size_t shared_waiting = store_.shared() ? queue_length() : 0;
    const std::lock_guard lock(mutex_);
    const std::size_t waiting = store_.shared() ? shared_waiting : queue_.size();
    if (draining_ || stopping_) return {SubmitOutcome::Kind::shutting_down, {}, {}};
    if (waiting >= options_.queue_limit) return {SubmitOutcome::Kind::queue_full, {}, {}};
    JobRecord record;
    record.id = new_job_id();
    record.status = JobStatus::queued;
    record.scene_json = scene_json;
    record.idempotency_key = idempotency_key;
    record.created = now_millis();
    try {
        store_.insert(record);
    } catch (const StoreError& e) {
        if (e.unwritable()) return {SubmitOutcome::Kind::store_unwritable, {}, e.what()};
        // Two requests with one key raced; the unique index let the first one in.
        if (auto replayed = replay()) return *replayed;
        throw;
    }
    record.scene_json.clear();
    if (!store_.shared()) {  // else the store is the queue
        auto job = std::make_shared<LiveJob>(record);
        queue_.push_back(job);
        live_.emplace(record.id, job);
    }
    wake_.notify_one();
    spdlog::info("job {} queued ({} waiting)", record.id, waiting + 1);
    return {SubmitOutcome::Kind::accepted, std::move(record), {}};
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
    {
        const std::lock_guard lock(mutex_);
        const auto it = unstored_.find(id);
        if (it != unstored_.end()) return it->second;
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
    if (store_.shared()) {
        // One query for a job another process runs: the store has a running snapshot only while
        // the job runs (and none before its first one, when there is no mesh to show either).
        if (std::shared_ptr<const JobSnapshot> running = remote_snapshot(id)) return running;
        const std::lock_guard lock(mutex_);
        remote_snapshots_.erase(id);
    }
    std::optional<StoredMesh> stored = store_.mesh(id);
    if (!stored) return nullptr;
    std::optional<CompactMesh> mesh = decode(stored->blob);
    if (!mesh) throw std::runtime_error("job store: the mesh of job " + id + " is damaged");
    if (const auto job = store_.find(id, false)) stored->info.progress = job->progress;
    return std::make_shared<const JobSnapshot>(id, std::move(stored->info), std::move(*mesh));
}

std::shared_ptr<const JobSnapshot> JobQueue::remote_snapshot(const std::string& id) const {
    std::shared_ptr<const JobSnapshot> cached;
    {
        const std::lock_guard lock(mutex_);
        const auto it = remote_snapshots_.find(id);
        if (it != remote_snapshots_.end()) cached = it->second;
    }
    std::optional<StoredMesh> stored =
        store_.running_snapshot(id, cached ? cached->info().values_event_id : 0);
    if (!stored) return nullptr;
    std::shared_ptr<const JobSnapshot> fresh;
    if (cached && stored->blob.empty()) {  // the values this process has already
        if (cached->info().radiosity_event_id == stored->info.radiosity_event_id) return cached;
        fresh = std::make_shared<const JobSnapshot>(id, std::move(stored->info), cached->mesh());
    } else {
        std::optional<CompactMesh> mesh = decode(stored->blob);
        if (!mesh) throw std::runtime_error("job store: the snapshot of job " + id + " is damaged");
        fresh = std::make_shared<const JobSnapshot>(id, std::move(stored->info), std::move(*mesh));
    }
    const std::lock_guard lock(mutex_);
    if (remote_snapshots_.size() >= kMaxRemoteSnapshots && !remote_snapshots_.contains(id)) {
        remote_snapshots_.erase(remote_snapshots_.begin());
    }
    remote_snapshots_[id] = fresh;
    return fresh;
}

std::optional<std::uint64_t> JobQueue::change_token(const std::string& id) const {
    {
        const std::lock_guard lock(mutex_);
        if (live_.contains(id) || unstored_.contains(id)) return std::nullopt;
    }
    return store_.change_token(id);
}

RunningScene JobQueue::running_scene(const std::string& id) const {
    {
        const std::lock_guard lock(mutex_);
        if (const auto it = live_.find(id); it != live_.end()) {
            const std::lock_guard job_lock(it->second->mutex);
            return it->second->scene;
        }
        if (const auto it = remote_scenes_.find(id); it != remote_scenes_.end()) return it->second;
    }
    if (!store_.shared()) return {};
    // Another process runs it: its scene, checked on submission, parses as it did there.
    const std::optional<JobRecord> job = store_.find(id);
    if (!job) return {};
    const proto::ParseOutcome outcome = proto::parse_scene(job->scene_json);
    if (!outcome.ok()) return {};
    const RunningScene scene{outcome.scene->name, outcome.scene->settings.digits};
    const std::lock_guard lock(mutex_);
    if (remote_scenes_.size() >= kMaxRemoteSnapshots && !remote_scenes_.contains(id)) {
        remote_scenes_.erase(remote_scenes_.begin());
    }
    remote_scenes_[id] = scene;
    return scene;
}

std::optional<JobRecord> JobQueue::cancel(const std::string& id) {
    {
        const std::lock_guard lock(mutex_);
        const auto it = live_.find(id);
        if (it != live_.end()) {
            const std::shared_ptr<LiveJob> job = it->second;
            const auto queued = std::find(queue_.begin(), queue_.end(), job);
            if (queued != queue_.end()) {
                // Never started: cancelled at once, with no result; stored first, so that a
                // store that refuses it leaves the job queued.
                const std::lock_guard job_lock(job->mutex);
                const UnixMillis finished = now_millis();
                store_.finish(id, JobStatus::cancelled, finished, job->record.progress, "",
                              std::nullopt);
                queue_.erase(queued);
                live_.erase(it);
                job->record.status = JobStatus::cancelled;
                job->record.finished = finished;
                spdlog::info("job {} queued -> cancelled", id);
                return job->record;
            }
            // Running: the engine polls the token and returns its best result within a second;
            // the worker then records the job as cancelled. The request is stored first: a
            // process that dies meanwhile must not run the job again after its restart.
            store_.request_cancel(id);
            job->user_cancelled = true;
            job->token.cancel();
            spdlog::info("job {} cancel requested", id);
            return job->copy();
        }
    }
    if (store_.shared()) {
        const std::optional<JobRecord> stored = store_.find(id, false);
        if (stored && stored->status == JobStatus::running) {
            // The process running it sees the request at its next heartbeat.
            store_.request_cancel(id);
            spdlog::info("job {} cancel requested (it runs elsewhere)", id);
        } else if (stored && stored->status == JobStatus::queued) {
            // Requested first: a process that claims the job meanwhile finds it no longer
            // running at its next heartbeat and stores nothing.
            store_.request_cancel(id);
            store_.finish(id, JobStatus::cancelled, now_millis(), stored->progress, "",
                          std::nullopt);
            spdlog::info("job {} queued -> cancelled", id);
        }
    }
    return find(id);
}

std::size_t JobQueue::queue_length() const {
    if (store_.shared()) {
        const auto counts = store_.count_by_status();
        const auto queued = counts.find(JobStatus::queued);
        return queued == counts.end() ? 0 : queued->second;
    }
    const std::lock_guard lock(mutex_);
    return queue_.size();
}

bool JobQueue::shutting_down() const {
    const std::lock_guard lock(mutex_);
    return draining_ || stopping_;
}

void JobQueue::drain(std::chrono::milliseconds deadline) {
    {
        std::unique_lock lock(mutex_);
        draining_ = true;
        wake_.notify_all();  // idle workers stop waiting for a job
        const std::size_t running = solving_;
        if (running > 0) spdlog::info("draining: {} running job(s) may finish", running);
        // Leases are still renewed meanwhile: the progress writer runs until shutdown().
        if (!solved_.wait_for(lock, deadline, [this] { return solving_ == 0 || stopping_; })) {
            spdlog::info("drain deadline: the running job(s) go back to the queue");
        }
    }
    shutdown();
}

void JobQueue::shutdown() {
    std::vector<std::thread> workers;
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        // Queued jobs stay queued in the store; running ones stop and run() hands them back.
        for (auto& [id, job] : live_) job->token.cancel();
        workers.swap(workers_);
    }
    wake_.notify_all();
    progress_wake_.notify_all();
    solved_.notify_all();
    for (std::thread& t : workers) t.join();
}

void JobQueue::write_progress() {
    std::unique_lock lock(mutex_);
    while (!progress_wake_.wait_for(lock, kProgressWritePeriod, [this] { return stopping_; })) {
        std::vector<std::pair<std::shared_ptr<LiveJob>, JobProgress>> changed;
        std::vector<std::pair<std::shared_ptr<LiveJob>, std::shared_ptr<const JobSnapshot>>>
            snapshots;
        const auto now = std::chrono::steady_clock::now();
        for (const auto& [id, job] : live_) {
            const std::lock_guard job_lock(job->mutex);
            if (job->record.status != JobStatus::running) continue;
            // Other replicas stream the job from the store (a final snapshot goes with the
            // result, in finish()).
            if (store_.shared() && job->snapshot && !job->snapshot->info().final &&
                job->snapshot->info().radiosity_event_id != job->stored_snapshot_event_id &&
                now - job->snapshot_stored_at >= kSnapshotStorePeriod) {
                snapshots.emplace_back(job, job->snapshot);
            }
            if (job->record.progress.sequence == job->stored_sequence) continue;
            job->stored_sequence = job->record.progress.sequence;
            changed.emplace_back(job, job->record.progress);
        }
        std::vector<JobRecord> unstored;
        for (const auto& [id, record] : unstored_) unstored.push_back(record);
        lock.unlock();  // the store has its own lock; submissions need not wait for the disk
        // Snapshots before progress: a reader that has seen a progress event then finds the
        // snapshots taken before it, and never skips one for its lower event id.
        for (const auto& [job, snapshot] : snapshots) store_snapshot(*job, *snapshot, now);
        for (const auto& [job, progress] : changed) {
            try {
                store_.save_progress(job->id, progress, job->lease);
            } catch (const std::exception& e) {
                spdlog::error("job {}: progress not stored: {}", job->id, e.what());
            }
        }
        std::vector<std::string> stored;
        for (const JobRecord& r : unstored) {
            try {
                store_.finish(r.id, r.status, r.finished, r.progress, r.error, std::nullopt,
                              std::nullopt, r.lease_token);
                stored.push_back(r.id);
                spdlog::info("job {}: its {} state is stored now", r.id, to_string(r.status));
            } catch (const std::exception&) {
                break;  // still refused; the next period tries again
            }
        }
        if (store_.shared()) renew_leases();
        lock.lock();
        for (const std::string& id : stored) unstored_.erase(id);
    }
}

void JobQueue::store_snapshot(LiveJob& job, const JobSnapshot& snapshot,
                              std::chrono::steady_clock::time_point now) {
    const SnapshotInfo& info = snapshot.info();
    const bool with_values = info.values_event_id != job.stored_values_event_id;
    try {
        store_.save_snapshot(job.id, info,
                             with_values ? std::optional(encode(snapshot.mesh())) : std::nullopt,
                             job.lease);
        job.stored_snapshot_event_id = info.radiosity_event_id;
        job.stored_values_event_id = info.values_event_id;
        job.snapshot_stored_at = now;
    } catch (const std::exception& e) {
        spdlog::error("job {}: snapshot not stored: {}", job.id, e.what());
    }
}

void JobQueue::renew_leases() {
    std::vector<std::shared_ptr<LiveJob>> running;
    {
        const std::lock_guard lock(mutex_);
        for (const auto& [id, job] : live_) {
            if (job->copy().status == JobStatus::running) running.push_back(job);
        }
    }
    for (const auto& job : running) {
        try {
            const LeaseRenewal renewal =
                store_.renew_lease(job->id, replica_, options_.lease, job->lease);
            if (!renewal.held) {
                spdlog::warn("job {}: its lease went to another radiantd; this run stops", job->id);
                job->lease_lost = true;
                job->token.cancel();
            } else if (renewal.cancel_requested && !job->user_cancelled) {
                spdlog::info("job {} cancel requested (accepted elsewhere)", job->id);
                job->user_cancelled = true;
                job->token.cancel();
            }
        } catch (const std::exception& e) {
            // The lease runs on; a store back within it loses nothing.
            spdlog::error("job {}: lease not renewed: {}", job->id, e.what());
        }
    }
}

std::shared_ptr<JobQueue::LiveJob> JobQueue::next_job() {
    if (store_.shared()) return claim_job();
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [this] { return draining_ || stopping_ || !queue_.empty(); });
    if (draining_ || stopping_) return nullptr;
    std::shared_ptr<LiveJob> job = queue_.front();
    queue_.pop_front();
    ++solving_;
    return job;
}

std::shared_ptr<JobQueue::LiveJob> JobQueue::claim_job() {
    for (;;) {
        {
            const std::lock_guard lock(mutex_);
            if (draining_ || stopping_) return nullptr;
        }
        std::optional<JobRecord> claimed;
        try {
            claimed = store_.claim(replica_, options_.lease, kMaxJobAttempts);
        } catch (const std::exception& e) {
            spdlog::error("cannot claim a job: {}", e.what());
        }
        std::unique_lock lock(mutex_);
        if (claimed) {
            // Running here once run() has its scene name, as a job from the in-memory queue.
            std::string scene_json = std::exchange(claimed->scene_json, std::string());
            claimed->status = JobStatus::queued;
            auto job = std::make_shared<LiveJob>(std::move(*claimed));
            job->claimed_scene_json = std::move(scene_json);
            live_.emplace(job->id, job);
            ++solving_;
            // Claimed as a drain began: run() hands it back at once.
            if (draining_ || stopping_) job->token.cancel();
            spdlog::info("job {} claimed by {}", job->id, replica_);
            return job;
        }
        wake_.wait_for(lock, kClaimPollPeriod);
    }
}

void JobQueue::work() {
    for (;;) {
        const std::shared_ptr<LiveJob> job = next_job();
        if (!job) return;
        try {
            run(job);
        } catch (const std::exception& e) {
            // A store that cannot follow the job fails it where clients see it; the daemon keeps
            // serving.
            spdlog::error("job {}: {}", job->id, e.what());
            fail_unstored(*job, e.what());
        }
        const std::lock_guard lock(mutex_);
        live_.erase(job->id);
        --solving_;
        solved_.notify_all();
    }
}

void JobQueue::run(const std::shared_ptr<LiveJob>& job) {
    const std::string& id = job->id;
    std::string scene_json = std::move(job->claimed_scene_json);
    if (scene_json.empty()) {
        std::optional<JobRecord> stored = store_.find(id);
        if (!stored) return;
        scene_json = std::move(stored->scene_json);
    }
    // The scene was checked on submission; parsing again keeps restarts on the same path. The
    // job turns running together with its scene name, so a running job always has one.
    const proto::ParseOutcome outcome = proto::parse_scene(scene_json);
    {
        const std::lock_guard lock(job->mutex);
        if (outcome.ok()) job->scene = {outcome.scene->name, outcome.scene->settings.digits};
        job->record.status = JobStatus::running;
        // A claim from a shared store set `started` by the store's clock, which every replica
        // reports; this process's would differ by milliseconds.
        if (!store_.shared()) job->record.started = now_millis();
    }
    // A claim from a shared store made the job running already, under this process's lease.
    if (!store_.shared()) store_.mark_running(id, job->copy().started);
    spdlog::info("job {} queued -> running", id);

    Result result;
    if (!outcome.ok()) {
        result.status = SolveStatus::failed;
        result.error = outcome.problems.front().pointer + ": " + outcome.problems.front().message;
    } else {
        SolveOptions options = options_from(outcome.scene->settings);
        options.threads = options_.solve_threads;
        // Concurrent solves share the machine: by default each may use its part of half the
        // memory.
        options.max_memory_bytes =
            options_.job_memory_bytes > 0
                ? options_.job_memory_bytes
                : physical_memory_bytes() / (2 * std::max<std::size_t>(1, options_.workers));
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
    if (job->lease_lost) {
        spdlog::info("job {}: stopped, another radiantd runs it now", id);
        return;
    }
    // A solve that converged just as shutdown began is kept; anything cut short runs again.
    if (job->token.cancelled() && !job->user_cancelled && result.status != SolveStatus::converged) {
        try {
            store_.release(id, job->lease);  // not an attempt that killed the process
        } catch (const StoreError& e) {
            spdlog::warn("job {}: attempt not released: {}", id, e.what());
        }
        spdlog::info("job {} interrupted by shutdown: handed back to the queue", id);
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
    JobRecord finished_job;
    finished_job.id = id;
    finished_job.status = status;
    finished_job.finished = now_millis();
    finished_job.progress = progress;
    finished_job.error = result.error;
    // The mesh is stored as the final snapshot streamed it, apart from the result text.
    std::optional<StoredMesh> mesh;
    if (final_snapshot && final_snapshot->info().final) {
        mesh = StoredMesh{final_snapshot->info(), encode(final_snapshot->mesh())};
    }
    finished_job.warnings = proto::warnings_to_json(result.warnings);
    store_outcome(*job, finished_job, proto::result_to_json(result, digits).dump(), mesh);
    metrics_.count_solve(result.stats.seconds, result.stats.rays);
    spdlog::info("job {} running -> {} ({}, {:.2f} s)", id, to_string(job->copy().status),
                 to_string(result.status), result.stats.seconds);
}

void JobQueue::store_outcome(LiveJob& job, const JobRecord& outcome, const std::string& result_json,
                             const std::optional<StoredMesh>& mesh) {
    JobRecord stored = outcome;
    try {
        store_.save_warnings(outcome.id, outcome.warnings, job.lease);
        if (!store_.finish(outcome.id, outcome.status, outcome.finished, outcome.progress,
                           outcome.error, result_json, mesh, job.lease)) {
            // Cut off from the store for longer than the lease: another replica runs the job.
            spdlog::warn(
                "job {}: its lease went to another radiantd; this run's outcome is dropped",
                outcome.id);
            job.lease_lost = true;
            return;
        }
    } catch (const StoreError& e) {
        // Most often a full disk: the result is lost, and the job says so. The short failed
        // state may still fit where the result did not.
        spdlog::error("job {}: result not stored: {}", outcome.id, e.what());
        stored.status = JobStatus::failed;
        stored.error = std::string("the result could not be stored: ") + e.what();
        try {
            store_.finish(stored.id, stored.status, stored.finished, stored.progress, stored.error,
                          std::nullopt, std::nullopt, job.lease);
        } catch (const StoreError&) {
            fail_unstored(job, e.what());
            return;
        }
    }
    const std::lock_guard lock(job.mutex);
    job.record.status = stored.status;
    job.record.finished = stored.finished;
    job.record.progress = stored.progress;
    job.record.error = stored.error;
    job.record.warnings = stored.warnings;
}

void JobQueue::fail_unstored(LiveJob& job, const std::string& why) {
    JobRecord record;
    {
        const std::lock_guard lock(job.mutex);
        job.record.status = JobStatus::failed;
        job.record.finished = now_millis();
        job.record.error = "the job store could not record this job: " + why;
        record = job.record;
    }
    const std::lock_guard lock(mutex_);
    unstored_[record.id] = record;
}

}  // namespace radiant::server
