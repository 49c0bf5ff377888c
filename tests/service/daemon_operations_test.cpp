// radiantd as an operator runs it, end to end: one daemon per data directory, private files,
// cancels and crashes that survive restarts, a full store, and running out of descriptors.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "daemon.h"
#include "daemon_fixture.h"
#include "service_scenes.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using boost::beast::http::verb;
using nlohmann::json;
using radiant::test::Daemon;
using radiant::test::http_call;

class DaemonOperationsTest : public radiant::test::StoreDaemonFixture {};
INSTANTIATE_TEST_SUITE_P(Stores, DaemonOperationsTest, radiant::test::both_stores(),
                         radiant::test::store_name);

/// CPU seconds (user + system) `pid` has used so far.
double cpu_seconds(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    // Fields after the command name (which may hold spaces) start after its closing ')'.
    std::istringstream fields(text.substr(text.rfind(')') + 2));
    std::string field;
    double ticks = 0;
    for (int i = 3; i <= 15 && fields >> field; ++i) {
        if (i == 14 || i == 15) ticks += std::stod(field);  // utime, stime
    }
    return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

/// Whether GET /healthz answers 200 within `timeout`; a daemon that never accepts gives false.
bool healthz_within(unsigned short port, std::chrono::seconds timeout) {
    namespace net = boost::asio;
    net::io_context ioc;
    net::ip::tcp::socket socket(ioc);
    boost::system::error_code ec;
    socket.connect({net::ip::make_address("127.0.0.1"), port}, ec);
    if (ec) return false;
    const timeval tv{static_cast<time_t>(timeout.count()), 0};
    setsockopt(socket.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    const std::string request = "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
    net::write(socket, net::buffer(request), ec);
    char answer[16] = {};
    const ssize_t n = ::recv(socket.native_handle(), answer, sizeof answer - 1, MSG_WAITALL);
    return n > 0 && std::string(answer).starts_with("HTTP/1.1 200");
}

TEST_P(DaemonOperationsTest, ASecondDaemonOnTheSameDataExitsWithAMessage) {
    if (postgresql()) GTEST_SKIP() << "radiantd share a PostgreSQL store by design (ReplicasTest)";
    Daemon first(data(), flags(), log());
    const fs::path second_log = dir_ / "second.log";
    try {
        Daemon second(data(), flags(), second_log);
        FAIL() << "a second radiantd started on the same --data";
    } catch (const std::runtime_error& e) {
        // It printed no port: it stopped before listening, with a failing exit code.
        EXPECT_NE(std::string(e.what()).find("exit code 1"), std::string::npos) << e.what();
    }
    const std::string said = radiant::test::read_text(second_log);
    EXPECT_NE(said.find("in use by another radiantd (pid " + std::to_string(first.pid())),
              std::string::npos)
        << said;
    EXPECT_EQ(http_call(first.port(), verb::get, "/healthz").status, 200u);
}

TEST_P(DaemonOperationsTest, DataIsPrivate) {
    if (postgresql()) GTEST_SKIP() << "a PostgreSQL store keeps no job under --data";
    Daemon d(data(), flags(), log());
    wait_for(d, post(d, radiant::test::tiny_room()), "done");
    struct stat st {};
    ASSERT_EQ(::stat(data().c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700u);
    for (const auto& entry : fs::directory_iterator(data())) {
        ASSERT_EQ(::stat(entry.path().c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 0777, 0600u) << entry.path();
    }
}

TEST_P(DaemonOperationsTest, AnAnsweredCancelSurvivesAKillRightAfter) {
    std::string id;
    {
        Daemon d(data(), flags(), log());
        id = post(d, radiant::test::slow_room());
        ASSERT_EQ(wait_for(d, id, "running")["status"], "running");
        ASSERT_EQ(http_call(d.port(), verb::delete_, "/v1/jobs/" + id).status, 202u);
        d.stop(SIGKILL);
    }
    Daemon d(data(), flags(), log());
    EXPECT_EQ(wait_for(d, id, "cancelled", 5)["status"], "cancelled");
}

TEST_P(DaemonOperationsTest, AJobThatKilledItsDaemonTwiceFails) {
    std::string id;
    json started;  // when the last attempt started
    for (int attempt = 0; attempt < 2; ++attempt) {
        // As the kernel's OOM killer would: SIGKILL while the job runs. On a shared store the
        // job is "running" under the dead daemon's lease until it expires: this daemon runs it
        // once it started it again.
        Daemon d(data(), flags(), log());
        if (id.empty()) id = post(d, radiant::test::slow_room());
        const json j = wait_for_new_run(d, id, started);
        ASSERT_EQ(j["status"], "running");
        ASSERT_NE(j["started"], started) << "attempt " << attempt << " did not start";
        started = j["started"];
        d.stop(SIGKILL);
    }
    Daemon d(data(), flags(), log());
    const json j = wait_for(d, id, "failed", 10);
    EXPECT_EQ(j["status"], "failed");
    EXPECT_NE(j.value("error", "").find("died"), std::string::npos) << j.dump();
}

TEST_P(DaemonOperationsTest, AFullStoreFailsJobsVisiblyAndReadinessSaysSo) {
    if (postgresql()) GTEST_SKIP() << "--max-store-mb caps the SQLite store only";
    Daemon d(data(), flags({"--max-store-mb", "1", "--queue-limit", "1000"}), log());
    const std::string running = post(d, radiant::test::slow_room(2));
    ASSERT_EQ(wait_for(d, running, "running")["status"], "running");
    // Scenes padded with whitespace fill the store until it refuses them, smaller and smaller
    // ones, so that no result fits either.
    for (const std::size_t padding : {200u << 10, 20u << 10, 2u << 10}) {
        const std::string padded = radiant::test::tiny_room() + std::string(padding, ' ');
        unsigned refused = 0;
        for (int i = 0; i < 200 && refused == 0; ++i) {
            const auto r = http_call(d.port(), verb::post, "/v1/jobs", padded);
            if (r.status == 503u) {
                refused = r.status;
                EXPECT_EQ(json::parse(r.body)["error"]["code"], "store_unwritable") << r.body;
            } else {
                ASSERT_EQ(r.status, 202u) << r.body;
            }
        }
        ASSERT_EQ(refused, 503u) << padding;
    }
    // The running job's result has no room: it fails, saying why, instead of running forever.
    const json j = wait_for(d, running, "failed", 20);
    EXPECT_EQ(j["status"], "failed") << j.dump();
    EXPECT_NE(j.value("error", "").find("store"), std::string::npos) << j.dump();
    // Not ready, saying why; alive all the same (a restart would not make room).
    const auto ready = http_call(d.port(), verb::get, "/readyz");
    EXPECT_EQ(ready.status, 503u);
    EXPECT_EQ(json::parse(ready.body)["error"]["code"], "store_unwritable") << ready.body;
    EXPECT_NE(json::parse(ready.body)["error"].value("message", "").find("full"), std::string::npos)
        << ready.body;
    // Alive, and its body says what the store's last write found.
    const auto alive = http_call(d.port(), verb::get, "/healthz");
    EXPECT_EQ(alive.status, 200u);
    EXPECT_EQ(json::parse(alive.body)["store"], "unwritable") << alive.body;
    EXPECT_NE(json::parse(alive.body).value("store_reason", "").find("full"), std::string::npos)
        << alive.body;
}

TEST_P(DaemonOperationsTest, OutOfDescriptorsAcceptPausesAndRecovers) {
    Daemon d(data(), flags(), log(), 40);
    // Connections beyond the descriptor limit wait in the backlog; accept keeps failing.
    namespace net = boost::asio;
    net::io_context ioc;
    std::vector<std::unique_ptr<net::ip::tcp::socket>> clients;
    for (int i = 0; i < 60; ++i) {
        clients.push_back(std::make_unique<net::ip::tcp::socket>(ioc));
        clients.back()->connect({net::ip::make_address("127.0.0.1"), d.port()});
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const double cpu_before = cpu_seconds(d.pid());
    const auto log_before = fs::file_size(log());
    std::this_thread::sleep_for(std::chrono::seconds(2));
    EXPECT_LT(cpu_seconds(d.pid()) - cpu_before, 0.3) << "accept spins";
    EXPECT_LT(fs::file_size(log()) - log_before, 1000u) << "the log floods";
    EXPECT_NE(radiant::test::read_text(log()).find("pausing accepts"), std::string::npos);
    clients.clear();
    // Descriptors come back as the daemon closes those connections: it serves again.
    bool healthy = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!healthy && std::chrono::steady_clock::now() < deadline) {
        healthy = healthz_within(d.port(), std::chrono::seconds(1));
    }
    EXPECT_TRUE(healthy);
}

}  // namespace
