// A test of radiantd end to end: a fresh directory per test for the daemon's data and log (the
// log printed when the test fails), and the HTTP calls the tests make of a job.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon.h"
#include "store_under_test.h"
#include "test_files.h"

namespace radiant::test {

class DaemonFixture : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ =
            std::filesystem::temp_directory_path() /
            ("radiantd_test_" + std::to_string(getpid()) + "_" + radiant::test::test_file_name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override {
        if (HasFailure()) std::cerr << read_text(log()) << '\n';
        std::filesystem::remove_all(dir_);
    }
    std::filesystem::path data() const { return dir_ / "data"; }
    std::filesystem::path log() const { return dir_ / "radiantd.log"; }

    /// POSTs `scene` as a job; its id (empty, and a failure, if it was not accepted).
    static std::string post(const Daemon& d, const std::string& scene) {
        const auto r = http_call(d.port(), boost::beast::http::verb::post, "/v1/jobs", scene);
        EXPECT_EQ(r.status, 202u) << r.body;
        return r.status == 202u ? nlohmann::json::parse(r.body)["id"].get<std::string>()
                                : std::string();
    }
    static nlohmann::json job(const Daemon& d, const std::string& id) {
        return nlohmann::json::parse(
            http_call(d.port(), boost::beast::http::verb::get, "/v1/jobs/" + id).body);
    }
    /// The job once its status is `want`, or as it is after `seconds`.
    static nlohmann::json wait_for(const Daemon& d, const std::string& id, const std::string& want,
                                   double seconds = 20) {
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        nlohmann::json j;
        do {
            j = job(d, id);
            if (j["status"] == want) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        } while (std::chrono::steady_clock::now() < deadline);
        return j;
    }
    /// The job once it is running in a run that started after `started` (a job's "started"
    /// field; null: any run), or as it is after `seconds`. A daemon killed on a shared store
    /// leaves its job "running" until the lease ends: only a new start shows it runs again.
    static nlohmann::json wait_for_new_run(const Daemon& d, const std::string& id,
                                           const nlohmann::json& started, double seconds = 20) {
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        nlohmann::json j;
        do {
            j = job(d, id);
            if (j["status"] == "running" && j["started"] != started) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        } while (std::chrono::steady_clock::now() < deadline);
        return j;
    }

    std::filesystem::path dir_;
};

/// A DaemonFixture whose tests run on each store: instantiate the suite with
/// INSTANTIATE_TEST_SUITE_P(Stores, Suite, both_stores(), store_name) and start daemons with
/// flags(), which names the test's store.
class StoreDaemonFixture : public DaemonFixture, public ::testing::WithParamInterface<std::string> {
protected:
    void SetUp() override {
        const std::string skip = StoreUnderTest::skip_reason(GetParam());
        if (!skip.empty()) GTEST_SKIP() << skip;
        DaemonFixture::SetUp();
        store_.emplace(GetParam());
    }
    /// `args` and the flags that start radiantd on this test's store.
    std::vector<std::string> flags(std::vector<std::string> args = {}) const {
        return store_->daemon_flags(std::move(args));
    }
    bool postgresql() const { return store_->postgresql(); }

    std::optional<StoreUnderTest> store_;
};

}  // namespace radiant::test
