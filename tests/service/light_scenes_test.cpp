// POST /v1/jobs/{id}/scenes end to end: a light scene from a finished job's stored solution,
// equal to the one the solve computed itself, and fast: 10⁴ sensor points in under 50 ms.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon.h"
#include "service_scenes.h"
#include "store_under_test.h"

namespace {

namespace fs = std::filesystem;
using boost::beast::http::verb;
using nlohmann::json;
using radiant::test::Daemon;
using radiant::test::http_call;

using LightScenesService = radiant::test::StoreTest;
INSTANTIATE_TEST_SUITE_P(Stores, LightScenesService, radiant::test::both_stores(),
                         radiant::test::store_name);

TEST_P(LightScenesService, EvaluatesTenThousandPointsFromTheStoredSolveInUnderFiftyMs) {
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_light_scenes_test_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    Daemon d(dir / "data", flags(), dir / "radiantd.log");

    const auto posted =
        http_call(d.port(), verb::post, "/v1/jobs", radiant::test::grouped_room(100));
    ASSERT_EQ(posted.status, 202u) << posted.body;
    const std::string id = json::parse(posted.body)["id"];
    const std::string job = "/v1/jobs/" + id;
    // Before the job has finished there is no solution to evaluate.
    const auto early = http_call(d.port(), verb::post, job + "/scenes",
                                 R"({"name": "early", "dimming": {"panel": 1}})");
    EXPECT_TRUE(early.status == 409u || early.status == 200u) << early.body;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(10);
    while (json::parse(http_call(d.port(), verb::get, job).body)["status"] != "done" &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    const json result = json::parse(http_call(d.port(), verb::get, job + "/result").body);
    ASSERT_EQ(result["status"], "converged") << result.dump().substr(0, 500);
    ASSERT_EQ(result["sensors"][0]["illuminance"].size(), 10000u);

    // The light scene the solve computed, evaluated again from the store: the first request
    // reads the stored result, the later ones reuse what it read.
    const auto cold_start = std::chrono::steady_clock::now();
    const auto again = http_call(d.port(), verb::post, job + "/scenes",
                                 R"({"name": "panel only", "dimming": {"panel": 1}})");
    RecordProperty(
        "first_ms",
        std::to_string(
            1e3 *
            std::chrono::duration<double>(std::chrono::steady_clock::now() - cold_start).count()));
    ASSERT_EQ(again.status, 200u) << again.body;
    const json scene = json::parse(again.body);
    const json& stored = result["light_scenes"][0];
    ASSERT_EQ(stored["name"], "panel only");
    for (std::size_t i = 0; i < 10000; i += 997) {
        EXPECT_NEAR(scene["sensors"][0]["illuminance"][i].get<double>(),
                    stored["sensors"][0]["illuminance"][i].get<double>(), 1e-9);
    }
    // Half of each group is half of everything, up to the rounding of both averages to the
    // result's 4 significant digits (half a unit of the last digit each).
    const auto half = http_call(d.port(), verb::post, job + "/scenes",
                                R"({"name": "half", "dimming": {"panel": 0.5, "down": 0.5}})");
    ASSERT_EQ(half.status, 200u);
    const auto last_digit = [](double x) { return std::pow(10.0, std::floor(std::log10(x)) - 3); };
    const double half_average = json::parse(half.body)["sensors"][0]["average"].get<double>();
    const double average = result["sensors"][0]["average"].get<double>();
    EXPECT_NEAR(half_average, 0.5 * average,
                0.5 * last_digit(half_average) + 0.25 * last_digit(average));

    // Timed: the median of several requests over loopback.
    std::vector<double> seconds;
    for (int k = 0; k < 7; ++k) {
        const auto start = std::chrono::steady_clock::now();
        const auto r = http_call(d.port(), verb::post, job + "/scenes",
                                 R"({"name": "mix", "dimming": {"panel": 0.3, "down": 0.9}})");
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        ASSERT_EQ(r.status, 200u);
    }
    std::nth_element(seconds.begin(), seconds.begin() + 3, seconds.end());
    EXPECT_LT(seconds[3], 0.05);
    RecordProperty("median_ms", std::to_string(1e3 * seconds[3]));

    // Bad light scenes: an unknown group, a dimming above 1, a body that is no light scene.
    const auto unknown = http_call(d.port(), verb::post, job + "/scenes",
                                   R"({"name": "x", "dimming": {"nope": 1}})");
    EXPECT_EQ(unknown.status, 400u);
    EXPECT_EQ(json::parse(unknown.body)["error"]["pointer"], "/dimming/nope");
    const auto bright = http_call(d.port(), verb::post, job + "/scenes",
                                  R"({"name": "x", "dimming": {"down": 2}})");
    EXPECT_EQ(bright.status, 400u);
    EXPECT_EQ(json::parse(bright.body)["error"]["pointer"], "/dimming/down");
    const auto wrong = http_call(d.port(), verb::post, job + "/scenes", R"({"dimming": 3})");
    EXPECT_EQ(wrong.status, 400u);
    // Sent as anything but JSON: refused like a scene (a web page could send it unasked).
    const auto plain =
        http_call(d.port(), verb::post, job + "/scenes", R"({"name": "x", "dimming": {"down": 1}})",
                  {{"Content-Type", "text/plain"}});
    EXPECT_EQ(plain.status, 415u);
    // GET is not the way to ask.
    EXPECT_EQ(http_call(d.port(), verb::get, job + "/scenes").status, 405u);
    fs::remove_all(dir);
}

}  // namespace
