#include "radiant/server/sqlite_job_store.h"

#include <fcntl.h>
#include <spdlog/spdlog.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

namespace radiant::server {
namespace {

namespace fs = std::filesystem;

/// Free space, on the disk and under JobStoreOptions::max_bytes, that lets an unwritable store
/// count as writable again: room for a few results with their meshes.
constexpr std::size_t kRecoveredFreeBytes = 16u << 20;

/// A condition on jobs that only the run holding a lease passes (bound twice, after the other
/// parameters); any run passes with kUnfenced.
constexpr const char* kFenced = " AND (? = 0 OR lease_token = ?)";

/// The lease of a job that mark_running started: it never expires while the process lives.
constexpr std::int64_t kHeldForLife = std::numeric_limits<std::int64_t>::max();

/// Errors after which the store takes no writes at all, as opposed to one refused row.
bool unwritable(int code) {
    switch (code & 0xff) {
        case SQLITE_FULL:
        case SQLITE_IOERR:
        case SQLITE_READONLY:
        case SQLITE_CANTOPEN:
        case SQLITE_CORRUPT:
        case SQLITE_NOTADB:
        case SQLITE_PERM:
        case SQLITE_NOMEM:
            return true;
        default:
            return false;
    }
}

[[noreturn]] void throw_store_error(sqlite3* db, const std::string& what) {
    throw StoreError("job store: " + what, unwritable(sqlite3_extended_errcode(db)));
}

/// The directory 0700 (it holds scenes, which may be confidential); created when missing.
void make_private_directory(const fs::path& dir) {
    fs::create_directories(dir);
    const auto perms = fs::status(dir).permissions();
    if ((perms & (fs::perms::group_all | fs::perms::others_all)) == fs::perms::none) return;
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace, ec);
    if (ec) spdlog::warn("cannot make {} private (0700): {}", dir.string(), ec.message());
}

/// Creates `file` 0600 when missing, and makes it 0600 when it is not; SQLite creates its -wal
/// and -shm files with the mode of the database.
void make_private_file(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd < 0) {
        throw std::runtime_error("cannot open " + file.string() + ": " + std::strerror(errno));
    }
    const int changed = ::fchmod(fd, 0600);
    ::close(fd);
    if (changed != 0) {
        throw std::runtime_error("cannot make " + file.string() +
                                 " private (0600): " + std::strerror(errno));
    }
}

/// An exclusive lock on `dir` for as long as the returned descriptor stays open; the file holds
/// the owner's pid, for the message a second process gets.
int lock_directory(const fs::path& dir) {
    const fs::path file = dir / "radiant.lock";
    make_private_file(file);
    const int fd = ::open(file.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        throw std::runtime_error("cannot open " + file.string() + ": " + std::strerror(errno));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        char pid[32] = {};
        const ssize_t n = ::pread(fd, pid, sizeof pid - 1, 0);
        ::close(fd);
        if (error != EWOULDBLOCK) {
            throw std::runtime_error("cannot lock " + file.string() + ": " + std::strerror(error));
        }
        const std::string holder = n > 0 ? std::string(pid, static_cast<std::size_t>(n)) : "?";
        throw std::runtime_error("the data directory " + dir.string() +
                                 " is in use by another radiantd (pid " + holder +
                                 "); stop it or give this one another --data");
    }
    const std::string pid = std::to_string(::getpid());
    if (::ftruncate(fd, 0) != 0 ||
        ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
        spdlog::warn("cannot write the pid into {}: {}", file.string(), std::strerror(errno));
    }
    return fd;
}

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
    /// version, mesh_version, mesh_event_id and radiosity_event_id from four columns.
    SnapshotInfo snapshot_info(int first_col) const {
        SnapshotInfo info;
        info.version = static_cast<std::uint64_t>(integer(first_col));
        info.mesh_version = static_cast<std::uint64_t>(integer(first_col + 1));
        info.mesh_event_id = static_cast<std::uint64_t>(integer(first_col + 2));
        info.radiosity_event_id = static_cast<std::uint64_t>(integer(first_col + 3));
        return info;
    }
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
    [[noreturn]] void fail() const { throw_store_error(db_, sqlite3_errmsg(db_)); }
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

