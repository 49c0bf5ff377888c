// The default job store: one SQLite database under --data, for one radiantd.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "radiant/server/job_store.h"

struct sqlite3;

namespace radiant::server {

struct JobStoreOptions {
    /// The database stops growing at this size (0: only the disk limits it); a write that would
    /// need more fails as on a full disk.
    std::size_t max_bytes = 0;
};

/// Thread-safe: one connection guarded by a mutex. Every statement is short (a row or a page), so
/// contention is not worth a connection pool at this scale. Throws StoreError on SQLite failures
/// (disk full, corruption); a failed write marks the store unwritable until one succeeds again.
class SqliteJobStore final : public JobStore {
public:
    /// Opens (creating when missing) `data_dir`/radiant.db in WAL mode. Takes an exclusive lock
    /// on the directory first (a second process on the same directory would run every job
    /// twice): throws std::runtime_error naming the holder's pid when another process has it.
    /// The directory is made 0700 and the files in it 0600: scenes may be confidential.
    explicit SqliteJobStore(const std::filesystem::path& data_dir, JobStoreOptions options = {});
    ~SqliteJobStore() override;

    void insert(const JobRecord& job) override;
    std::optional<JobRecord> find(const std::string& id, bool with_scene = true) const override;
    std::optional<JobRecord> find_by_idempotency_key(const std::string& key) const override;
    std::vector<JobRecord> list(std::size_t limit, const std::string& after) const override;
    void mark_running(const std::string& id, UnixMillis started) override;
    void release(const std::string& id, LeaseToken lease = kUnfenced) override;
    void request_cancel(const std::string& id) override;
    void save_progress(const std::string& id, const JobProgress& progress,
                       LeaseToken lease = kUnfenced) override;
    void save_warnings(const std::string& id, const nlohmann::json& warnings,
                       LeaseToken lease = kUnfenced) override;
    bool finish(const std::string& id, JobStatus status, UnixMillis finished,
                const JobProgress& progress, const std::string& error,
                const std::optional<std::string>& result_json,
                const std::optional<StoredMesh>& mesh = std::nullopt,
                LeaseToken lease = kUnfenced) override;
    std::optional<std::string> result(const std::string& id) const override;
    std::optional<StoredMesh> mesh(const std::string& id) const override;
    void save_snapshot(const std::string& id, const SnapshotInfo& info,
                       const std::optional<std::string>& blob,
                       LeaseToken lease = kUnfenced) override;
    std::optional<StoredMesh> running_snapshot(const std::string& id,
                                               std::uint64_t have_values_event_id) const override;
    /// Nothing: one process writes this store, and it holds the jobs it runs in memory.
    std::optional<std::uint64_t> change_token(const std::string&) const override {
        return std::nullopt;
    }
    /// The directory lock proves that no other process runs these jobs any more.
    UnfinishedJobs requeue_unfinished(int max_attempts) override;
    std::map<JobStatus, std::size_t> count_by_status() const override;
    std::optional<JobRecord> claim(const std::string& owner, std::chrono::milliseconds lease,
                                   int max_attempts) override;
    LeaseRenewal renew_lease(const std::string& id, const std::string& owner,
                             std::chrono::milliseconds lease,
                             LeaseToken token = kUnfenced) override;
    /// Unwritable from a failed write until a write that adds rows succeeds, or the disk (and
    /// max_bytes) has room for results again.
    StoreHealth health() override;
    /// One process owns the directory (its lock).
    bool shared() const override { return false; }

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
    /// Runs `body` in one immediate (write-locked) transaction; the caller holds mutex_.
    template <typename Body>
    void transaction(Body&& body);
    /// Ids of the jobs `where` selects, oldest first; the caller holds mutex_.
    std::vector<std::string> ids(const std::string& where) const;
    /// Ends the jobs whose process is gone (`dead` selects the running ones) that must not run
    /// again: a cancel request makes them cancelled, `max_attempts` starts failed. The caller
    /// holds mutex_ in a transaction.
    void end_dead_jobs(const std::string& dead, UnixMillis now, int max_attempts,
                       UnfinishedJobs& out);
    bool finish_locked(const std::string& id, JobStatus status, UnixMillis finished,
                       const JobProgress& progress, const std::string& error,
                       const std::optional<std::string>& result_json,
                       const std::optional<StoredMesh>& mesh, LeaseToken lease);
    const std::filesystem::path data_dir_;
    /// Upgrades a store written by an older radiantd in place.
    void add_column_if_missing(const char* table, const char* column, const char* definition) const;
    sqlite3* db_ = nullptr;
    int lock_fd_ = -1;
    mutable std::mutex mutex_;
    std::string write_error_;  ///< guarded by mutex_; empty while writes succeed
};

}  // namespace radiant::server
