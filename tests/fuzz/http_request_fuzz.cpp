// libFuzzer target: a raw HTTP request as radiantd's sessions read it (Beast's parser with the
// session's limits), then routed: access checks, the router and every handler, over a real job
// store and queue, without sockets.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <boost/asio/buffer.hpp>

#include "radiant/proto/scene_json.h"
#include "radiant/server/router.h"
#include "radiant/server/session.h"
#include "radiant/server/sqlite_job_store.h"
#include "radiant/solve.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant::server;

/// A store in its own directory, a queue and a router. Accepted jobs are solved briefly on one
/// thread (a fuzzer gets one core), and the whole service is replaced every thousand inputs so
/// that the store stays small: LeakSanitizer scans the heap after every input that keeps memory
/// (a stored job), and with ten thousand inputs between restarts those scans held half the time.
class Service {
public:
    explicit Service(const fs::path& dir)
        : dir_(dir),
          store_(dir),
          jobs_(store_, metrics_, queue_options()),
          ctx_{jobs_, store_, metrics_, SessionLimits{}.body_bytes,
               AccessPolicy{{}, {}, {"https://app.example.com"}}},
          router_(ctx_) {}
    ~Service() { jobs_.shutdown(); }

    RouteResult route(const Request& request) { return router_.route(request); }

private:
    static JobQueueOptions queue_options() {
        JobQueueOptions options;
        options.workers = 1;
        options.queue_limit = 4;
        options.job_seconds = 0.05;
        options.job_memory_bytes = std::size_t{256} << 20;
        options.solve_threads = 1;
        return options;
    }
    /// Empty when the service starts, removed when it ends (declared first: destroyed last).
    struct ScratchDirectory {
        explicit ScratchDirectory(const fs::path& path) : path(path) { fs::remove_all(path); }
        ~ScratchDirectory() { fs::remove_all(path); }
        fs::path path;
    } dir_;
    Metrics metrics_;
    SqliteJobStore store_;
    JobQueue jobs_;
    ServiceContext ctx_;
    Router router_;
};

/// Bytes → a request, as Session::do_read parses them; none when Beast refuses them.
std::optional<Request> parse_request(const std::uint8_t* data, std::size_t size) {
    http::request_parser<http::string_body> parser;
    const SessionLimits limits;
    parser.header_limit(static_cast<std::uint32_t>(limits.header_bytes));
    parser.body_limit(limits.body_bytes);
    boost::beast::error_code ec;
    std::size_t used = 0;
    while (!ec && !parser.is_done() && used < size) {
        const std::size_t n = parser.put(boost::asio::buffer(data + used, size - used), ec);
        if (n == 0) break;
        used += n;
    }
    // The end of the stream completes a body without a length (Beast asserts that some came).
    if (!ec && !parser.is_done() && parser.got_some()) parser.put_eof(ec);
    if (ec || !parser.is_done()) return std::nullopt;
    return parser.release();
}

/// libFuzzer ends a run with exit(), which destroys statics in the reverse order of their making
/// while the service's worker may still be solving: what a solve makes on first use (the log's
/// registry, OpenMesh's log streams, which every solve calls) must be made before the service,
/// so that it outlives the service's destructor, which joins the worker. A small room solved
/// once by every method makes it.
bool make_what_solves_make_on_first_use() {
    spdlog::set_level(spdlog::level::off);
    const radiant::proto::ParseOutcome room = radiant::proto::parse_scene(R"({
        "format": "radiant-scene/1",
        "materials": {"wall": {"reflectance": 0.5}},
        "surfaces": [{"name": "room", "material": "wall",
                      "box": {"min": [0, 0, 0], "max": [2, 2, 2], "facing": "in"}}],
        "luminaires": [{"name": "bulb", "position": [1, 1, 1.5], "flux": 100,
                        "distribution": "isotropic"}],
        "sensors": [{"name": "plane", "points": [[1, 1, 0.5]], "normal": [0, 0, 1]}]})");
    if (!room.ok()) throw std::logic_error("the warm-up room: " + room.problems.front().message);
    for (const std::string& method : radiant::solver_names()) {
        radiant::SolveOptions options = radiant::options_from(room.scene->settings);
        options.method = method;
        options.tolerance = 0.3;
        options.threads = 1;
        radiant::solve(*room.scene, options);
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const fs::path dir =
        fs::temp_directory_path() / ("radiant_http_fuzz_" + std::to_string(getpid()));
    [[maybe_unused]] static const bool made = make_what_solves_make_on_first_use();
    static std::unique_ptr<Service> service;
    static std::size_t runs = 0;
    if (runs++ % 1000 == 0) {
        service.reset();
        service = std::make_unique<Service>(dir);
    }
    if (std::optional<Request> request = parse_request(data, size)) service->route(*request);
    return 0;
}