SqliteJobStore::SqliteJobStore(const std::filesystem::path& data_dir, JobStoreOptions options)
    : data_dir_(data_dir) {
    make_private_directory(data_dir);
    lock_fd_ = lock_directory(data_dir);
    const fs::path file = data_dir / "radiant.db";
    try {
        make_private_file(file);
        for (const char* suffix : {"-wal", "-shm"}) {
            const fs::path side = file.string() + suffix;
            if (fs::exists(side)) make_private_file(side);
        }
    } catch (...) {
        ::close(lock_fd_);
        throw;
    }
    if (sqlite3_open(file.c_str(), &db_) != SQLITE_OK) {
        const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        ::close(lock_fd_);
        throw std::runtime_error("cannot open job store " + file.string() + ": " + why);
    }
    try {
        initialise(options);
    } catch (...) {
        sqlite3_close(db_);
        ::close(lock_fd_);
        throw;
    }
}

void SqliteJobStore::initialise(const JobStoreOptions& options) {
    // WAL: readers never wait for the writer; synchronous=NORMAL is durable across process
    // crashes (kill -9), which is what the contract promises; power loss may lose the last commit.
    exec("PRAGMA journal_mode=WAL");
    exec("PRAGMA synchronous=NORMAL");
    exec("PRAGMA foreign_keys=ON");
    if (options.max_bytes > 0) {
        const std::size_t pages = std::max<std::size_t>(1, options.max_bytes / page_size());
        exec(("PRAGMA max_page_count=" + std::to_string(pages)).c_str());
    }
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
    // Stores written by an older radiantd get the newer columns, with their defaults.
    add_column_if_missing("jobs", "warnings", "TEXT NOT NULL DEFAULT '[]'");
    // Solves started; one that never returns (its process died) stays counted.
    add_column_if_missing("jobs", "attempts", "INTEGER NOT NULL DEFAULT 0");
    add_column_if_missing("jobs", "cancel_requested", "INTEGER NOT NULL DEFAULT 0");
    // The shared queue's lease (JobStore::claim): who runs the job, and until when (Unix ms).
    add_column_if_missing("jobs", "lease_owner", "TEXT NOT NULL DEFAULT ''");
    add_column_if_missing("jobs", "lease_expires", "INTEGER NOT NULL DEFAULT 0");
    // Each claim's token, which fences the writes of a run another claim took over.
    add_column_if_missing("jobs", "lease_token", "INTEGER NOT NULL DEFAULT 0");
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
    // A running job's latest snapshot (save_snapshot), as the PostgreSQL store keeps it for
    // other replicas; deleted when the job finishes.
    exec(
        "CREATE TABLE IF NOT EXISTS snapshots ("
        " job_id TEXT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
        " version INTEGER NOT NULL,"
        " mesh_version INTEGER NOT NULL,"
        " mesh_event_id INTEGER NOT NULL,"
        " radiosity_event_id INTEGER NOT NULL,"
        " values_event_id INTEGER NOT NULL,"
        " progress TEXT NOT NULL,"
        " mesh BLOB NOT NULL)");
}

SqliteJobStore::~SqliteJobStore() {
    sqlite3_close(db_);
    ::close(lock_fd_);  // releases the directory
}

void SqliteJobStore::add_column_if_missing(const char* table, const char* column,
                                           const char* definition) const {
    Statement info(db_, (std::string("PRAGMA table_info(") + table + ")").c_str());
    while (info.step()) {
        if (info.text(1) == column) return;
    }
    exec(
        (std::string("ALTER TABLE ") + table + " ADD COLUMN " + column + " " + definition).c_str());
}

void SqliteJobStore::exec(const char* sql) const {
    char* message = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        std::string why = message ? message : "unknown error";
        sqlite3_free(message);
        throw_store_error(db_, why);
    }
}

std::size_t SqliteJobStore::page_size() const {
    Statement s(db_, "PRAGMA page_size");
    return s.step() ? static_cast<std::size_t>(std::max<std::int64_t>(s.integer(0), 512)) : 4096;
}

template <typename Write>
void SqliteJobStore::write(Write&& write, bool adds_rows) {
    try {
        write();
        // Only a write that needed room proves there is room again: a row changed in place
        // fits even where no result would.
        if (adds_rows) {
            write_error_.clear();
            note_health({});
        }
    } catch (const StoreError& e) {
        if (e.unwritable()) {
            write_error_ = e.what();
            note_health({false, write_error_});
        }
        throw;
    }
}

