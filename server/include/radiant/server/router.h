// Maps method + path to a handler. route() is a plain function of the request, so tests drive the
// whole API without sockets; only the event stream needs the session to keep writing, and
// deferred work (pictures, CSV) a thread that is not an I/O thread.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "radiant/server/handlers.h"
#include "radiant/server/http.h"
#include "radiant/server/static_files.h"

namespace radiant::server {

/// The session should answer with text/event-stream for this job instead of `response`.
struct EventStreamStart {
    std::string job_id;
    std::uint64_t last_event_id = 0;
};

struct RouteResult {
    Response response;
    std::optional<EventStreamStart> events;
    /// Set instead of `response` by handlers whose work is too slow for an I/O thread: the
    /// session runs it on the service's BlockingPool and sends what it returns. Never throws.
    DeferredResponse deferred = {};
};

/// "a=1&b=x%20y" → {a: 1, b: "x y"}; later duplicates win.
Query parse_query(std::string_view query);

class Router {
public:
    /// `web`: the viewer's files, served at every path outside /v1, /healthz and /metrics.
    explicit Router(ServiceContext& ctx, StaticFiles web = {}) : ctx_(ctx), web_(std::move(web)) {}

    /// Never throws: an exception from a handler becomes a 500 with a JSON error body. Requests
    /// the access policy refuses get their 401 or 403 before any handler runs.
    RouteResult route(const Request& request);

    /// Whether routing `request` may parse a scene (a submitted body, a stored scene), which
    /// takes time in proportion to its size: sessions run these on the scene pool.
    static bool parses_scene(const Request& request);

    ServiceContext& context() { return ctx_; }

private:
    RouteResult dispatch(const Request& request);
    ServiceContext& ctx_;
    const StaticFiles web_;
};

}  // namespace radiant::server
