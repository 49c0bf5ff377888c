// radiant-load: starts a few solves on a radiantd, then polls GET /v1/jobs/{id} at a fixed rate
// from several keep-alive connections and reports throughput, latency percentiles and errors.
// Bounded on purpose: loopback addresses only, a capped duration, and the solves it started are
// cancelled at the end, so it cannot be pointed at someone else's server or left running.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using Clock = std::chrono::steady_clock;

constexpr double kMaxSeconds = 600;  // the longest run the tool agrees to
constexpr double kMaxRate = 5000;    // requests per second

struct Options {
    std::string server = "http://127.0.0.1:8080";
    std::string scene;
    double rate = 200;
    double seconds = 10;
    int solves = 2;
    int connections = 4;
    std::optional<double> tolerance;
    std::optional<double> max_p99_ms;
};

/// "http://HOST:PORT" → a loopback endpoint; nothing for anything else.
std::optional<tcp::endpoint> loopback_endpoint(const std::string& url) {
    const std::string prefix = "http://";
    if (url.rfind(prefix, 0) != 0) return std::nullopt;
    std::string rest = url.substr(prefix.size());
    if (!rest.empty() && rest.back() == '/') rest.pop_back();
    const std::size_t colon = rest.rfind(':');
    if (colon == std::string::npos) return std::nullopt;
    std::string host = rest.substr(0, colon);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
        host = host.substr(1, host.size() - 2);
    }
    if (host == "localhost") host = "127.0.0.1";
    boost::system::error_code ec;
    const net::ip::address address = net::ip::make_address(host, ec);
    if (ec || !address.is_loopback()) return std::nullopt;
    unsigned port = 0;
    try {
        port = static_cast<unsigned>(std::stoul(rest.substr(colon + 1)));
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (port == 0 || port > 65535) return std::nullopt;
    return tcp::endpoint(address, static_cast<unsigned short>(port));
}

/// One keep-alive connection; reconnects after a failure.
class Connection {
public:
    explicit Connection(tcp::endpoint endpoint) : endpoint_(endpoint), socket_(ioc_) {}

    /// The status, or 0 when the request failed on the wire.
    unsigned request(http::verb method, const std::string& target, const std::string& body,
                     std::string* answer = nullptr) {
        try {
            if (!socket_.is_open()) socket_.connect(endpoint_);
            http::request<http::string_body> req{method, target, 11};
            req.set(http::field::host, "127.0.0.1");
            req.keep_alive(true);
            if (!body.empty()) req.set(http::field::content_type, "application/json");
            req.body() = body;
            req.prepare_payload();
            http::write(socket_, req);
            http::response<http::string_body> res;
            http::read(socket_, buffer_, res);
            if (!res.keep_alive()) close();
            if (answer) *answer = std::move(res.body());
            return res.result_int();
        } catch (const std::exception&) {
            close();
            return 0;
        }
    }

private:
    void close() {
        boost::system::error_code ignored;
        socket_.close(ignored);
        buffer_.clear();
    }
    tcp::endpoint endpoint_;
    net::io_context ioc_;
    tcp::socket socket_;
    beast::flat_buffer buffer_;
};

double percentile(std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0;
    const auto k = static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) + 0.5);
    return sorted[std::min(k, sorted.size() - 1)];
}