std::size_t SqliteJobStore::free_bytes() const {
    struct statvfs disk {};
    std::size_t free = ::statvfs(data_dir_.c_str(), &disk) == 0
                           ? static_cast<std::size_t>(disk.f_bavail) * disk.f_frsize
                           : 0;
    auto pragma = [this](const char* sql) {
        Statement s(db_, sql);
        return s.step() ? static_cast<std::size_t>(s.integer(0)) : 0;
    };
    const std::size_t max_pages = pragma("PRAGMA max_page_count");
    const std::size_t used_pages = pragma("PRAGMA page_count") - pragma("PRAGMA freelist_count");
    if (max_pages > used_pages) {
        free = std::min(free, (max_pages - used_pages) * page_size());
    } else {
        free = 0;
    }
    return free;
}

StoreHealth SqliteJobStore::health() {
    const std::lock_guard lock(mutex_);
    if (write_error_.empty()) return {};
    // Nothing may write for a while (a balancer stops sending jobs to an unhealthy daemon), so
    // room for new results counts as recovery too.
    const std::size_t free = free_bytes();
    if (free >= kRecoveredFreeBytes) {
        write_error_.clear();
        note_health({});
        return {};
    }
    StoreHealth unwritable{false, write_error_ + " (" + std::to_string(free / 1024) + " KiB free)"};
    note_health(unwritable);
    return unwritable;
}

void SqliteJobStore::insert(const JobRecord& job) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
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
        },
        true);
}

std::optional<JobRecord> SqliteJobStore::find(const std::string& id, bool with_scene) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, select_jobs("WHERE id = ?", with_scene).c_str());
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return read_job(s);
}

std::optional<JobRecord> SqliteJobStore::find_by_idempotency_key(const std::string& key) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, select_jobs("WHERE idempotency_key = ?").c_str());
    s.bind(1, key);
    if (!s.step()) return std::nullopt;
    return read_job(s);
}

std::vector<JobRecord> SqliteJobStore::list(std::size_t limit, const std::string& after) const {
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

void SqliteJobStore::mark_running(const std::string& id, UnixMillis started) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
            Statement s(db_,
                        "UPDATE jobs SET status = 'running', started = ?, attempts = attempts + 1,"
                        " lease_owner = '', lease_expires = ? WHERE id = ?");
            s.bind(1, started).bind(2, kHeldForLife).bind(3, id);
            s.step();
        },
        false);
}

void SqliteJobStore::release(const std::string& id, LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
            Statement s(db_, (std::string("UPDATE jobs SET status = 'queued', started = 0,"
                                          " attempts = MAX(attempts - 1, 0) WHERE id = ? AND"
                                          " status = 'running'") +
                              kFenced)
                                 .c_str());
            s.bind(1, id).bind(2, lease).bind(3, lease);
            s.step();
        },
        false);
}

void SqliteJobStore::request_cancel(const std::string& id) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
            Statement s(db_,
                        "UPDATE jobs SET cancel_requested = 1"
                        " WHERE id = ? AND status IN ('queued', 'running')");
            s.bind(1, id);
            s.step();
        },
        false);
}

void SqliteJobStore::save_progress(const std::string& id, const JobProgress& progress,
                                   LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
            // A late write must not replace the final progress of a job that has just finished.
            Statement s(
                db_,
                (std::string("UPDATE jobs SET progress = ? WHERE id = ? AND status = 'running'") +
                 kFenced)
                    .c_str());
            s.bind(1, progress_to_json(progress).dump()).bind(2, id).bind(3, lease).bind(4, lease);
            s.step();
        },
        false);
}

void SqliteJobStore::save_warnings(const std::string& id, const nlohmann::json& warnings,
                                   LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
            Statement s(
                db_, (std::string("UPDATE jobs SET warnings = ? WHERE id = ?") + kFenced).c_str());
            s.bind(1, warnings.dump()).bind(2, id).bind(3, lease).bind(4, lease);
            s.step();
        },
        false);
}

bool SqliteJobStore::finish(const std::string& id, JobStatus status, UnixMillis finished,
                            const JobProgress& progress, const std::string& error,
                            const std::optional<std::string>& result_json,
                            const std::optional<StoredMesh>& mesh, LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    bool held = false;
    write(
        [&] {
            held = finish_locked(id, status, finished, progress, error, result_json, mesh, lease);
        },
        result_json.has_value());
    return held;
}

