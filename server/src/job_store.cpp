#include "radiant/server/job_store.h"

#include <sqlite3.h>

#include <stdexcept>
#include <utility>

namespace radiant::server {
namespace {

/// RAII prepared statement with 1-based binds; columns are read by index.
class Statement {
public:
    Statement(sqlite3* db, const char* sql) : db_(db) {
        if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) fail();
    }
    ~Statement() { sqlite3_finalize(stmt_); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    Statement& bind(int i, const std::string& text) {
        check(sqlite3_bind_text(stmt_, i, text.data(), static_cast<int>(text.size()),
                                SQLITE_TRANSIENT));
        return *this;
    }
    Statement& bind(int i, std::int64_t value) {
        check(sqlite3_bind_int64(stmt_, i, value));
        return *this;
    }
    Statement& bind_blob(int i, const std::string& bytes) {
        check(sqlite3_bind_blob64(stmt_, i, bytes.data(), bytes.size(), SQLITE_TRANSIENT));
        return *this;
    }
    Statement& bind_null(int i) {
        check(sqlite3_bind_null(stmt_, i));
        return *this;
    }
    /// True while there is a row to read.
    bool step() {
        const int rc = sqlite3_step(stmt_);
        if (rc == SQLITE_ROW) return true;
        if (rc != SQLITE_DONE) fail();
        return false;
    }
    std::string text(int col) const {
        const auto* p = sqlite3_column_text(stmt_, col);
        return p ? std::string(reinterpret_cast<const char*>(p),
                               static_cast<std::size_t>(sqlite3_column_bytes(stmt_, col)))
                 : std::string();
    }
    std::int64_t integer(int col) const { return sqlite3_column_int64(stmt_, col); }
    std::string blob(int col) const {
        const void* p = sqlite3_column_blob(stmt_, col);
        return p ? std::string(static_cast<const char*>(p),
                               static_cast<std::size_t>(sqlite3_column_bytes(stmt_, col)))
                 : std::string();
    }

private:
    void check(int rc) const {
        if (rc != SQLITE_OK) fail();
    }
    [[noreturn]] void fail() const {
        throw std::runtime_error(std::string("job store: ") + sqlite3_errmsg(db_));
    }
    sqlite3* db_;
    sqlite3_stmt* stmt_ = nullptr;
};

constexpr const char* kJobColumns =
    "id, status, scene, idempotency_key, created, started, finished, progress, error, warnings";

JobRecord read_job(const Statement& s) {
    JobRecord job;
    job.id = s.text(0);
    job.status = parse_job_status(s.text(1)).value_or(JobStatus::failed);
    job.scene_json = s.text(2);
    job.idempotency_key = s.text(3);
    job.created = s.integer(4);
    job.started = s.integer(5);
    job.finished = s.integer(6);
    job.progress = progress_from_json(nlohmann::json::parse(s.text(7), nullptr, false));
    job.error = s.text(8);
    job.warnings = nlohmann::json::parse(s.text(9), nullptr, false);
    if (!job.warnings.is_array()) job.warnings = nlohmann::json::array();
    return job;
}

std::string select_jobs(const char* where, bool with_scene = true) {
    std::string columns = kJobColumns;
    // Listing never needs scenes, which may be megabytes each.
    if (!with_scene) columns.replace(columns.find("scene,"), 6, "'' AS scene,");
    return "SELECT " + columns + " FROM jobs " + where;
}

}  // namespace

JobStore::JobStore(const std::filesystem::path& data_dir) {
    std::filesystem::create_directories(data_dir);
    const std::string file = (data_dir / "radiant.db").string();
    if (sqlite3_open(file.c_str(), &db_) != SQLITE_OK) {
        const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        throw std::runtime_error("cannot open job store " + file + ": " + why);
    }
    // WAL: readers never wait for the writer; synchronous=NORMAL is durable across process
    // crashes (kill -9), which is what the contract promises; power loss may lose the last commit.
    exec("PRAGMA journal_mode=WAL");
    exec("PRAGMA synchronous=NORMAL");
    exec("PRAGMA foreign_keys=ON");
    // A second process on the same directory waits briefly instead of failing at once.
    sqlite3_busy_timeout(db_, 5000);
    exec(
        "CREATE TABLE IF NOT EXISTS jobs ("
        " seq INTEGER PRIMARY KEY AUTOINCREMENT,"  // submission order: newest first = seq DESC
        " id TEXT NOT NULL UNIQUE,"
        " status TEXT NOT NULL,"
        " scene TEXT NOT NULL,"
        " idempotency_key TEXT,"
        " created INTEGER NOT NULL,"
        " started INTEGER NOT NULL DEFAULT 0,"
        " finished INTEGER NOT NULL DEFAULT 0,"
        " progress TEXT NOT NULL DEFAULT '{}',"
        " error TEXT NOT NULL DEFAULT '',"
        " warnings TEXT NOT NULL DEFAULT '[]')");
    add_column_if_missing("jobs", "warnings", "TEXT NOT NULL DEFAULT '[]'");
    exec(
        "CREATE UNIQUE INDEX IF NOT EXISTS jobs_idempotency ON jobs(idempotency_key)"
        " WHERE idempotency_key IS NOT NULL");
    exec(
        "CREATE TABLE IF NOT EXISTS results ("
        " job_id TEXT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
        " result TEXT NOT NULL)");
    // The solved mesh apart from the result text: float32 arrays in one blob (compact_mesh.h),
    // with the event ids its `mesh` and `radiosity` events had, so a stream can replay them.
    exec(
        "CREATE TABLE IF NOT EXISTS meshes ("
        " job_id TEXT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
        " version INTEGER NOT NULL,"
        " mesh_version INTEGER NOT NULL,"
        " mesh_event_id INTEGER NOT NULL,"
        " radiosity_event_id INTEGER NOT NULL,"
        " final INTEGER NOT NULL,"
        " mesh BLOB NOT NULL)");
}

JobStore::~JobStore() { sqlite3_close(db_); }

void JobStore::add_column_if_missing(const char* table, const char* column,
                                     const char* definition) const {
    Statement info(db_, (std::string("PRAGMA table_info(") + table + ")").c_str());
    while (info.step()) {
        if (info.text(1) == column) return;
    }
    exec(
        (std::string("ALTER TABLE ") + table + " ADD COLUMN " + column + " " + definition).c_str());
}

void JobStore::exec(const char* sql) const {
    char* message = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        std::string why = message ? message : "unknown error";
        sqlite3_free(message);
        throw std::runtime_error("job store: " + why);
    }
}

