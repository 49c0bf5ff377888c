// Opening a libpq connection the way every part of the PostgreSQL store does.
#pragma once

#include <string>

struct pg_conn;

namespace radiant::server {

/// Connects to `uri` (a postgresql:// URI or key=value pairs) with the store's timeouts; throws
/// StoreError (unwritable) saying why when the server cannot be reached.
pg_conn* connect_postgres(const std::string& uri);

}  // namespace radiant::server
