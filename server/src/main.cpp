// radiantd: the Radiant job service (contract §4). A thin main over radiant_server: flags, the
// store, the queue, the listener, and a clean stop on SIGTERM/SIGINT.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>

#include "radiant/server/blocking_pool.h"
#include "radiant/server/config.h"
#include "radiant/server/handlers.h"
#include "radiant/server/job_queue.h"
#include "radiant/server/job_store.h"
#include "radiant/server/listener.h"
#include "radiant/server/metrics.h"
#include "radiant/server/router.h"

namespace {

namespace net = boost::asio;
using namespace radiant::server;

/// Pictures and CSV files of stored results are drawn one at a time beside the solves (each
/// takes well under a second); this many more may wait before requests get 503.
constexpr std::size_t kDrawingThreads = 1;
constexpr std::size_t kMostWaitingDrawings = 16;

int serve(const ServerConfig& config) {
    const auto listen = parse_listen(config.listen);
    if (!listen) {
        spdlog::error("--listen must be ADDR:PORT, not \"{}\"", config.listen);
        return 2;
    }
    JobStore store(config.data_dir);
    Metrics metrics;
    JobQueueOptions queue_options;
    queue_options.workers = config.workers;
    queue_options.queue_limit = config.queue_limit;
    queue_options.job_seconds = config.job_seconds;
    JobQueue jobs(store, metrics, queue_options);
    ServiceContext ctx{jobs, store, metrics, config.max_body_bytes};
    Router router(ctx);

    net::io_context ioc(static_cast<int>(config.io_threads));
    // After ioc, so that it stops first: its waiting tasks hold sessions of ioc's sockets.
    BlockingPool drawing(kDrawingThreads, kMostWaitingDrawings);
    ctx.blocking = &drawing;
    SessionLimits limits;
    limits.body_bytes = config.max_body_bytes;
    const net::ip::tcp::endpoint endpoint(net::ip::make_address(listen->host), listen->port);
    auto listener = std::make_shared<Listener>(ioc, endpoint, router, limits);
    // The first line of stdout names the bound port, so callers can use --listen ADDR:0.
    const auto bound = listener->local_endpoint();
    std::printf("listening on %s:%u\n", bound.address().to_string().c_str(),
                static_cast<unsigned>(bound.port()));
    std::fflush(stdout);
    spdlog::info("radiantd listening on {}:{}, data in {}, {} worker(s)",
                 bound.address().to_string(), bound.port(), config.data_dir, config.workers);
    listener->run();

    net::signal_set signals(ioc, SIGINT, SIGTERM);
    signals.async_wait([&](const boost::system::error_code& ec, int signal) {
        if (ec) return;
        spdlog::info("signal {}: stopping", signal);
        listener->stop();
        // Running solves stop and stay "running" in the store, so the next start runs them again.
        jobs.shutdown();
        ioc.stop();
    });

    std::vector<std::thread> threads;
    for (std::size_t i = 1; i < config.io_threads; ++i) threads.emplace_back([&ioc] { ioc.run(); });
    ioc.run();
    for (std::thread& t : threads) t.join();
    jobs.shutdown();
    spdlog::info("radiantd stopped");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // Logs go to stderr: stdout carries only the "listening on" line that scripts read.
    spdlog::set_default_logger(spdlog::stderr_color_mt("radiantd"));
    ServerConfig config;
    CLI::App app("radiantd: the Radiant radiosity job service", "radiantd");
    app.add_option("--listen", config.listen, "ADDR:PORT to listen on (port 0: any free port)")
        ->envname("RADIANT_LISTEN")
        ->capture_default_str();
    app.add_option("--data", config.data_dir, "directory of the job store")
        ->envname("RADIANT_DATA")
        ->capture_default_str();
    app.add_option("--workers", config.workers, "concurrent solves (each uses every core)")
        ->envname("RADIANT_WORKERS")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    app.add_option("--queue-limit", config.queue_limit, "waiting jobs before POST answers 429")
        ->envname("RADIANT_QUEUE_LIMIT")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    app.add_option("--max-body-bytes", config.max_body_bytes, "largest request body (413 above)")
        ->envname("RADIANT_MAX_BODY_BYTES")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 30))
        ->capture_default_str();
    app.add_option("--job-seconds", config.job_seconds, "wall-clock cap on each solve")
        ->envname("RADIANT_JOB_SECONDS")
        ->check(CLI::PositiveNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        return serve(config);
    } catch (const std::exception& e) {
        spdlog::error("radiantd: {}", e.what());
        return 1;
    }
}
