// The durable job store: one SQLite database under --data, so an accepted job survives a restart
// or a crash (contract §4).
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
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

/// Thread-safe: one connection guarded by a mutex. Every statement is short (a row or a page), so
/// contention is not worth a connection pool at this scale. Throws std::runtime_error on SQLite
/// failures (disk full, corruption): those are broken invariants, not bad input.
class JobStore {
public:
    /// Opens (creating when missing) `data_dir`/radiant.db in WAL mode.
    explicit JobStore(const std::filesystem::path& data_dir);
    ~JobStore();
    JobStore(const JobStore&) = delete;
    JobStore& operator=(const JobStore&) = delete;

    void insert(const JobRecord& job);
    /// `with_scene` false leaves scene_json empty: status reads never need megabytes of scene.
    std::optional<JobRecord> find(const std::string& id, bool with_scene = true) const;
    std::optional<JobRecord> find_by_idempotency_key(const std::string& key) const;
    /// Newest first; `after` is the id of the last job of the previous page (empty: from the top).
    std::vector<JobRecord> list(std::size_t limit, const std::string& after) const;

    void mark_running(const std::string& id, UnixMillis started);
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

    /// Jobs that were queued or running when the last process stopped, oldest first; their state
    /// goes back to queued (a solve that did not finish starts over) and their progress to just
    /// a sequence a million above the stored one, where the next run's event ids continue.
    std::vector<std::string> requeue_unfinished();
    std::map<JobStatus, std::size_t> count_by_status() const;

private:
    void exec(const char* sql) const;
    /// Upgrades a store written by an older radiantd in place.
    void add_column_if_missing(const char* table, const char* column, const char* definition) const;
    sqlite3* db_ = nullptr;
    mutable std::mutex mutex_;
};

}  // namespace radiant::server
