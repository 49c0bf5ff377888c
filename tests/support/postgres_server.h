// A throw-away PostgreSQL cluster for tests: its own cluster in a temporary directory and a
// server that listens only on a unix socket in that directory (no TCP port at all), stopped and
// deleted with the object. Uses the Debian package's binaries (/usr/lib/postgresql/*/bin). The
// cluster is a copy of one that initdb made once per build (RADIANT_BIN_DIR/../postgres-template):
// ctest runs each test case in a process of its own, and initdb costs a second where a copy
// costs a fraction.
#pragma once

#include <fcntl.h>
#include <libpq-fe.h>
#include <pwd.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace radiant::test {

class PostgresServer {
public:
    /// The newest /usr/lib/postgresql/<version>/bin that has initdb and pg_ctl; empty when
    /// PostgreSQL is not installed.
    static std::filesystem::path binaries() {
        namespace fs = std::filesystem;
        std::vector<fs::path> found;
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator("/usr/lib/postgresql", ec)) {
            const fs::path bin = entry.path() / "bin";
            if (fs::exists(bin / "initdb") && fs::exists(bin / "pg_ctl")) found.push_back(bin);
        }
        if (found.empty()) return {};
        // Version directories are numbers ("15", "16"): the longest, then the greatest, is newest.
        return *std::max_element(
            found.begin(), found.end(), [](const fs::path& a, const fs::path& b) {
                const std::string x = a.parent_path().filename(), y = b.parent_path().filename();
                return x.size() != y.size() ? x.size() < y.size() : x < y;
            });
    }

    /// Creates and starts the cluster; throws with the server's log when that fails.
    PostgresServer() : bin_(binaries()) {
        if (bin_.empty()) throw std::runtime_error("PostgreSQL is not installed");
        std::string pattern =
            (std::filesystem::temp_directory_path() / "radiant_pg_XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        dir_ = pattern;
        // initdb refuses to run as root (CI runs as root): the cluster then belongs to the
        // package's `postgres` user.
        if (::geteuid() == 0) {
            if (!::getpwnam("postgres")) {
                throw std::runtime_error("running as root and there is no postgres user");
            }
            as_user_ = "runuser -u postgres -- ";
            give_to_server(dir_);
        }
        const std::string data = (dir_ / "data").string();
        copy_template(data);
        run("pg_ctl -D " + data + " -l " + (dir_ / "server.log").string() +
            " -w -t 60 -o \"-c listen_addresses='' -k " + dir_.string() + " -p " + kPort +
            " -c fsync=off -c max_connections=50\" start");
        started_ = true;
    }

    ~PostgresServer() {
        if (started_) {
            std::system((as_user_ + (bin_ / "pg_ctl").string() + " -D " + (dir_ / "data").string() +
                         " -m immediate stop >/dev/null 2>&1")
                            .c_str());
        }
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    PostgresServer(const PostgresServer&) = delete;
    PostgresServer& operator=(const PostgresServer&) = delete;

    /// A libpq connection string for `database` on this server.
    std::string uri(const std::string& database) const {
        return "host=" + dir_.string() + " port=" + kPort + " user=radiant dbname=" + database;
    }

    /// The same as a postgresql:// URI, as radiantd --store takes it.
    std::string url(const std::string& database) const {
        return "postgresql://radiant@/" + database + "?host=" + dir_.string() + "&port=" + kPort;
    }

    /// The first row `sql` returns on `database`, its values as text (empty: no row).
    std::vector<std::string> query_row(const std::string& database, const std::string& sql) const {
        PGconn* conn = PQconnectdb(uri(database).c_str());
        PGresult* result = PQexec(conn, sql.c_str());
        const bool ok = PQresultStatus(result) == PGRES_TUPLES_OK;
        const std::string why = PQerrorMessage(conn);
        std::vector<std::string> row;
        for (int col = 0; ok && PQntuples(result) > 0 && col < PQnfields(result); ++col) {
            row.emplace_back(PQgetvalue(result, 0, col));
        }
        PQclear(result);
        PQfinish(conn);
        if (!ok) throw std::runtime_error(sql + ": " + why);
        return row;
    }

    /// Creates an empty database named `name` (letters, digits and underscores).
    void create_database(const std::string& name) const {
        PGconn* conn = PQconnectdb(uri("postgres").c_str());
        const std::string sql = "CREATE DATABASE " + name;
        PGresult* result = PQexec(conn, sql.c_str());
        const bool ok = PQresultStatus(result) == PGRES_COMMAND_OK;
        const std::string why = PQerrorMessage(conn);
        PQclear(result);
        PQfinish(conn);
        if (!ok) throw std::runtime_error(sql + ": " + why);
    }

    /// Runs `sql` on `database`, as an operator would with psql; throws when it fails.
    void execute(const std::string& database, const std::string& sql) const {
        PGconn* conn = PQconnectdb(uri(database).c_str());
        PGresult* result = PQexec(conn, sql.c_str());
        const ExecStatusType status = PQresultStatus(result);
        const std::string why = PQerrorMessage(conn);
        PQclear(result);
        PQfinish(conn);
        if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
            throw std::runtime_error(sql + ": " + why);
        }
    }

private:
    static constexpr const char* kPort = "5432";  // only names the socket file in dir_

    /// Copies the build's template cluster to `data`, making the template first if there is none
    /// (one process at a time, under a lock; it appears whole, by a rename, or not at all).
    void copy_template(const std::string& data) const {
        namespace fs = std::filesystem;
        const fs::path root = fs::path(RADIANT_BIN_DIR).parent_path() / "postgres-template";
        const fs::path made = root / bin_.parent_path().filename();  // one per server version
        fs::create_directories(root);
        const int lock = ::open((root / "lock").c_str(), O_RDWR | O_CREAT, 0644);
        if (lock < 0 || ::flock(lock, LOCK_EX) != 0)
            throw std::runtime_error("cannot lock " + root.string());
        try {
            if (!fs::exists(made)) {
                const fs::path building = root / "building";
                fs::remove_all(building);
                fs::create_directories(building);
                give_to_server(building);
                // --no-sync (and fsync=off at start): a test cluster need not survive a power
                // cut, and syncing costs seconds on a shared CI disk.
                run("initdb -D " + (building / "data").string() +
                    " -U radiant -A trust -E UTF8 --no-locale --no-sync");
                fs::rename(building / "data", made);
                fs::remove_all(building);
            }
        } catch (...) {
            ::close(lock);
            throw;
        }
        ::close(lock);
        // cp -a keeps the owner and the 0700 mode the server insists on.
        if (std::system(("cp -a '" + made.string() + "' '" + data + "'").c_str()) != 0) {
            throw std::runtime_error("cannot copy the template cluster " + made.string());
        }
    }

    /// As root, initdb and the server run as `postgres`: `dir` must be theirs.
    void give_to_server(const std::filesystem::path& dir) const {
        if (as_user_.empty()) return;
        const passwd* user = ::getpwnam("postgres");
        if (!user || ::chown(dir.c_str(), user->pw_uid, user->pw_gid) != 0) {
            throw std::runtime_error("cannot give " + dir.string() + " to postgres");
        }
    }

    void run(const std::string& command) const {
        const std::string log = (dir_ / "setup.log").string();
        const std::string line = as_user_ + (bin_ / command).string() + " >>" + log + " 2>&1";
        if (std::system(line.c_str()) != 0) {
            std::ifstream in(log);
            std::ostringstream text;
            text << in.rdbuf();
            std::ifstream server(dir_ / "server.log");
            text << server.rdbuf();
            throw std::runtime_error("`" + line + "` failed:\n" + text.str());
        }
    }

    std::filesystem::path bin_;
    std::filesystem::path dir_;
    std::string as_user_;  ///< a prefix that runs a command as `postgres` when we are root
    bool started_ = false;
};

/// One cluster for a whole test binary (starting one takes a second or two), stopped at exit.
inline PostgresServer& shared_postgres() {
    static PostgresServer server;
    return server;
}

/// Why a test that needs PostgreSQL does not run, or empty when it can.
inline std::string postgres_missing() {
    if (!PostgresServer::binaries().empty()) return {};
    return "PostgreSQL is not installed (no /usr/lib/postgresql/*/bin/initdb): the PostgreSQL "
           "store is not tested; scripts/deps installs it";
}

}  // namespace radiant::test
