// The durable job store's interface and the types its implementations share.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "radiant/server/job.h"
#include "radiant/server/job_snapshot.h"

namespace radiant::server {

/// A stored snapshot: its place in the event sequence and encode(CompactMesh).
struct StoredMesh {
    /// A finished job's progress is not stored here (the job's own is the same); a running
    /// job's is.
    SnapshotInfo info;
    std::string blob;
};

/// A statement the store could not run: disk full, a read-only or vanished file, corruption, or a
/// constraint (a second job with one idempotency key).
class StoreError : public std::runtime_error {
public:
    StoreError(const std::string& what, bool unwritable)
        : std::runtime_error(what), unwritable_(unwritable) {}
    /// True when the store cannot take writes at all (as opposed to a refused row).
    bool unwritable() const { return unwritable_; }

private:
    bool unwritable_;
};

/// Whether the store takes writes; `reason` says why not.
struct StoreHealth {
    bool writable = true;
    std::string reason;
};

/// What the store found unfinished at start: jobs to run again, and jobs it ended instead.
struct UnfinishedJobs {
    std::vector<std::string> requeued;   ///< oldest first
    std::vector<std::string> failed;     ///< had been started `max_attempts` times already
    std::vector<std::string> cancelled;  ///< a cancel was accepted before the process died
};

/// What renewing a lease tells the replica that runs the job.
struct LeaseRenewal {
    /// False: the lease had expired and the job went to another replica (or ended); the solve
    /// must stop and store nothing.
    bool held = false;
    bool cancel_requested = false;  ///< a cancel accepted by any replica
};

/// Which claim of a job a write comes from: claim() gives each claim a new, greater token. A
/// store refuses the writes of a run (progress, warnings, snapshot, outcome, hand-back,
/// heartbeat) whose token is no longer the job's, i.e. after its lease expired and another
/// claim took the job: a replica cut off from the store cannot overwrite the new owner's work.
using LeaseToken = std::int64_t;
/// A write that belongs to no claim (the single-process queue, a cancel of a queued job).
inline constexpr LeaseToken kUnfenced = 0;

/// The error a job gets when its solve was started `max_attempts` times and never finished.
std::string attempts_exhausted_error(int max_attempts);

/// Where jobs, their progress, results and meshes live, so that an accepted job survives a
/// restart or a crash (contract §4). Two implementations: SqliteJobStore (one file under --data,
/// the default) and, later, a server database shared by several radiantd. Every method is
/// thread-safe and throws StoreError when the store cannot run it.
class JobStore {
public:
    virtual ~JobStore() = default;
    JobStore() = default;
    JobStore(const JobStore&) = delete;
    JobStore& operator=(const JobStore&) = delete;

    virtual void insert(const JobRecord& job) = 0;
    /// `with_scene` false leaves scene_json empty: status reads never need megabytes of scene.
    virtual std::optional<JobRecord> find(const std::string& id, bool with_scene = true) const = 0;
    virtual std::optional<JobRecord> find_by_idempotency_key(const std::string& key) const = 0;
    /// Newest first; `after` is the id of the last job of the previous page (empty: from the top).
    virtual std::vector<JobRecord> list(std::size_t limit, const std::string& after) const = 0;

    /// Counts an attempt: a process that dies while the job runs leaves the count raised. The job
    /// is held for the life of this process (no lease: the single-process queue's way).
    virtual void mark_running(const std::string& id, UnixMillis started) = 0;
    /// A running job that a clean shutdown stopped goes back to queued, its attempt uncounted.
    virtual void release(const std::string& id, LeaseToken lease = kUnfenced) = 0;
    /// Records that a cancel was accepted, before the answer says so: a process that dies before
    /// the solve stops leaves the job cancelled, not queued again. No-op for finished jobs.
    virtual void request_cancel(const std::string& id) = 0;
    virtual void save_progress(const std::string& id, const JobProgress& progress,
                               LeaseToken lease = kUnfenced) = 0;
    /// The job's warnings (a JSON array), as GET /v1/jobs/{id} reports them.
    virtual void save_warnings(const std::string& id, const nlohmann::json& warnings,
                               LeaseToken lease = kUnfenced) = 0;
    /// Final state, progress and (optionally) the result document (without its mesh) and the
    /// solved mesh, in one transaction. False, and nothing stored, when `lease` is fenced off.
    virtual bool finish(const std::string& id, JobStatus status, UnixMillis finished,
                        const JobProgress& progress, const std::string& error,
                        const std::optional<std::string>& result_json,
                        const std::optional<StoredMesh>& mesh = std::nullopt,
                        LeaseToken lease = kUnfenced) = 0;
    virtual std::optional<std::string> result(const std::string& id) const = 0;
    /// A finished job's final snapshot, as finish() stored it.
    virtual std::optional<StoredMesh> mesh(const std::string& id) const = 0;