void JobStore::insert(const JobRecord& job) {
    const std::lock_guard lock(mutex_);
    Statement s(db_,
                "INSERT INTO jobs (id, status, scene, idempotency_key, created, progress)"
                " VALUES (?, ?, ?, ?, ?, ?)");
    s.bind(1, job.id).bind(2, std::string(to_string(job.status))).bind(3, job.scene_json);
    if (job.idempotency_key.empty()) {
        s.bind_null(4);
    } else {
        s.bind(4, job.idempotency_key);
    }
    s.bind(5, job.created).bind(6, progress_to_json(job.progress).dump());
    s.step();
}

std::optional<JobRecord> JobStore::find(const std::string& id, bool with_scene) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, select_jobs("WHERE id = ?", with_scene).c_str());
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return read_job(s);
}

std::optional<JobRecord> JobStore::find_by_idempotency_key(const std::string& key) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, select_jobs("WHERE idempotency_key = ?").c_str());
    s.bind(1, key);
    if (!s.step()) return std::nullopt;
    return read_job(s);
}

std::vector<JobRecord> JobStore::list(std::size_t limit, const std::string& after) const {
    const std::lock_guard lock(mutex_);
    const std::string sql = after.empty() ? select_jobs("ORDER BY seq DESC LIMIT ?", false)
                                          : select_jobs(
                                                "WHERE seq < (SELECT seq FROM jobs WHERE id = ?)"
                                                " ORDER BY seq DESC LIMIT ?",
                                                false);
    Statement s(db_, sql.c_str());
    int i = 1;
    if (!after.empty()) s.bind(i++, after);
    s.bind(i, static_cast<std::int64_t>(limit));
    std::vector<JobRecord> jobs;
    while (s.step()) jobs.push_back(read_job(s));
    return jobs;
}

void JobStore::mark_running(const std::string& id, UnixMillis started) {
    const std::lock_guard lock(mutex_);
    Statement s(db_, "UPDATE jobs SET status = 'running', started = ? WHERE id = ?");
    s.bind(1, started).bind(2, id);
    s.step();
}

