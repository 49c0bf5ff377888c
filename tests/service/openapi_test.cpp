// The live server's answers against proto/openapi.yaml: every endpoint, its success and error
// statuses, JSON bodies and event data, checked by tests/support/openapi_check.py.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "daemon.h"
#include "service_scenes.h"
#include "sse.h"
#include "store_under_test.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using boost::beast::http::verb;
using nlohmann::json;
using radiant::test::http_call;
using radiant::test::Reply;

const char* verb_name(verb method) {
    switch (method) {
        case verb::post:
            return "post";
        case verb::delete_:
            return "delete";
        default:
            return "get";
    }
}

/// Sends requests and records each answer with the path template it exercises.
class Recorder {
public:
    explicit Recorder(unsigned short port) : port_(port) {}

    Reply call(verb method, const std::string& path_template, const std::string& target,
               const std::string& body = "",
               const std::map<std::string, std::string>& headers = {}) {
        Reply r = http_call(port_, method, target, body, headers);
        const auto type = r.headers.find("Content-Type");
        const std::string content_type = type == r.headers.end() ? "" : type->second;
        // Pictures are bytes, not text for a JSON string: only their type is checked.
        const bool binary = content_type.rfind("image/", 0) == 0;
        exchanges_.push_back({{"method", verb_name(method)},
                              {"path", path_template},
                              {"status", r.status},
                              {"content_type", content_type},
                              {"body", binary ? std::string() : r.body}});
        if (type != r.headers.end() && type->second == "text/event-stream") {
            for (const auto& e : radiant::test::parse_sse(r.body)) {
                std::string component = e.name;
                component[0] = static_cast<char>(std::toupper(component[0]));
                exchanges_.push_back(
                    {{"component", component + "Event"}, {"body", json::parse(e.data)}});
                ++events_[e.name];
            }
        }
        return r;
    }
    const json& exchanges() const { return exchanges_; }
    int events(const std::string& name) const {
        const auto it = events_.find(name);
        return it == events_.end() ? 0 : it->second;
    }

private:
    unsigned short port_;
    json exchanges_ = json::array();
    std::map<std::string, int> events_;
};

/// Polls the job (unrecorded) until its status is `want`.
std::string wait_for(unsigned short port, const std::string& id, const std::string& want) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    std::string status;
    while (std::chrono::steady_clock::now() < deadline) {
        status = json::parse(http_call(port, verb::get, "/v1/jobs/" + id).body)["status"];
        if (status == want) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return status;
}

using OpenApiTest = radiant::test::StoreTest;
INSTANTIATE_TEST_SUITE_P(Stores, OpenApiTest, radiant::test::both_stores(),
                         radiant::test::store_name);