    /// A running job's latest snapshot (info.progress included), which the process running it
    /// writes so that other processes can stream it. `blob` nothing: the stored blob has these
    /// values already (same values_event_id), only the info changes. Does nothing unless the job
    /// is running; finish() deletes it.
    virtual void save_snapshot(const std::string& id, const SnapshotInfo& info,
                               const std::optional<std::string>& blob,
                               LeaseToken lease = kUnfenced) = 0;
    /// What save_snapshot stored, if the job is still running; the blob is left empty when its
    /// values_event_id is `have_values_event_id` (the reader has those values already).
    virtual std::optional<StoredMesh> running_snapshot(
        const std::string& id, std::uint64_t have_values_event_id) const = 0;
    /// A number that changes whenever another process may have changed job `id` (its state,
    /// progress or snapshot), so a reader need not read the job again until it does; nothing
    /// when the store cannot tell (then read it every time).
    virtual std::optional<std::uint64_t> change_token(const std::string& id) const = 0;

    /// Jobs that were queued or running when the last process stopped. Those with a cancel
    /// request end cancelled; those started `max_attempts` times end failed (each start killed
    /// its process: out of memory, most likely); the rest go back to queued (a solve that did not
    /// finish starts over), their progress to just a sequence a million above the stored one,
    /// where the next run's event ids continue.
    virtual UnfinishedJobs requeue_unfinished(int max_attempts) = 0;
    virtual std::map<JobStatus, std::size_t> count_by_status() const = 0;

    /// The shared queue: takes the oldest job that no live process holds (queued, or running
    /// under a lease that expired because its process died or was cut off) and makes it running
    /// under `owner`'s lease for `lease`, its attempt counted, its scene and a new lease_token
    /// included. A job taken
    /// back from an expired lease continues its event ids a million above the stored sequence.
    /// Before choosing, ends the expired jobs that must not run again: those with a cancel
    /// request end cancelled, those started `max_attempts` times end failed. Concurrent claims
    /// (threads, or processes on a shared store) never take the same job. Nothing when no job
    /// is waiting.
    virtual std::optional<JobRecord> claim(const std::string& owner,
                                           std::chrono::milliseconds lease, int max_attempts) = 0;
    /// The heartbeat of a running job: extends `owner`'s lease to `lease` from now, if `owner`
    /// still holds it under `token`.
    virtual LeaseRenewal renew_lease(const std::string& id, const std::string& owner,
                                     std::chrono::milliseconds lease,
                                     LeaseToken token = kUnfenced) = 0;

    /// Whether the store takes writes now, and why not.
    virtual StoreHealth health() = 0;
    /// What the store's last write or query found, without asking it again (no I/O, no wait on
    /// a slow store): what liveness may report.
    StoreHealth last_known_health() const {
        const std::lock_guard lock(known_mutex_);
        return known_;
    }

    /// True when other processes may use the store at the same time: then the queue lives in the
    /// store (claim, renew_lease), not in one process's memory.
    virtual bool shared() const = 0;

protected:
    /// Stores call this with each write's or query's outcome (see last_known_health).
    void note_health(StoreHealth health) const {
        const std::lock_guard lock(known_mutex_);
        known_ = std::move(health);
    }

private:
    mutable std::mutex known_mutex_;
    mutable StoreHealth known_;
};

}  // namespace radiant::server