bool SqliteJobStore::finish_locked(const std::string& id, JobStatus status, UnixMillis finished,
                                   const JobProgress& progress, const std::string& error,
                                   const std::optional<std::string>& result_json,
                                   const std::optional<StoredMesh>& mesh, LeaseToken lease) {
    bool held = false;
    transaction([&] {
        Statement s(db_, (std::string("UPDATE jobs SET status = ?, finished = ?, progress = ?,"
                                      " error = ? WHERE id = ?") +
                          kFenced + " RETURNING 1")
                             .c_str());
        s.bind(1, std::string(to_string(status)))
            .bind(2, finished)
            .bind(3, progress_to_json(progress).dump())
            .bind(4, error)
            .bind(5, id)
            .bind(6, lease)
            .bind(7, lease);
        held = s.step();
        if (!held) return;  // another claim runs the job now: its outcome is the one to keep
        Statement running(db_, "DELETE FROM snapshots WHERE job_id = ?");
        running.bind(1, id);
        running.step();
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
    });
    return held;
}

std::optional<std::string> SqliteJobStore::result(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT result FROM results WHERE job_id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return s.text(0);
}

std::optional<StoredMesh> SqliteJobStore::mesh(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_,
                "SELECT version, mesh_version, mesh_event_id, radiosity_event_id, final, mesh"
                " FROM meshes WHERE job_id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    StoredMesh mesh;
    mesh.info = s.snapshot_info(0);
    mesh.info.final = s.integer(4) != 0;
    mesh.blob = s.blob(5);
    return mesh;
}

void SqliteJobStore::save_snapshot(const std::string& id, const SnapshotInfo& info,
                                   const std::optional<std::string>& blob, LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    write(
        [&] {
            transaction([&] {
                Statement running(
                    db_, (std::string("SELECT 1 FROM jobs WHERE id = ? AND status = 'running'") +
                          kFenced)
                             .c_str());
                running.bind(1, id).bind(2, lease).bind(3, lease);
                if (!running.step()) return;
                // Without a blob, only a row whose values are these already is updated.
                Statement s(db_, blob ? "INSERT OR REPLACE INTO snapshots (version, mesh_version,"
                                        " mesh_event_id, radiosity_event_id, progress,"
                                        " values_event_id, job_id, mesh)"
                                        " VALUES (?, ?, ?, ?, ?, ?, ?, ?)"
                                      : "UPDATE snapshots SET version = ?, mesh_version = ?,"
                                        " mesh_event_id = ?, radiosity_event_id = ?,"
                                        " progress = ? WHERE values_event_id = ? AND job_id = ?");
                s.bind(1, static_cast<std::int64_t>(info.version))
                    .bind(2, static_cast<std::int64_t>(info.mesh_version))
                    .bind(3, static_cast<std::int64_t>(info.mesh_event_id))
                    .bind(4, static_cast<std::int64_t>(info.radiosity_event_id))
                    .bind(5, progress_to_json(info.progress).dump())
                    .bind(6, static_cast<std::int64_t>(info.values_event_id))
                    .bind(7, id);
                if (blob) s.bind_blob(8, *blob);
                s.step();
            });
        },
        blob.has_value());
}

std::optional<StoredMesh> SqliteJobStore::running_snapshot(
    const std::string& id, std::uint64_t have_values_event_id) const {
    const std::lock_guard lock(mutex_);
    Statement s(db_,
                "SELECT s.version, s.mesh_version, s.mesh_event_id, s.radiosity_event_id,"
                " s.values_event_id, s.progress, CASE WHEN s.values_event_id = ? THEN NULL"
                " ELSE s.mesh END FROM snapshots s JOIN jobs j ON j.id = s.job_id"
                " WHERE s.job_id = ? AND j.status = 'running'");
    s.bind(1, static_cast<std::int64_t>(have_values_event_id)).bind(2, id);
    if (!s.step()) return std::nullopt;
    StoredMesh snapshot;
    snapshot.info = s.snapshot_info(0);
    snapshot.info.values_event_id = static_cast<std::uint64_t>(s.integer(4));
    snapshot.info.progress = progress_from_json(nlohmann::json::parse(s.text(5), nullptr, false));
    snapshot.blob = s.blob(6);
    return snapshot;
}

std::vector<std::string> SqliteJobStore::ids(const std::string& where) const {
    Statement s(db_, ("SELECT id FROM jobs WHERE " + where + " ORDER BY seq").c_str());
    std::vector<std::string> found;
    while (s.step()) found.push_back(s.text(0));
    return found;
}

