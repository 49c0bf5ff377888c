// The durable job store: one SQLite database under --data, so an accepted job survives a restart
// or a crash (contract §4).
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "radiant/server/job.h"
#include "radiant/server/job_snapshot.h"

struct sqlite3;

namespace radiant::server {

/// A finished job's final snapshot: its place in the event sequence and encode(CompactMesh).
struct StoredMesh {
    SnapshotInfo info;  ///< progress is not stored here (the job's own progress is the same)
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

struct JobStoreOptions {
    /// The database stops growing at this size (0: only the disk limits it); a write that would
    /// need more fails as on a full disk.
    std::size_t max_bytes = 0;
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

/// Thread-safe: one connection guarded by a mutex. Every statement is short (a row or a page), so
/// contention is not worth a connection pool at this scale. Throws StoreError on SQLite failures
/// (disk full, corruption); a failed write marks the store unwritable until one succeeds again.
class JobStore {
public:
    /// Opens (creating when missing) `data_dir`/radiant.db in WAL mode. Takes an exclusive lock
    /// on the directory first (a second process on the same directory would run every job
    /// twice): throws std::runtime_error naming the holder's pid when another process has it.
    /// The directory is made 0700 and the files in it 0600: scenes may be confidential.
    explicit JobStore(const std::filesystem::path& data_dir, JobStoreOptions options = {});
    ~JobStore();
    JobStore(const JobStore&) = delete;
    JobStore& operator=(const JobStore&) = delete;

    void insert(const JobRecord& job);
    /// `with_scene` false leaves scene_json empty: status reads never need megabytes of scene.
    std::optional<JobRecord> find(const std::string& id, bool with_scene = true) const;
    std::optional<JobRecord> find_by_idempotency_key(const std::string& key) const;
    /// Newest first; `after` is the id of the last job of the previous page (empty: from the top).
    std::vector<JobRecord> list(std::size_t limit, const std::string& after) const;

    /// Counts an attempt: a process that dies while the job runs leaves the count raised.
    void mark_running(const std::string& id, UnixMillis started);
    /// A running job that a clean shutdown stopped goes back to queued, its attempt uncounted.
    void release(const std::string& id);
    /// Records that a cancel was accepted, before the answer says so: a process that dies before
    /// the solve stops leaves the job cancelled, not queued again. No-op for finished jobs.
    void request_cancel(const std::string& id);
    void save_progress(const std::string& id, const JobProgress& progress);
    /// The job's warnings (a JSON array), as GET /v1/jobs/{id} reports them.
    void save_warnings(const std::string& id, const nlohmann::json& warnings);
    /// Final state, progress and (optionally) the result document (without its mesh) and the
    /// solved mesh, in one transaction.
    void finish(const std::string& id, JobStatus status, UnixMillis finished,
                const JobProgress& progress, const std::string& error,
                const std::optional<std::string>& result_json,
                const std::optional<StoredMesh>& mesh = std::nullopt);
    std::optional<std::string> result(const std::string& id) const;
    std::optional<StoredMesh> mesh(const std::string& id) const;

    /// Jobs that were queued or running when the last process stopped. Those with a cancel
    /// request end cancelled; those started `max_attempts` times end failed (each start killed
    /// its process: out of memory, most likely); the rest go back to queued (a solve that did not
    /// finish starts over), their progress to just a sequence a million above the stored one,
    /// where the next run's event ids continue.
    UnfinishedJobs requeue_unfinished(int max_attempts);
    std::map<JobStatus, std::size_t> count_by_status() const;

    /// Unwritable from a failed write until a write that adds rows succeeds, or the disk (and
    /// max_bytes) has room for results again.
    StoreHealth health();

private:
    /// Pragmas and tables, after the lock is held and the file is open.
    void initialise(const JobStoreOptions& options);
    void exec(const char* sql) const;
    std::size_t page_size() const;
    /// What a write can still add: free disk space, or room under max_bytes.
    std::size_t free_bytes() const;
    /// Runs `write` (the caller holds mutex_) and keeps the store's health from its outcome:
    /// a failure marks it unwritable, a success that `adds_rows` writable again.
    template <typename Write>
    void write(Write&& write, bool adds_rows);
    void finish_locked(const std::string& id, JobStatus status, UnixMillis finished,
                       const JobProgress& progress, const std::string& error,
                       const std::optional<std::string>& result_json,
                       const std::optional<StoredMesh>& mesh);
    const std::filesystem::path data_dir_;
    /// Upgrades a store written by an older radiantd in place.
    void add_column_if_missing(const char* table, const char* column, const char* definition) const;
    sqlite3* db_ = nullptr;
    int lock_fd_ = -1;
    mutable std::mutex mutex_;
    std::string write_error_;  ///< guarded by mutex_; empty while writes succeed
};

}  // namespace radiant::server
