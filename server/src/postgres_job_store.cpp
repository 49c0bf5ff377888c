#include "radiant/server/postgres_job_store.h"

#include "postgres_change_feed.h"
#include "postgres_connection.h"

#include <fmt/format.h>
#include <libpq-fe.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <limits>
#include <utility>

namespace radiant::server {
namespace {

/// The database's clock in Unix milliseconds; clock_timestamp(), not now(), because now() stays
/// at the transaction's start.
constexpr const char* kNowMs = "(extract(epoch FROM clock_timestamp()) * 1000)::bigint";

/// The lease of a job that mark_running started: it never expires while the process lives.
constexpr std::int64_t kHeldForLife = std::numeric_limits<std::int64_t>::max();

/// Serialises schema migrations among replicas that start together (an arbitrary constant:
/// "radiant" in ASCII).
constexpr long long kMigrationLockKey = 0x72616469616e74;

/// Each entry takes the schema from version i to i + 1; never edit one that has shipped.
constexpr const char* kMigrations[] = {
    // 1: jobs (seq keeps submission order), results, and the solved meshes, as in the SQLite
    // store, plus the lease of the replica running a job.
    "CREATE TABLE jobs ("
    " seq BIGSERIAL PRIMARY KEY,"
    " id TEXT NOT NULL UNIQUE,"
    " status TEXT NOT NULL,"
    " scene TEXT NOT NULL,"
    " idempotency_key TEXT UNIQUE,"
    " created BIGINT NOT NULL,"
    " started BIGINT NOT NULL DEFAULT 0,"
    " finished BIGINT NOT NULL DEFAULT 0,"
    " progress TEXT NOT NULL DEFAULT '{}',"
    " error TEXT NOT NULL DEFAULT '',"
    " warnings TEXT NOT NULL DEFAULT '[]',"
    " attempts INTEGER NOT NULL DEFAULT 0,"
    " cancel_requested BOOLEAN NOT NULL DEFAULT false,"
    " lease_owner TEXT NOT NULL DEFAULT '',"
    " lease_expires BIGINT NOT NULL DEFAULT 0);"
    // Claims scan only unfinished jobs, however many finished ones the table holds.
    "CREATE INDEX jobs_unfinished ON jobs (seq) WHERE status IN ('queued', 'running');"
    "CREATE TABLE results ("
    " job_id TEXT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
    " result TEXT NOT NULL);"
    "CREATE TABLE meshes ("
    " job_id TEXT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
    " version BIGINT NOT NULL,"
    " mesh_version BIGINT NOT NULL,"
    " mesh_event_id BIGINT NOT NULL,"
    " radiosity_event_id BIGINT NOT NULL,"
    " final BOOLEAN NOT NULL,"
    " mesh BYTEA NOT NULL);",
    // 2: a running job's latest snapshot, which its replica writes so that the others can
    // stream it; and a NOTIFY on `radiant_jobs` with the job's id whenever a job's state or
    // progress, or its snapshot, changes (postgres_change_feed.h). Lease renewals do not notify:
    // they change nothing a reader shows.
    "CREATE TABLE snapshots ("
    " job_id TEXT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
    " version BIGINT NOT NULL,"
    " mesh_version BIGINT NOT NULL,"
    " mesh_event_id BIGINT NOT NULL,"
    " radiosity_event_id BIGINT NOT NULL,"
    " values_event_id BIGINT NOT NULL,"
    " progress TEXT NOT NULL,"
    " mesh BYTEA NOT NULL);"
    "CREATE FUNCTION radiant_job_changed() RETURNS trigger LANGUAGE plpgsql AS"
    " $$BEGIN PERFORM pg_notify('radiant_jobs', NEW.id); RETURN NULL; END$$;"
    "CREATE TRIGGER jobs_changed AFTER UPDATE OF status, progress, error, warnings ON jobs"
    " FOR EACH ROW EXECUTE FUNCTION radiant_job_changed();"
    "CREATE FUNCTION radiant_snapshot_changed() RETURNS trigger LANGUAGE plpgsql AS"
    " $$BEGIN PERFORM pg_notify('radiant_jobs', NEW.job_id); RETURN NULL; END$$;"
    "CREATE TRIGGER snapshots_changed AFTER INSERT OR UPDATE ON snapshots FOR EACH ROW"
    " EXECUTE FUNCTION radiant_snapshot_changed();",
    // 3: each claim's token, which fences the writes of a run whose lease another claim took
    // (JobStore::LeaseToken).
    "ALTER TABLE jobs ADD COLUMN lease_token BIGINT NOT NULL DEFAULT 0;",
};
static_assert(std::size(kMigrations) == PostgresJobStore::kSchemaVersion);

constexpr const char* kJobColumns =
    "id, status, scene, idempotency_key, created, started, finished, progress, error, warnings";

/// Failures after which no write can succeed (as opposed to one refused row): the connection
/// (class 08), the server's resources (53), a read-only server (25006), or its shutdown (57P).
bool unwritable(const std::string& sqlstate) {
    return sqlstate.empty() || sqlstate.starts_with("08") || sqlstate.starts_with("53") ||
           sqlstate == "25006" || sqlstate.starts_with("57P");
}

/// Sets progress to a sequence a million above the stored one (see JobStore::claim).
std::string bumped_sequence(const std::string& progress) {
    return "jsonb_build_object('sequence', COALESCE((" + progress +
           "::jsonb->>'sequence')::bigint, 0) + 1000000)::text";
}

std::string expired_lease() {
    return std::string("status = 'running' AND lease_expires < ") + kNowMs;
}

std::int64_t to_int64(const char* text) { return std::strtoll(text, nullptr, 10); }

/// A condition on jobs that only the run holding `lease` (parameter $n) passes; any run passes
/// with kUnfenced.
std::string fenced(int n) {
    return fmt::format(" AND (${0}::bigint = 0 OR lease_token = ${0}::bigint)", n);
}

}  // namespace

/// A statement's outcome, freed with it; values are read as text.
class PostgresJobStore::Result {
public:
    explicit Result(PGresult* result) : result_(result) {}
    ~Result() { PQclear(result_); }
    Result(Result&& other) noexcept : result_(std::exchange(other.result_, nullptr)) {}
    Result(const Result&) = delete;
    Result& operator=(const Result&) = delete;
    Result& operator=(Result&&) = delete;