TEST_P(OpenApiTest, EveryAnswerMatchesTheSpec) {
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_openapi_test_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    radiant::test::Daemon d(dir / "data",
                            flags({"--queue-limit", "1", "--max-body-bytes", "100000"}),
                            dir / "radiantd.log");
    Recorder rec(d.port());
    const std::string jobs = "/v1/jobs", job = "/v1/jobs/{id}";
    const std::string result = "/v1/jobs/{id}/result", events = "/v1/jobs/{id}/events";

    // A finished job: submit, status, result with and without the mesh, its event stream.
    const Reply posted = rec.call(verb::post, jobs, jobs, radiant::test::tiny_room());
    ASSERT_EQ(posted.status, 202u);
    const std::string done = json::parse(posted.body)["id"];
    ASSERT_EQ(wait_for(d.port(), done, "done"), "done");
    EXPECT_EQ(rec.call(verb::get, job, jobs + "/" + done).status, 200u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + done + "/result").status, 200u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + done + "/result?include=mesh").status, 200u);
    EXPECT_EQ(rec.call(verb::get, events, jobs + "/" + done + "/events").status, 200u);
    const std::string csv = "/v1/jobs/{id}/sensors.csv", plan = "/v1/jobs/{id}/plan.png",
                      view = "/v1/jobs/{id}/view.png";
    EXPECT_EQ(rec.call(verb::get, csv, jobs + "/" + done + "/sensors.csv").status, 200u);
    EXPECT_EQ(rec.call(verb::get, plan, jobs + "/" + done + "/plan.png?size=200").status, 200u);
    EXPECT_EQ(rec.call(verb::get, plan, jobs + "/" + done + "/plan.png?size=5").status, 400u);
    EXPECT_EQ(rec.call(verb::get, plan, jobs + "/" + done + "/plan.png?sensors=nope").status, 404u);
    EXPECT_EQ(
        rec.call(verb::get, view, jobs + "/" + done + "/view.png?width=64&height=48&falsecolor=1")
            .status,
        200u);
    EXPECT_EQ(rec.call(verb::get, view, jobs + "/" + done + "/view.png?eye=1,2").status, 400u);
    EXPECT_EQ(rec.call(verb::get, "/v1/openapi.yaml", "/v1/openapi.yaml").status, 200u);
    const Reply keyed =
        rec.call(verb::post, jobs, jobs, radiant::test::tiny_room(), {{"Idempotency-Key", "k"}});
    ASSERT_EQ(keyed.status, 202u);
    // The queue holds one job: let this one finish before filling it on purpose below.
    ASSERT_EQ(wait_for(d.port(), json::parse(keyed.body)["id"], "done"), "done");

    // A light scene from a finished job's groups; a job without groups cannot give one.
    const std::string scenes = "/v1/jobs/{id}/scenes";
    const Reply grouped = rec.call(verb::post, jobs, jobs, radiant::test::grouped_room());
    ASSERT_EQ(grouped.status, 202u);
    const std::string lit = json::parse(grouped.body)["id"];
    ASSERT_EQ(wait_for(d.port(), lit, "done"), "done");
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + lit + "/result").status, 200u);
    EXPECT_EQ(rec.call(verb::post, scenes, jobs + "/" + lit + "/scenes",
                       R"({"name": "dim", "dimming": {"panel": 0.5, "down": 1}})")
                  .status,
              200u);
    EXPECT_EQ(rec.call(verb::post, scenes, jobs + "/" + lit + "/scenes",
                       R"({"name": "x", "dimming": {"nope": 1}})")
                  .status,
              400u);
    EXPECT_EQ(rec.call(verb::post, scenes, jobs + "/" + done + "/scenes",
                       R"({"name": "x", "dimming": {}})")
                  .status,
              409u);
    // A job with warnings, and a strict scene refused for them.
    const std::string dark_room =
        R"({"format": "radiant-scene/1", "materials": {"w": {"reflectance": 0.5}},
            "surfaces": [{"name": "room", "material": "w",
                          "box": {"min": [0,0,0], "max": [1,1,1]}}],
            "settings": {"method": "direct", "tolerance": 0.1)";
    const Reply dark = rec.call(verb::post, jobs, jobs, dark_room + "}}");
    ASSERT_EQ(dark.status, 202u);
    const std::string warned = json::parse(dark.body)["id"];
    ASSERT_EQ(wait_for(d.port(), warned, "done"), "done");
    EXPECT_EQ(json::parse(rec.call(verb::get, job, jobs + "/" + warned).body)["warnings"].size(),
              1u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + warned + "/result").status, 200u);
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, dark_room + R"(, "strict": true}})").status, 400u);

    // A running job, one queued behind it, and a full queue.
    const std::string running =
        json::parse(rec.call(verb::post, jobs, jobs, radiant::test::slow_room()).body)["id"];
    ASSERT_EQ(wait_for(d.port(), running, "running"), "running");
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // a snapshot or two
    const std::string queued =
        json::parse(rec.call(verb::post, jobs, jobs, radiant::test::tiny_room()).body)["id"];
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, radiant::test::tiny_room()).status, 429u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + running + "/result").status, 200u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + running + "/result?include=mesh").status,
              200u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + queued + "/result").status, 404u);
    EXPECT_EQ(rec.call(verb::get, csv, jobs + "/" + running + "/sensors.csv").status, 404u);
    EXPECT_EQ(rec.call(verb::get, jobs, jobs + "?limit=2").status, 200u);
    EXPECT_EQ(rec.call(verb::delete_, job, jobs + "/" + queued).status, 200u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + queued + "/result").status, 404u);
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        http_call(d.port(), verb::delete_, "/v1/jobs/" + running);
    });
    EXPECT_EQ(rec.call(verb::get, events, jobs + "/" + running + "/events").status, 200u);
    canceller.join();
    EXPECT_EQ(rec.call(verb::delete_, job, jobs + "/" + running).status, 200u);

    // Errors.
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, "{").status, 400u);
    EXPECT_EQ(
        rec.call(verb::post, jobs, jobs, R"({"format": "radiant-scene/1", "surfaces": []})").status,
        400u);
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, std::string(100001, ' ')).status, 413u);
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, std::string(1000, '[')).status, 413u);
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, radiant::test::tiny_room(),
                       {{"Content-Type", "text/plain"}})
                  .status,
              415u);
    EXPECT_EQ(rec.call(verb::get, jobs, jobs, "", {{"Host", "evil.example"}}).status, 403u);
    EXPECT_EQ(rec.call(verb::post, jobs, jobs, radiant::test::tiny_room(),
                       {{"Origin", "https://evil.example"}})
                  .status,
              403u);
    EXPECT_EQ(rec.call(verb::get, jobs, jobs + "?limit=0").status, 400u);
    const std::string unknown = "/v1/jobs/00000000000000000000000000000000";
    EXPECT_EQ(rec.call(verb::get, job, unknown).status, 404u);
    EXPECT_EQ(rec.call(verb::delete_, job, unknown).status, 404u);
    EXPECT_EQ(rec.call(verb::get, result, unknown + "/result").status, 404u);
    EXPECT_EQ(rec.call(verb::get, result, jobs + "/" + done + "/result?include=nope").status, 400u);
    EXPECT_EQ(rec.call(verb::get, events, unknown + "/events").status, 404u);
    EXPECT_EQ(rec.call(verb::post, "/v1/jobs/{id}/scenes", unknown + "/scenes",
                       R"({"name": "x", "dimming": {}})")
                  .status,
              404u);
    EXPECT_EQ(rec.call(verb::get, "/healthz", "/healthz").status, 200u);
    EXPECT_EQ(rec.call(verb::get, "/readyz", "/readyz").status, 200u);
    EXPECT_EQ(rec.call(verb::get, "/metrics", "/metrics").status, 200u);
    // The viewer (200 when the build made it, else 404) and a file that is not there.
    const unsigned viewer = rec.call(verb::get, "/", "/").status;
    EXPECT_TRUE(viewer == 200u || viewer == 404u) << viewer;
    EXPECT_EQ(rec.call(verb::get, "/{file}", "/no-such-file.js").status, 404u);

    // Every kind of event was seen, so each event schema was exercised too.
    for (const char* name : {"progress", "mesh", "radiosity", "done"}) {
        EXPECT_GT(rec.events(name), 0) << name;
    }

    const fs::path recorded = dir / "exchanges.json";
    std::ofstream(recorded) << rec.exchanges().dump(1);
    const std::string command =
        "python3 '" RADIANT_SOURCE_DIR "/tests/support/openapi_check.py' '" RADIANT_SOURCE_DIR
        "/proto/openapi.yaml' '" +
        recorded.string() + "' > '" + (dir / "check.out").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0)
        << radiant::test::read_text(dir / "check.out");
    fs::remove_all(dir);
}

}  // namespace
