// radiantd: the Radiant job service (contract §4). A thin main over radiant_server: flags, the
// store, the queue, the listener, and a clean stop on SIGTERM/SIGINT.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/thread_pool.hpp>

#include "radiant/server/blocking_pool.h"
#include "radiant/server/config.h"
#include "radiant/server/handlers.h"
#include "radiant/server/job_queue.h"
#include "radiant/server/listener.h"
#include "radiant/server/metrics.h"
#include "radiant/server/postgres_job_store.h"
#include "radiant/server/router.h"
#include "radiant/server/sqlite_job_store.h"
#include "radiant/server/static_files.h"
#include "radiant/solve.h"

namespace {

namespace net = boost::asio;
namespace fs = std::filesystem;
using namespace radiant::server;

/// Pictures and CSV files of stored results are drawn one at a time beside the solves (each
/// takes well under a second); this many more may wait before requests get 503.
constexpr std::size_t kDrawingThreads = 1;
constexpr std::size_t kMostWaitingDrawings = 16;

std::size_t mebibytes(double mb) { return static_cast<std::size_t>(mb * 1024 * 1024); }

/// --store URI's PostgreSQL, or SQLite under --data. The URI is never logged: it may hold a
/// password.
std::unique_ptr<JobStore> open_store(const ServerConfig& config) {
    if (!config.store_uri.empty()) return std::make_unique<PostgresJobStore>(config.store_uri);
    JobStoreOptions options;
    options.max_bytes = mebibytes(config.max_store_mb);
    return std::make_unique<SqliteJobStore>(config.data_dir, options);
}

bool is_postgresql_uri(const std::string& uri) {
    return uri.starts_with("postgresql://") || uri.starts_with("postgres://");
}

int serve(const ServerConfig& config) {
    const auto listen = parse_listen(config.listen);
    if (!listen) {
        spdlog::error("--listen must be ADDR:PORT, not \"{}\"", config.listen);
        return 2;
    }
    std::string token;
    if (!config.token_file.empty()) {
        try {
            token = read_token_file(config.token_file);
        } catch (const std::exception& e) {
            spdlog::error("--token-file: {}", e.what());
            return 2;
        }
    }
    if (!config.store_uri.empty() && !is_postgresql_uri(config.store_uri)) {
        spdlog::error("--store must be a postgresql:// URI");
        return 2;
    }
    const std::unique_ptr<JobStore> owned_store = open_store(config);
    JobStore& store = *owned_store;
    Metrics metrics(config.replica);
    JobQueueOptions queue_options;
    queue_options.workers = config.workers;
    queue_options.queue_limit = config.queue_limit;
    queue_options.replica = config.replica;
    queue_options.lease = std::chrono::milliseconds(static_cast<long>(config.lease_seconds * 1000));
    queue_options.job_seconds = config.job_seconds;
    queue_options.job_memory_bytes = config.job_memory_mb > 0
                                         ? mebibytes(config.job_memory_mb)
                                         : radiant::physical_memory_bytes() / (2 * config.workers);
    JobQueue jobs(store, metrics, queue_options);
    ServiceContext ctx{jobs, store, metrics, config.max_body_bytes};
    ctx.access.allowed_hosts = config.allowed_hosts;
    ctx.access.cors_origins = config.cors_origins;
    ctx.access.token = token;
    ctx.listen_host = listen->host;
    StaticFiles web(config.web_root.empty() ? default_web_root(fs::read_symlink("/proc/self/exe"))
                                            : fs::path(config.web_root));
    if (web.installed()) {
        spdlog::info("web viewer from {}", web.root().string());
    } else {
        spdlog::warn("no web viewer in {} (no index.html): GET / answers 404", web.root().string());
    }
    Router router(ctx, std::move(web));

    net::io_context ioc(static_cast<int>(config.io_threads));
    // After the io_context, so that they are joined and destroyed first: their tasks hold
    // sessions.
    net::thread_pool scene_pool(config.scene_threads);
    ctx.scene_pool = &scene_pool;
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
    spdlog::info(
        "radiantd listening on {}:{}, {}, {} worker(s), each job up to {:.0f} s "
        "and {} MiB{}",
        bound.address().to_string(), bound.port(),
        config.store_uri.empty() ? "data in " + config.data_dir : std::string("PostgreSQL store"),
        config.workers, config.job_seconds, queue_options.job_memory_bytes >> 20,
        ctx.access.token.empty() ? "" : ", bearer token required");
    listener->run();

    // A stop drains: no new job is accepted or started, running solves go on for up to
    // --drain-seconds while requests are still answered, then go back to the queue (another
    // replica, or the next start, runs them). A second signal hands them back at once.
    net::signal_set signals(ioc, SIGINT, SIGTERM);
    std::thread drainer;
    signals.async_wait([&](const boost::system::error_code& ec, int signal) {
        if (ec) return;
        spdlog::info("signal {}: draining for up to {} s (a second signal stops at once)", signal,
                     config.drain_seconds);
        signals.async_wait([&](const boost::system::error_code& again, int) {
            if (again) return;
            spdlog::info("second signal: running jobs go back to the queue now");
            jobs.shutdown();
        });
        drainer = std::thread([&] {
            jobs.drain(std::chrono::milliseconds(static_cast<long>(config.drain_seconds * 1000)));
            net::post(ioc, [&] {
                listener->stop();
                ioc.stop();
            });
        });
    });

    std::vector<std::thread> threads;
    for (std::size_t i = 1; i < config.io_threads; ++i) threads.emplace_back([&ioc] { ioc.run(); });
    ioc.run();
    for (std::thread& t : threads) t.join();
    if (drainer.joinable()) drainer.join();
    // Parses still queued finish; the queue is shut, so they answer 503 to nobody.
    scene_pool.join();
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
    app.add_option("--store", config.store_uri,
                   "postgresql://… : a job store shared by several radiantd (instead of --data)")
        ->envname("RADIANT_STORE");
    app.add_option("--replica", config.replica,
                   "this radiantd's name in a shared store's job leases (default: host:pid)")
        ->envname("RADIANT_REPLICA");
    app.add_option("--lease-seconds", config.lease_seconds,
                   "how long a shared store's job waits for a replica that stopped renewing its "
                   "lease (died) before another one takes it")
        ->envname("RADIANT_LEASE_SECONDS")
        ->check(CLI::Range(2.0, 3600.0))
        ->capture_default_str();
    app.add_option("--drain-seconds", config.drain_seconds,
                   "after SIGTERM, how long running solves may go on before they go back to the "
                   "queue (0: at once)")
        ->envname("RADIANT_DRAIN_SECONDS")
        ->check(CLI::Range(0.0, 3600.0))
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
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--job-memory-mb", config.job_memory_mb,
                   "memory budget of each solve in MiB (default: half the physical memory "
                   "divided among the workers)")
        ->envname("RADIANT_JOB_MEMORY_MB")
        ->check(CLI::PositiveNumber);
    app.add_option("--max-store-mb", config.max_store_mb,
                   "size cap of the job store in MiB (default: the disk's)")
        ->envname("RADIANT_MAX_STORE_MB")
        ->check(CLI::PositiveNumber);
    app.add_option("--token-file", config.token_file,
                   "file holding a bearer token required on every route but /healthz and /readyz")
        ->envname("RADIANT_TOKEN_FILE");
    app.add_option("--allow-host", config.allowed_hosts,
                   "a Host name answered besides localhost and the listen address (repeatable; "
                   "* for any)")
        ->envname("RADIANT_ALLOW_HOST")
        ->delimiter(',');
    app.add_option("--cors-origin", config.cors_origins,
                   "a browser origin allowed cross-origin access, e.g. https://app.example.com "
                   "(repeatable)")
        ->envname("RADIANT_CORS_ORIGIN")
        ->delimiter(',');
    app.add_option("--web-root", config.web_root,
                   "the web viewer's files, served at / (default: ../share/radiant/web from the "
                   "binary)")
        ->envname("RADIANT_WEB_ROOT");
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
