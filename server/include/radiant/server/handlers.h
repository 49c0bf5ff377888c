// The endpoint handlers of contract §4: plain functions from a request to a response, so tests
// call them without sockets. They never solve: they parse, read or write the store and the
// queue, and return. Those that parse a scene run on ServiceContext::scene_pool, the rest on
// the I/O threads. Those that draw or convert a stored result return their work instead
// (DeferredResponse), for the session to run on a BlockingPool.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <boost/asio/thread_pool.hpp>

#include "radiant/server/access_policy.h"
#include "radiant/server/blocking_pool.h"
#include "radiant/server/http.h"
#include "radiant/server/job_queue.h"
#include "radiant/server/job_store.h"
#include "radiant/server/metrics.h"
#include "radiant/server/stored_solutions.h"

namespace radiant::server {

/// What the handlers share; owned by main (or a test).
struct ServiceContext {
    JobQueue& jobs;
    JobStore& store;
    Metrics& metrics;
    std::size_t max_body_bytes;
    AccessPolicy access{};                  ///< token, Host and Origin checks
    std::string listen_host = "127.0.0.1";  ///< the address listened on: a Host answered to
    /// Runs the requests that parse a scene (Router::parses_scene), so that a large or hostile
    /// body never holds an I/O thread; none: sessions run them inline.
    boost::asio::thread_pool* scene_pool = nullptr;
    /// Light scenes' solutions, read once per finished job.
    std::shared_ptr<StoredSolutions> solutions = std::make_shared<StoredSolutions>();
    /// Where deferred work runs (main's pool); null: the caller runs it (tests without sockets).
    BlockingPool* blocking = nullptr;
};

using Query = std::map<std::string, std::string>;

/// A response whose making must not hold up an I/O thread (see RouteResult::deferred).
using DeferredResponse = std::function<Response()>;

namespace handlers {

Response submit_job(ServiceContext& ctx, const Request& request);
Response get_job(ServiceContext& ctx, const Request& request, const std::string& id);
/// `?include=mesh` adds the solved mesh (a running job's: its latest snapshot's).
Response get_result(ServiceContext& ctx, const Request& request, const std::string& id,
                    const Query& query);
/// The solved mesh and sensors as binary glTF (`radiant solve --gltf`); a running job's from its
/// latest snapshot, without sensors (they are computed at the end of a solve).
Response get_result_glb(ServiceContext& ctx, const Request& request, const std::string& id);
/// Files made from a finished job's stored result, without solving again; their work is
/// deferred. `sensors.csv`: every sensor point (radiant solve --csv).
DeferredResponse get_sensors_csv(ServiceContext& ctx, const Request& request,
                                 const std::string& id);
/// `plan.png?sensors=NAME&size=PX&max_lux=LX`: a sensor set's false-colour map (radiant plan).
DeferredResponse get_plan_png(ServiceContext& ctx, const Request& request, const std::string& id,
                              const Query& query);
/// `view.png?eye=X,Y,Z&target=X,Y,Z&up=…&fov=DEG&width=PX&height=PX&falsecolor=1&max_lux=LX&
/// exposure=CD_M2` (metres): a perspective picture of the solved mesh (radiant render).
DeferredResponse get_view_png(ServiceContext& ctx, const Request& request, const std::string& id,
                              const Query& query);
/// proto/openapi.yaml, as the daemon was built with it.
Response openapi(const Request& request);
Response cancel_job(ServiceContext& ctx, const Request& request, const std::string& id);
/// A light scene ({"name", "dimming"}) from a finished job's group contributions, without
/// solving again (light_scene_handler.cpp): 409 while the job runs or when its scene has no
/// groups, 400 with pointers for an unknown group or a dimming outside [0, 1].
Response post_light_scene(ServiceContext& ctx, const Request& request, const std::string& id);
Response list_jobs(ServiceContext& ctx, const Request& request, const Query& query);
/// Liveness: 200 whenever the process answers, whatever the store and while it drains; the
/// body carries the store's last known state (`store`: writable or unwritable, and why).
Response healthz(ServiceContext& ctx, const Request& request);
/// Readiness for a load balancer: 200 while the store answers and takes writes, else 503 with
/// an error (`shutting_down`, `store_unwritable` and the store's reason).
Response readyz(ServiceContext& ctx, const Request& request);
Response metrics(ServiceContext& ctx, const Request& request);
Response not_found(const Request& request);

}  // namespace handlers
}  // namespace radiant::server
