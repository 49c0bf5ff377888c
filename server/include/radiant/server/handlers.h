// The endpoint handlers of contract §4: plain functions from a request to a response, so tests
// call them without sockets. They never solve: they parse, read or write the store and the
// queue, and return. Those that parse a scene run on ServiceContext::scene_pool, the rest on
// the I/O threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include <boost/asio/thread_pool.hpp>

#include "radiant/server/access_policy.h"
#include "radiant/server/http.h"
#include "radiant/server/job_queue.h"
#include "radiant/server/job_store.h"
#include "radiant/server/metrics.h"

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
};

using Query = std::map<std::string, std::string>;

namespace handlers {

Response submit_job(ServiceContext& ctx, const Request& request);
Response get_job(ServiceContext& ctx, const Request& request, const std::string& id);
/// `?include=mesh` adds the solved mesh (a running job's: its latest snapshot's).
Response get_result(ServiceContext& ctx, const Request& request, const std::string& id,
                    const Query& query);
/// The solved mesh and sensors as binary glTF (`radiant solve --gltf`); a running job's from its
/// latest snapshot, without sensors (they are computed at the end of a solve).
Response get_result_glb(ServiceContext& ctx, const Request& request, const std::string& id);
Response cancel_job(ServiceContext& ctx, const Request& request, const std::string& id);
Response list_jobs(ServiceContext& ctx, const Request& request, const Query& query);
Response healthz(ServiceContext& ctx, const Request& request);
Response metrics(ServiceContext& ctx, const Request& request);
Response not_found(const Request& request);

}  // namespace handlers
}  // namespace radiant::server
