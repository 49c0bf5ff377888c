#include "postgres_connection.h"

#include <libpq-fe.h>

#include "radiant/server/job_store.h"

namespace radiant::server {

pg_conn* connect_postgres(const std::string& uri) {
    // connect_timeout: a replica whose database is unreachable says so within seconds instead
    // of hanging its start or a request. statement_timeout: a statement stuck behind a lock must
    // not hold the store's mutex, and the requests waiting on it, for ever.
    const char* keys[] = {"dbname", "connect_timeout", "options", "application_name", nullptr};
    const char* values[] = {uri.c_str(), "5",
                            "-c statement_timeout=10000 -c client_min_messages=warning", "radiantd",
                            nullptr};
    PGconn* conn = PQconnectdbParams(keys, values, 1);
    if (PQstatus(conn) != CONNECTION_OK) {
        const std::string why = conn ? PQerrorMessage(conn) : "out of memory";
        PQfinish(conn);
        throw StoreError("job store: cannot connect to PostgreSQL: " + why, true);
    }
    return conn;
}

}  // namespace radiant::server