void JobStore::save_progress(const std::string& id, const JobProgress& progress) {
    const std::lock_guard lock(mutex_);
    // A late write must not replace the final progress of a job that has just finished.
    Statement s(db_, "UPDATE jobs SET progress = ? WHERE id = ? AND status = 'running'");
    s.bind(1, progress_to_json(progress).dump()).bind(2, id);
    s.step();
}

void JobStore::save_warnings(const std::string& id, const nlohmann::json& warnings) {
    const std::lock_guard lock(mutex_);
    Statement s(db_, "UPDATE jobs SET warnings = ? WHERE id = ?");
    s.bind(1, warnings.dump()).bind(2, id);
    s.step();
}

void JobStore::finish(const std::string& id, JobStatus status, UnixMillis finished,
                      const JobProgress& progress, const std::string& error,
                      const std::optional<std::string>& result_json,
                      const std::optional<StoredMesh>& mesh) {
    const std::lock_guard lock(mutex_);
    exec("BEGIN IMMEDIATE");
    try {
        Statement s(db_,
                    "UPDATE jobs SET status = ?, finished = ?, progress = ?, error = ?"
                    " WHERE id = ?");
        s.bind(1, std::string(to_string(status)))
            .bind(2, finished)
            .bind(3, progress_to_json(progress).dump())
            .bind(4, error)
            .bind(5, id);
        s.step();
        if (result_json) {
            Statement r(db_, "INSERT OR REPLACE INTO results (job_id, result) VALUES (?, ?)");
            r.bind(1, id).bind(2, *result_json);
            r.step();
        }
        if (mesh) {
            Statement m(db_,
                        "INSERT OR REPLACE INTO meshes (job_id, version, mesh_version,"
                        " mesh_event_id, radiosity_event_id, final, mesh)"
                        " VALUES (?, ?, ?, ?, ?, ?, ?)");
            const SnapshotInfo& i = mesh->info;
            m.bind(1, id)
                .bind(2, static_cast<std::int64_t>(i.version))
                .bind(3, static_cast<std::int64_t>(i.mesh_version))
                .bind(4, static_cast<std::int64_t>(i.mesh_event_id))
                .bind(5, static_cast<std::int64_t>(i.radiosity_event_id))
                .bind(6, std::int64_t{i.final ? 1 : 0})
                .bind_blob(7, mesh->blob);
            m.step();
        }
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
}

std::optional<std::string> JobStore::result(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT result FROM results WHERE job_id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return s.text(0);
}

std::optional<StoredMesh> JobStore::mesh(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_,
                "SELECT version, mesh_version, mesh_event_id, radiosity_event_id, final, mesh"
                " FROM meshes WHERE job_id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    StoredMesh mesh;
    mesh.info.version = static_cast<std::uint64_t>(s.integer(0));
    mesh.info.mesh_version = static_cast<std::uint64_t>(s.integer(1));
    mesh.info.mesh_event_id = static_cast<std::uint64_t>(s.integer(2));
    mesh.info.radiosity_event_id = static_cast<std::uint64_t>(s.integer(3));
    mesh.info.final = s.integer(4) != 0;
    mesh.blob = s.blob(5);
    return mesh;
}

std::vector<std::string> JobStore::requeue_unfinished() {
    const std::lock_guard lock(mutex_);
    // Event ids continue far above any the stopped run can have sent (it stored its sequence at
    // least once a second and sends a few dozen ids a second), so a client resuming with an old
    // Last-Event-ID still gets the new run's events.
    exec(
        "UPDATE jobs SET status = 'queued', started = 0, progress = json_object('sequence',"
        " COALESCE(json_extract(progress, '$.sequence'), 0) + 1000000)"
        " WHERE status IN ('queued', 'running')");
    Statement s(db_, "SELECT id FROM jobs WHERE status = 'queued' ORDER BY seq");
    std::vector<std::string> ids;
    while (s.step()) ids.push_back(s.text(0));
    return ids;
}

std::map<JobStatus, std::size_t> JobStore::count_by_status() const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT status, COUNT(*) FROM jobs GROUP BY status");
    std::map<JobStatus, std::size_t> counts;
    while (s.step()) {
        if (auto status = parse_job_status(s.text(0))) {
            counts[*status] = static_cast<std::size_t>(s.integer(1));
        }
    }
    return counts;
}

}  // namespace radiant::server
