// The shared job store: one PostgreSQL database that several radiantd replicas use as one queue
// and one store (issue 31). Jobs are claimed with SELECT … FOR UPDATE SKIP LOCKED under a lease
// that the running replica renews; a replica that dies loses its lease and another takes the job.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "radiant/server/job_store.h"

struct pg_conn;

namespace radiant::server {

class PostgresChangeFeed;

/// Thread-safe: one connection guarded by a mutex, as SqliteJobStore (statements are short, and
/// each replica runs few of them a second). Times (leases, started, finished) come from the
/// database's clock, so replicas on machines whose clocks differ agree on when a lease ends.
/// Throws StoreError on failures; a lost connection is opened again by the next statement.
class PostgresJobStore final : public JobStore {
public:
    /// The schema this build writes; older schemas are migrated on open.
    static constexpr int kSchemaVersion = 3;

    /// Connects to `uri` (postgresql://user@host/db or key=value pairs, as libpq takes them),
    /// then creates or migrates the schema, one replica at a time. Throws StoreError when the
    /// server cannot be reached or its schema is newer than this build's.
    explicit PostgresJobStore(std::string uri);
    ~PostgresJobStore() override;

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
    /// From LISTEN/NOTIFY (PostgresChangeFeed), on a second connection opened by the first call.
    std::optional<std::uint64_t> change_token(const std::string& id) const override;
    /// Other replicas may be running jobs: only jobs whose lease expired count as unfinished.
    UnfinishedJobs requeue_unfinished(int max_attempts) override;
    std::map<JobStatus, std::size_t> count_by_status() const override;
    std::optional<JobRecord> claim(const std::string& owner, std::chrono::milliseconds lease,
                                   int max_attempts) override;
    LeaseRenewal renew_lease(const std::string& id, const std::string& owner,
                             std::chrono::milliseconds lease,
                             LeaseToken token = kUnfenced) override;
    /// Unwritable while the server cannot be reached or refuses writes.
    StoreHealth health() override;
    bool shared() const override { return true; }

    /// The schema version the database holds.
    int schema_version() const;

private:
    class Result;
    /// Runs `sql` with text parameters ($1…); `binary` marks parameters sent as bytes (bytea).
    /// The caller holds mutex_. Notes the outcome for last_known_health.
    Result run(const std::string& sql, const std::vector<std::optional<std::string>>& params = {},
               const std::vector<bool>& binary = {}) const;
    Result execute(const std::string& sql, const std::vector<std::optional<std::string>>& params,
                   const std::vector<bool>& binary) const;
    /// Opens the connection when there is none or it broke; the caller holds mutex_.
    void connect() const;
    void migrate();
    /// Runs `body` in one transaction; the caller holds mutex_.
    template <typename Body>
    void transaction(Body&& body) const;
    /// As SqliteJobStore::end_dead_jobs, where `dead` selects running jobs whose process is gone.
    void end_dead_jobs(const std::string& dead, int max_attempts, UnfinishedJobs& out) const;
    std::optional<JobRecord> find_where(const std::string& where, const std::string& value,
                                        bool with_scene) const;

    const std::string uri_;
    mutable pg_conn* conn_ = nullptr;
    mutable std::mutex mutex_;
    mutable std::once_flag feed_once_;
    mutable std::unique_ptr<PostgresChangeFeed> feed_;
};

}  // namespace radiant::server