int run(const Options& o, const tcp::endpoint& endpoint) {
    std::ifstream in(o.scene, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "radiant-load: cannot read %s\n", o.scene.c_str());
        return 2;
    }
    nlohmann::json scene = nlohmann::json::parse(std::istreambuf_iterator<char>(in),
                                                 std::istreambuf_iterator<char>(), nullptr, false);
    if (!scene.is_object()) {
        std::fprintf(stderr, "radiant-load: %s is not a JSON object\n", o.scene.c_str());
        return 2;
    }
    // The solves stop by themselves shortly after the polling does.
    scene["settings"]["max_seconds"] = o.seconds + 5;
    if (o.tolerance) scene["settings"]["tolerance"] = *o.tolerance;

    Connection control(endpoint);
    std::vector<std::string> ids;
    for (int i = 0; i < o.solves; ++i) {
        std::string answer;
        const unsigned status =
            control.request(http::verb::post, "/v1/jobs", scene.dump(), &answer);
        const auto reply = nlohmann::json::parse(answer, nullptr, false);
        if (status != 202 || !reply.contains("id")) {
            std::fprintf(stderr, "radiant-load: POST /v1/jobs answered %u: %s\n", status,
                         answer.c_str());
            return 1;
        }
        ids.push_back(reply["id"]);
    }

    std::mutex mutex;
    std::vector<double> latencies_ms;
    std::atomic<std::uint64_t> errors{0};
    const auto start = Clock::now() + std::chrono::milliseconds(100);
    const auto total = static_cast<std::uint64_t>(o.rate * o.seconds);
    const auto period = std::chrono::duration<double>(1.0 / o.rate);
    std::vector<std::thread> pollers;
    for (int c = 0; c < o.connections; ++c) {
        pollers.emplace_back([&, c] {
            Connection connection(endpoint);
            std::vector<double> mine;
            // Open loop: request k is due at start + k / rate whatever happened before, and its
            // latency counts from then, so a stalled server cannot hide its queueing delay.
            for (std::uint64_t k = static_cast<std::uint64_t>(c); k < total;
                 k += static_cast<std::uint64_t>(o.connections)) {
                const auto due = start + std::chrono::duration_cast<Clock::duration>(
                                             period * static_cast<double>(k));
                std::this_thread::sleep_until(due);
                const std::string& id = ids[k % ids.size()];
                if (connection.request(http::verb::get, "/v1/jobs/" + id, "") != 200) ++errors;
                mine.push_back(
                    std::chrono::duration<double, std::milli>(Clock::now() - due).count());
            }
            const std::lock_guard lock(mutex);
            latencies_ms.insert(latencies_ms.end(), mine.begin(), mine.end());
        });
    }
    for (std::thread& t : pollers) t.join();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    for (const std::string& id : ids) control.request(http::verb::delete_, "/v1/jobs/" + id, "");

    std::sort(latencies_ms.begin(), latencies_ms.end());
    const double p50 = percentile(latencies_ms, 0.50);
    const double p99 = percentile(latencies_ms, 0.99);
    std::printf(
        "requests %zu  errors %llu  throughput %.1f req/s  p50 %.2f ms  p99 %.2f ms  max %.2f ms"
        "  (%d solves, %d connections, target %.0f req/s)\n",
        latencies_ms.size(), static_cast<unsigned long long>(errors.load()),
        static_cast<double>(latencies_ms.size()) / elapsed, p50, p99,
        latencies_ms.empty() ? 0.0 : latencies_ms.back(), o.solves, o.connections, o.rate);
    if (errors > 0) return 1;
    if (o.max_p99_ms && p99 > *o.max_p99_ms) {
        std::fprintf(stderr, "radiant-load: p99 %.2f ms is over %.2f ms\n", p99, *o.max_p99_ms);
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app("radiant-load: status-poll latency of a local radiantd while solves run",
                 "radiant-load");
    app.add_option("--server", o.server, "http://HOST:PORT of radiantd (loopback only)")
        ->envname("RADIANT_SERVER")
        ->capture_default_str();
    app.add_option("--scene", o.scene, "scene to solve while polling")->required();
    app.add_option("--rate", o.rate, "status polls per second")
        ->check(CLI::Range(1.0, kMaxRate))
        ->capture_default_str();
    app.add_option("--seconds", o.seconds, "how long to poll")
        ->check(CLI::Range(0.1, kMaxSeconds))
        ->capture_default_str();
    app.add_option("--solves", o.solves, "solves to start first")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    app.add_option("--connections", o.connections, "keep-alive connections polling in parallel")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    app.add_option("--tolerance", o.tolerance, "override the scene's tolerance (longer solves)")
        ->check(CLI::PositiveNumber);
    app.add_option("--max-p99-ms", o.max_p99_ms, "exit 1 when the p99 latency is above this")
        ->check(CLI::PositiveNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    const auto endpoint = loopback_endpoint(o.server);
    if (!endpoint) {
        std::fprintf(stderr,
                     "radiant-load: --server must be http://<loopback address>:PORT, not %s\n",
                     o.server.c_str());
        return 2;
    }
    return run(o, *endpoint);
}