void SqliteJobStore::end_dead_jobs(const std::string& dead, UnixMillis now, int max_attempts,
                                   UnfinishedJobs& out) {
    const std::string cancelled = "(status = 'queued' OR (" + dead + ")) AND cancel_requested = 1";
    out.cancelled = ids(cancelled);
    Statement cancel(
        db_, ("UPDATE jobs SET status = 'cancelled', finished = ? WHERE " + cancelled).c_str());
    cancel.bind(1, now);
    cancel.step();
    const std::string killed = "(" + dead + ") AND attempts >= " + std::to_string(max_attempts);
    out.failed = ids(killed);
    Statement fail(
        db_,
        ("UPDATE jobs SET status = 'failed', finished = ?, error = ? WHERE " + killed).c_str());
    fail.bind(1, now).bind(2, attempts_exhausted_error(max_attempts));
    fail.step();
}

template <typename Body>
void SqliteJobStore::transaction(Body&& body) {
    exec("BEGIN IMMEDIATE");
    try {
        body();
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
}

UnfinishedJobs SqliteJobStore::requeue_unfinished(int max_attempts) {
    const std::lock_guard lock(mutex_);
    UnfinishedJobs out;
    write(
        [&] {
            transaction([&] {
                // The directory lock proves that every running job's process is gone.
                end_dead_jobs("status = 'running'", now_millis(), max_attempts, out);
                // Event ids continue far above any the stopped run can have sent (it stored its
                // sequence at least once a second and sends a few dozen ids a second), so a client
                // resuming with an old Last-Event-ID still gets the new run's events.
                exec(
                    "UPDATE jobs SET status = 'queued', started = 0, progress = json_object("
                    "'sequence', COALESCE(json_extract(progress, '$.sequence'), 0) + 1000000)"
                    " WHERE status IN ('queued', 'running')");
                out.requeued = ids("status = 'queued'");
            });
        },
        false);
    return out;
}

std::optional<JobRecord> SqliteJobStore::claim(const std::string& owner,
                                               std::chrono::milliseconds lease, int max_attempts) {
    const std::lock_guard lock(mutex_);
    std::string id;
    LeaseToken token = kUnfenced;
    write(
        [&] {
            transaction([&] {
                const UnixMillis now = now_millis();
                const std::string expired =
                    "status = 'running' AND lease_expires < " + std::to_string(now);
                UnfinishedJobs ended;
                end_dead_jobs(expired, now, max_attempts, ended);
                // A job taken back from a dead process continues its event ids far above the
                // ones that process sent (see requeue_unfinished).
                Statement s(
                    db_,
                    ("UPDATE jobs SET status = 'running', started = ?, attempts = attempts + 1,"
                     " lease_owner = ?, lease_expires = ?, lease_token = lease_token + 1,"
                     " progress = CASE WHEN status = 'running'"
                     " THEN json_object('sequence',"
                     " COALESCE(json_extract(progress, '$.sequence'), 0) + 1000000)"
                     " ELSE progress END"
                     " WHERE seq = (SELECT seq FROM jobs WHERE status = 'queued' OR (" +
                     expired + ") ORDER BY seq LIMIT 1) RETURNING id, lease_token")
                        .c_str());
                s.bind(1, now).bind(2, owner).bind(3, now + lease.count());
                if (s.step()) {
                    id = s.text(0);
                    token = s.integer(1);
                }
            });
        },
        false);
    if (id.empty()) return std::nullopt;
    Statement s(db_, select_jobs("WHERE id = ?").c_str());
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    JobRecord claimed = read_job(s);
    claimed.lease_token = token;
    return claimed;
}

LeaseRenewal SqliteJobStore::renew_lease(const std::string& id, const std::string& owner,
                                         std::chrono::milliseconds lease, LeaseToken token) {
    const std::lock_guard lock(mutex_);
    LeaseRenewal renewal;
    write(
        [&] {
            Statement s(db_, (std::string("UPDATE jobs SET lease_expires = ? WHERE id = ? AND"
                                          " status = 'running' AND lease_owner = ?") +
                              kFenced + " RETURNING cancel_requested")
                                 .c_str());
            s.bind(1, now_millis() + lease.count())
                .bind(2, id)
                .bind(3, owner)
                .bind(4, token)
                .bind(5, token);
            if (s.step()) {
                renewal.held = true;
                renewal.cancel_requested = s.integer(0) != 0;
            }
        },
        false);
    return renewal;
}

std::map<JobStatus, std::size_t> SqliteJobStore::count_by_status() const {
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