    const PGresult* get() const { return result_; }
    int rows() const { return PQntuples(result_); }
    std::string text(int row, int col) const {
        return std::string(PQgetvalue(result_, row, col),
                           static_cast<std::size_t>(PQgetlength(result_, row, col)));
    }
    std::int64_t integer(int row, int col) const { return to_int64(PQgetvalue(result_, row, col)); }
    bool boolean(int row, int col) const { return PQgetvalue(result_, row, col)[0] == 't'; }
    std::string bytes(int row, int col) const {
        std::size_t length = 0;
        unsigned char* raw = PQunescapeBytea(
            reinterpret_cast<const unsigned char*>(PQgetvalue(result_, row, col)), &length);
        if (!raw) throw StoreError("job store: out of memory reading a mesh", false);
        std::string out(reinterpret_cast<const char*>(raw), length);
        PQfreemem(raw);
        return out;
    }
    /// version, mesh_version, mesh_event_id and radiosity_event_id from four columns of row 0.
    SnapshotInfo snapshot_info(int first_col) const {
        SnapshotInfo info;
        info.version = static_cast<std::uint64_t>(integer(0, first_col));
        info.mesh_version = static_cast<std::uint64_t>(integer(0, first_col + 1));
        info.mesh_event_id = static_cast<std::uint64_t>(integer(0, first_col + 2));
        info.radiosity_event_id = static_cast<std::uint64_t>(integer(0, first_col + 3));
        return info;
    }
    std::vector<std::string> column(int col) const {
        std::vector<std::string> values;
        for (int row = 0; row < rows(); ++row) values.push_back(text(row, col));
        return values;
    }
    JobRecord job(int row) const {
        JobRecord job;
        job.id = text(row, 0);
        job.status = parse_job_status(text(row, 1)).value_or(JobStatus::failed);
        job.scene_json = text(row, 2);
        job.idempotency_key = text(row, 3);
        job.created = integer(row, 4);
        job.started = integer(row, 5);
        job.finished = integer(row, 6);
        job.progress = progress_from_json(nlohmann::json::parse(text(row, 7), nullptr, false));
        job.error = text(row, 8);
        job.warnings = nlohmann::json::parse(text(row, 9), nullptr, false);
        if (!job.warnings.is_array()) job.warnings = nlohmann::json::array();
        return job;
    }

private:
    PGresult* result_;
};

PostgresJobStore::PostgresJobStore(std::string uri) : uri_(std::move(uri)) {
    const std::lock_guard lock(mutex_);
    connect();
    migrate();
}

PostgresJobStore::~PostgresJobStore() { PQfinish(conn_); }

void PostgresJobStore::connect() const {
    if (conn_ && PQstatus(conn_) == CONNECTION_OK) return;
    PQfinish(conn_);
    conn_ = nullptr;
    conn_ = connect_postgres(uri_);
}

PostgresJobStore::Result PostgresJobStore::run(
    const std::string& sql, const std::vector<std::optional<std::string>>& params,
    const std::vector<bool>& binary) const {
    try {
        Result result = execute(sql, params, binary);
        note_health({});
        return result;
    } catch (const StoreError& e) {
        // A refused row (a constraint) says nothing of the store's health.
        if (e.unwritable()) note_health({false, e.what()});
        throw;
    }
}

PostgresJobStore::Result PostgresJobStore::execute(
    const std::string& sql, const std::vector<std::optional<std::string>>& params,
    const std::vector<bool>& binary) const {
    connect();
    std::vector<const char*> values;
    std::vector<int> lengths;
    std::vector<int> formats;
    for (std::size_t i = 0; i < params.size(); ++i) {
        values.push_back(params[i] ? params[i]->data() : nullptr);
        lengths.push_back(params[i] ? static_cast<int>(params[i]->size()) : 0);
        formats.push_back(i < binary.size() && binary[i] ? 1 : 0);
    }
    // Without parameters, PQexec: it also runs several statements at once (a migration).
    Result result(params.empty()
                      ? PQexec(conn_, sql.c_str())
                      : PQexecParams(conn_, sql.c_str(), static_cast<int>(params.size()), nullptr,
                                     values.data(), lengths.data(), formats.data(), 0));
    const PGresult* raw = result.get();  // null only when libpq ran out of memory
    const ExecStatusType status = raw ? PQresultStatus(raw) : PGRES_FATAL_ERROR;
    if (status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK) return result;
    const char* state = raw ? PQresultErrorField(raw, PG_DIAG_SQLSTATE) : nullptr;
    throw StoreError(std::string("job store: ") + PQerrorMessage(conn_),
                     unwritable(state ? state : ""));
}

template <typename Body>
void PostgresJobStore::transaction(Body&& body) const {
    run("BEGIN");
    try {
        body();
        run("COMMIT");
    } catch (...) {
        if (PQstatus(conn_) == CONNECTION_OK) PQclear(PQexec(conn_, "ROLLBACK"));
        throw;
    }
}

void PostgresJobStore::migrate() {
    transaction([&] {
        run("SELECT pg_advisory_xact_lock($1)", {std::to_string(kMigrationLockKey)});
        run("CREATE TABLE IF NOT EXISTS radiant_schema (version INTEGER NOT NULL)");
        const Result found = run("SELECT version FROM radiant_schema");
        int version = found.rows() > 0 ? static_cast<int>(found.integer(0, 0)) : 0;
        if (version > kSchemaVersion) {
            throw StoreError("job store: the database's schema is version " +
                                 std::to_string(version) + ", newer than this radiantd's " +
                                 std::to_string(kSchemaVersion) + "; upgrade radiantd",
                             false);
        }
        if (found.rows() == 0) run("INSERT INTO radiant_schema (version) VALUES (0)");
        for (; version < kSchemaVersion; ++version) {
            run(kMigrations[version]);
            spdlog::info("job store: PostgreSQL schema migrated to version {}", version + 1);
        }
        run("UPDATE radiant_schema SET version = $1", {std::to_string(kSchemaVersion)});
    });
}

int PostgresJobStore::schema_version() const {
    const std::lock_guard lock(mutex_);
    const Result r = run("SELECT version FROM radiant_schema");
    return r.rows() > 0 ? static_cast<int>(r.integer(0, 0)) : 0;
}

StoreHealth PostgresJobStore::health() {
    const std::lock_guard lock(mutex_);
    try {
        run("SELECT 1");
        return {};
    } catch (const StoreError& e) {
        return {false, e.what()};
    }
}

void PostgresJobStore::insert(const JobRecord& job) {
    const std::lock_guard lock(mutex_);
    std::optional<std::string> key;
    if (!job.idempotency_key.empty()) key = job.idempotency_key;
    run("INSERT INTO jobs (id, status, scene, idempotency_key, created, progress)"
        " VALUES ($1, $2, $3, $4, $5, $6)",
        {job.id, std::string(to_string(job.status)), job.scene_json, key,
         std::to_string(job.created), progress_to_json(job.progress).dump()});
}

std::optional<JobRecord> PostgresJobStore::find_where(const std::string& where,
                                                      const std::string& value,
                                                      bool with_scene) const {
    const std::lock_guard lock(mutex_);
    std::string columns = kJobColumns;
    // Status reads never need the scene, which may be megabytes.
    if (!with_scene) columns.replace(columns.find("scene,"), 6, "'' AS scene,");
    const Result r = run("SELECT " + columns + " FROM jobs WHERE " + where, {value});
    if (r.rows() == 0) return std::nullopt;
    return r.job(0);
}

std::optional<JobRecord> PostgresJobStore::find(const std::string& id, bool with_scene) const {
    return find_where("id = $1", id, with_scene);
}

std::optional<JobRecord> PostgresJobStore::find_by_idempotency_key(const std::string& key) const {
    return find_where("idempotency_key = $1", key, true);
}

std::vector<JobRecord> PostgresJobStore::list(std::size_t limit, const std::string& after) const {
    const std::lock_guard lock(mutex_);
    std::string columns = kJobColumns;
    columns.replace(columns.find("scene,"), 6, "'' AS scene,");
    const std::string select = "SELECT " + columns + " FROM jobs ";
    const Result r =
        after.empty()
            ? run(select + "ORDER BY seq DESC LIMIT $1", {std::to_string(limit)})
            : run(select +
                      "WHERE seq < (SELECT seq FROM jobs WHERE id = $1) ORDER BY seq DESC LIMIT $2",
                  {after, std::to_string(limit)});
    std::vector<JobRecord> jobs;
    for (int row = 0; row < r.rows(); ++row) jobs.push_back(r.job(row));
    return jobs;
}

void PostgresJobStore::mark_running(const std::string& id, UnixMillis started) {
    const std::lock_guard lock(mutex_);
    run("UPDATE jobs SET status = 'running', started = $1, attempts = attempts + 1,"
        " lease_owner = '', lease_expires = $2 WHERE id = $3",
        {std::to_string(started), std::to_string(kHeldForLife), id});
}

void PostgresJobStore::release(const std::string& id, LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    // Another replica takes the job at once: its run's event ids continue above any this one
    // sent, as after a lease that expired; the stopped run's snapshot is no longer news.
    transaction([&] {
        run("UPDATE jobs SET status = 'queued', started = 0, attempts = GREATEST(attempts - 1, 0),"
            " lease_owner = '', lease_expires = 0, progress = " +
                bumped_sequence("progress") + " WHERE id = $1 AND status = 'running'" + fenced(2),
            {id, std::to_string(lease)});
        run("DELETE FROM snapshots WHERE job_id = $1 AND EXISTS (SELECT 1 FROM jobs WHERE id = $1"
            " AND status = 'queued')",
            {id});
    });
}

void PostgresJobStore::request_cancel(const std::string& id) {
    const std::lock_guard lock(mutex_);
    run("UPDATE jobs SET cancel_requested = true"
        " WHERE id = $1 AND status IN ('queued', 'running')",
        {id});
}

void PostgresJobStore::save_progress(const std::string& id, const JobProgress& progress,
                                     LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    // A late write must not replace the final progress of a job that has just finished.
    run("UPDATE jobs SET progress = $1 WHERE id = $2 AND status = 'running'" + fenced(3),
        {progress_to_json(progress).dump(), id, std::to_string(lease)});
}

void PostgresJobStore::save_warnings(const std::string& id, const nlohmann::json& warnings,
                                     LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    run("UPDATE jobs SET warnings = $1 WHERE id = $2" + fenced(3),
        {warnings.dump(), id, std::to_string(lease)});
}

bool PostgresJobStore::finish(const std::string& id, JobStatus status, UnixMillis finished,
                              const JobProgress& progress, const std::string& error,
                              const std::optional<std::string>& result_json,
                              const std::optional<StoredMesh>& mesh, LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    bool held = false;
    transaction([&] {
        held = run("UPDATE jobs SET status = $1, finished = $2, progress = $3, error = $4,"
                   " lease_owner = '', lease_expires = 0 WHERE id = $5" +
                       fenced(6) + " RETURNING 1",
                   {std::string(to_string(status)), std::to_string(finished),
                    progress_to_json(progress).dump(), error, id, std::to_string(lease)})
                   .rows() > 0;
        if (!held) return;  // another claim runs the job now: its outcome is the one to keep
        run("DELETE FROM snapshots WHERE job_id = $1", {id});
        if (result_json) {
            run("INSERT INTO results (job_id, result) VALUES ($1, $2)"
                " ON CONFLICT (job_id) DO UPDATE SET result = EXCLUDED.result",
                {id, *result_json});
        }
        if (mesh) {
            const SnapshotInfo& i = mesh->info;
            run("INSERT INTO meshes (job_id, version, mesh_version, mesh_event_id,"
                " radiosity_event_id, final, mesh) VALUES ($1, $2, $3, $4, $5, $6, $7)"
                " ON CONFLICT (job_id) DO UPDATE SET version = EXCLUDED.version,"
                " mesh_version = EXCLUDED.mesh_version, mesh_event_id = EXCLUDED.mesh_event_id,"
                " radiosity_event_id = EXCLUDED.radiosity_event_id, final = EXCLUDED.final,"
                " mesh = EXCLUDED.mesh",
                {id, std::to_string(i.version), std::to_string(i.mesh_version),
                 std::to_string(i.mesh_event_id), std::to_string(i.radiosity_event_id),
                 std::string(i.final ? "true" : "false"), mesh->blob},
                {false, false, false, false, false, false, true});
        }
    });
    return held;
}

std::optional<std::string> PostgresJobStore::result(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    const Result r = run("SELECT result FROM results WHERE job_id = $1", {id});
    if (r.rows() == 0) return std::nullopt;
    return r.text(0, 0);
}

std::optional<StoredMesh> PostgresJobStore::mesh(const std::string& id) const {
    const std::lock_guard lock(mutex_);
    const Result r =
        run("SELECT version, mesh_version, mesh_event_id, radiosity_event_id, final, mesh"
            " FROM meshes WHERE job_id = $1",
            {id});
    if (r.rows() == 0) return std::nullopt;
    StoredMesh mesh;
    mesh.info = r.snapshot_info(0);
    mesh.info.final = r.boolean(0, 4);
    mesh.blob = r.bytes(0, 5);
    return mesh;
}

void PostgresJobStore::save_snapshot(const std::string& id, const SnapshotInfo& info,
                                     const std::optional<std::string>& blob, LeaseToken lease) {
    const std::lock_guard lock(mutex_);
    transaction([&] {
        // The job's row stays locked until the snapshot is in: a finish() that comes meanwhile
        // waits, then deletes it, and no snapshot outlives its job's run.
        if (run("SELECT 1 FROM jobs WHERE id = $1 AND status = 'running'" + fenced(2) +
                    " FOR UPDATE",
                {id, std::to_string(lease)})
                .rows() == 0) {
            return;
        }
        std::vector<std::optional<std::string>> params = {id,
                                                          std::to_string(info.version),
                                                          std::to_string(info.mesh_version),
                                                          std::to_string(info.mesh_event_id),
                                                          std::to_string(info.radiosity_event_id),
                                                          std::to_string(info.values_event_id),
                                                          progress_to_json(info.progress).dump()};
        if (!blob) {
            // Only a row whose values are these already is updated.
            run("UPDATE snapshots SET version = $2, mesh_version = $3, mesh_event_id = $4,"
                " radiosity_event_id = $5, progress = $7 WHERE job_id = $1"
                " AND values_event_id = $6",
                params);
            return;
        }
        params.push_back(*blob);
        run("INSERT INTO snapshots (job_id, version, mesh_version, mesh_event_id,"
            " radiosity_event_id, values_event_id, progress, mesh)"
            " VALUES ($1, $2, $3, $4, $5, $6, $7, $8) ON CONFLICT (job_id) DO UPDATE SET"
            " version = EXCLUDED.version, mesh_version = EXCLUDED.mesh_version,"
            " mesh_event_id = EXCLUDED.mesh_event_id,"
            " radiosity_event_id = EXCLUDED.radiosity_event_id,"
            " values_event_id = EXCLUDED.values_event_id, progress = EXCLUDED.progress,"
            " mesh = EXCLUDED.mesh",
            params, {false, false, false, false, false, false, false, true});
    });
}

std::optional<StoredMesh> PostgresJobStore::running_snapshot(
    const std::string& id, std::uint64_t have_values_event_id) const {
    const std::lock_guard lock(mutex_);
    const Result r =
        run("SELECT s.version, s.mesh_version, s.mesh_event_id, s.radiosity_event_id,"
            " s.values_event_id, s.progress, CASE WHEN s.values_event_id = $2 THEN ''::bytea"
            " ELSE s.mesh END FROM snapshots s JOIN jobs j ON j.id = s.job_id"
            " WHERE s.job_id = $1 AND j.status = 'running'",
            {id, std::to_string(have_values_event_id)});
    if (r.rows() == 0) return std::nullopt;
    StoredMesh snapshot;
    snapshot.info = r.snapshot_info(0);
    snapshot.info.values_event_id = static_cast<std::uint64_t>(r.integer(0, 4));
    snapshot.info.progress =
        progress_from_json(nlohmann::json::parse(r.text(0, 5), nullptr, false));
    snapshot.blob = r.bytes(0, 6);
    return snapshot;
}

std::optional<std::uint64_t> PostgresJobStore::change_token(const std::string& id) const {
    // Started by the first reader: a replica that never streams another's job needs no second
    // connection (nor do tools and tests that use the store directly).
    std::call_once(feed_once_, [this] { feed_ = std::make_unique<PostgresChangeFeed>(uri_); });
    return feed_->token(id);
}

void PostgresJobStore::end_dead_jobs(const std::string& dead, int max_attempts,
                                     UnfinishedJobs& out) const {
    // SKIP LOCKED: a row another replica is claiming or finishing right now is its business.
    out.cancelled =
        run(std::string("WITH ended AS (UPDATE jobs SET status = 'cancelled',"
                        " finished = ") +
            kNowMs + " WHERE seq IN (SELECT seq FROM jobs WHERE (status = 'queued' OR (" + dead +
            ")) AND cancel_requested FOR UPDATE SKIP LOCKED)"
            " RETURNING seq, id) SELECT id FROM ended ORDER BY seq")
            .column(0);
    out.failed = run(std::string("WITH ended AS (UPDATE jobs SET status = 'failed', finished = ") +
                         kNowMs + ", error = $1 WHERE seq IN (SELECT seq FROM jobs WHERE (" + dead +
                         ") AND attempts >= $2 FOR UPDATE SKIP LOCKED)"
                         " RETURNING seq, id) SELECT id FROM ended ORDER BY seq",
                     {attempts_exhausted_error(max_attempts), std::to_string(max_attempts)})
                     .column(0);
}

UnfinishedJobs PostgresJobStore::requeue_unfinished(int max_attempts) {
    const std::lock_guard lock(mutex_);
    UnfinishedJobs out;
    transaction([&] {
        end_dead_jobs(expired_lease(), max_attempts, out);
        run("UPDATE jobs SET status = 'queued', started = 0, lease_owner = '', progress = " +
            bumped_sequence("progress") + " WHERE seq IN (SELECT seq FROM jobs WHERE " +
            expired_lease() + " FOR UPDATE SKIP LOCKED)");
        out.requeued = run("SELECT id FROM jobs WHERE status = 'queued' ORDER BY seq").column(0);
    });
    return out;
}

std::optional<JobRecord> PostgresJobStore::claim(const std::string& owner,
                                                 std::chrono::milliseconds lease,
                                                 int max_attempts) {
    const std::lock_guard lock(mutex_);
    std::optional<JobRecord> claimed;
    transaction([&] {
        UnfinishedJobs ended;
        end_dead_jobs(expired_lease(), max_attempts, ended);
        for (const std::string& id : ended.failed) {
            spdlog::warn("job {} failed: {}", id, attempts_exhausted_error(max_attempts));
        }
        // The oldest waiting job that no other replica is claiming at this moment.
        const Result r = run(std::string("WITH next AS (SELECT seq FROM jobs WHERE status = "
                                         "'queued' OR (") +
                                 expired_lease() +
                                 ") ORDER BY seq LIMIT 1 FOR UPDATE SKIP LOCKED)"
                                 " UPDATE jobs j SET status = 'running', started = " +
                                 kNowMs +
                                 ", attempts = j.attempts + 1, lease_owner = $1,"
                                 " lease_expires = " +
                                 kNowMs +
                                 " + $2, lease_token = j.lease_token + 1,"
                                 " progress = CASE WHEN j.status = 'running' THEN " +
                                 bumped_sequence("j.progress") +
                                 " ELSE j.progress END FROM next WHERE j.seq = next.seq"
                                 " RETURNING j.id, j.status, j.scene, j.idempotency_key,"
                                 " j.created, j.started, j.finished, j.progress, j.error,"
                                 " j.warnings, j.lease_token",
                             {owner, std::to_string(lease.count())});
        if (r.rows() > 0) {
            claimed = r.job(0);
            claimed->lease_token = r.integer(0, 10);
        }
    });
    return claimed;
}

LeaseRenewal PostgresJobStore::renew_lease(const std::string& id, const std::string& owner,
                                           std::chrono::milliseconds lease, LeaseToken token) {
    const std::lock_guard lock(mutex_);
    const Result r = run(std::string("UPDATE jobs SET lease_expires = ") + kNowMs +
                             " + $1 WHERE id = $2 AND status = 'running' AND lease_owner = $3" +
                             fenced(4) + " RETURNING cancel_requested",
                         {std::to_string(lease.count()), id, owner, std::to_string(token)});
    if (r.rows() == 0) return {};
    return {true, r.boolean(0, 0)};
}

std::map<JobStatus, std::size_t> PostgresJobStore::count_by_status() const {
    const std::lock_guard lock(mutex_);
    const Result r = run("SELECT status, COUNT(*) FROM jobs GROUP BY status");
    std::map<JobStatus, std::size_t> counts;
    for (int row = 0; row < r.rows(); ++row) {
        if (auto status = parse_job_status(r.text(row, 0))) {
            counts[*status] = static_cast<std::size_t>(r.integer(row, 1));
        }
    }
    return counts;
}

}  // namespace radiant::server
