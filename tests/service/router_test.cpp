// The HTTP API through Router::route, without sockets: status codes, bodies, and the job life
// cycle with a real queue, store and worker.
#include "radiant/server/router.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <thread>

#include "gltf_validator.h"
#include "radiant/proto/scene_json.h"
#include "radiant/proto/sensors_csv.h"
#include "radiant/server/config.h"
#include "radiant/server/sqlite_job_store.h"
#include "service_scenes.h"
#include "store_under_test.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant::server;
using nlohmann::json;

/// A store (`store`'s, SQLite in a fresh temp directory), a queue with one worker, and the router
/// over them.
class Service {
public:
    explicit Service(const radiant::test::StoreUnderTest& store, JobQueueOptions options = {},
                     std::size_t max_body_bytes = 1 << 20)
        : dir_(fs::temp_directory_path() /
               ("radiant_router_test_" + std::to_string(getpid()) + "_" + std::to_string(++n_))) {
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        store_ = store.open(dir_);
        jobs_ = std::make_unique<JobQueue>(*store_, metrics_, options);
        ctx_ = std::make_unique<ServiceContext>(
            ServiceContext{*jobs_, *store_, metrics_, max_body_bytes});
        router_ = std::make_unique<Router>(*ctx_);
    }
    ~Service() {
        jobs_->shutdown();
        router_.reset();
        jobs_.reset();
        store_.reset();
        fs::remove_all(dir_);
    }

    RouteResult call(http::verb method, const std::string& target, const std::string& body = "",
                     const std::string& idempotency_key = "") {
        Request request{method, target, 11};
        if (!idempotency_key.empty()) request.set("Idempotency-Key", idempotency_key);
        if (!body.empty()) request.set(http::field::content_type, "application/json");
        request.body() = body;
        request.prepare_payload();
        return router_->route(request);
    }
    /// Deferred answers (pictures, CSV) are made here, as the session's pool would.
    Response get(const std::string& target) {
        RouteResult routed = call(http::verb::get, target);
        return routed.deferred ? routed.deferred() : routed.response;
    }
    Response post(const std::string& body, const std::string& key = "") {
        return call(http::verb::post, "/v1/jobs", body, key).response;
    }
    Response del(const std::string& target) { return call(http::verb::delete_, target).response; }

    /// Polls GET /v1/jobs/{id} until its status is `want` or `seconds` pass.
    json wait_for(const std::string& id, const std::string& want, double seconds = 15) {
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        json job;
        do {
            job = json::parse(get("/v1/jobs/" + id).body());
            if (job["status"] == want) return job;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        } while (std::chrono::steady_clock::now() < deadline);
        return job;
    }

    /// `request` as it comes, headers and all.
    Response send(const Request& request) { return router_->route(request).response; }
    ServiceContext& context() { return *ctx_; }
    JobQueue& jobs() { return *jobs_; }
    JobStore& store() { return *store_; }
    Metrics& metrics() { return metrics_; }
    const fs::path& dir() const { return dir_; }

private:
    static inline int n_ = 0;
    fs::path dir_;
    Metrics metrics_;
    std::unique_ptr<JobStore> store_;
    std::unique_ptr<JobQueue> jobs_;
    std::unique_ptr<ServiceContext> ctx_;
    std::unique_ptr<Router> router_;
};

using RouterTest = radiant::test::StoreTest;
INSTANTIATE_TEST_SUITE_P(Stores, RouterTest, radiant::test::both_stores(),
                         radiant::test::store_name);

std::string id_of(const Response& response) { return json::parse(response.body())["id"]; }

TEST_P(RouterTest, GoodSceneIsAcceptedAndSolved) {
    Service s(store());
    const Response posted = s.post(radiant::test::tiny_room());
    ASSERT_EQ(posted.result(), http::status::accepted) << posted.body();
    const std::string id = id_of(posted);
    EXPECT_EQ(id.size(), 32u);
    EXPECT_EQ(json::parse(posted.body())["status"], "queued");
    EXPECT_EQ(posted[http::field::location], "/v1/jobs/" + id);

    const json job = s.wait_for(id, "done");
    ASSERT_EQ(job["status"], "done") << job.dump();
    EXPECT_EQ(job["progress"]["fraction"], 1.0);
    EXPECT_TRUE(job["created"].is_string());
    EXPECT_TRUE(job["finished"].get<std::string>().ends_with("Z"));

    const Response result = s.get("/v1/jobs/" + id + "/result");
    ASSERT_EQ(result.result(), http::status::ok);
    const json doc = json::parse(result.body());
    EXPECT_EQ(doc["format"], "radiant-result/1");
    EXPECT_EQ(doc["status"], "converged");
    EXPECT_GT(doc["sensors"][0]["average"].get<double>(), 0);
}

TEST_P(RouterTest, ResultGlbIsAValidGltfOfTheSolvedMeshAndSensors) {
    Service s(store());
    const Response posted = s.post(radiant::test::tiny_room());
    ASSERT_EQ(posted.result(), http::status::accepted) << posted.body();
    const std::string id = id_of(posted);
    ASSERT_EQ(s.wait_for(id, "done")["status"], "done");
    const Response glb = s.get("/v1/jobs/" + id + "/result.glb");
    ASSERT_EQ(glb.result(), http::status::ok) << glb.body();
    EXPECT_EQ(glb[http::field::content_type], "model/gltf-binary");
    const std::string& body = glb.body();
    ASSERT_GT(body.size(), 20u);
    EXPECT_EQ(body.substr(0, 4), "glTF");
    // Both layers are there: the solved surfaces and the sensor points.
    EXPECT_NE(body.find("\"surfaces\""), std::string::npos);
    EXPECT_NE(body.find("\"sensors\""), std::string::npos);
    const fs::path file = s.dir() / "result.glb";
    std::ofstream(file, std::ios::binary) << body;
    radiant::test::expect_valid_gltf(file);

    EXPECT_EQ(s.get("/v1/jobs/ffffffffffffffffffffffffffffffff/result.glb").result(),
              http::status::not_found);
    EXPECT_EQ(s.call(http::verb::post, "/v1/jobs/" + id + "/result.glb").response.result(),
              http::status::method_not_allowed);
}

/// A finished job of a room with a 3 × 2 grid and two named points; its id.
std::string solved_grid_room(Service& s) {
    const std::string scene = R"({"format": "radiant-scene/1", "name": "grid-room",
  "materials": {"wall": {"reflectance": 0.5}},
  "surfaces": [{"name": "room", "material": "wall",
                "box": {"min": [0, 0, 0], "max": [4, 4, 3], "facing": "in"}}],
  "luminaires": [{"name": "bulb", "position": [2, 2, 2.5], "flux": 1000}],
  "sensors": [
    {"name": "grid", "normal": [0, 0, 1],
     "grid": {"origin": [0.5, 1, 0.8], "u": [3, 0, 0], "v": [0, 2, 0], "nu": 3, "nv": 2}},
    {"name": "desk, \"north\"", "normal": [0, -1, 0], "points": [[1.2, 3, 0.75], [2.8, 3, 0.75]]}
  ],
  "settings": {"tolerance": 0.1}})";
    const Response posted = s.post(scene);
    EXPECT_EQ(posted.result(), http::status::accepted) << posted.body();
    const std::string id = id_of(posted);
    EXPECT_EQ(s.wait_for(id, "done")["status"], "done");
    return id;
}

TEST_P(RouterTest, SensorsCsvHoldsTheResultsPointsAndLux) {
    Service s(store());
    const std::string id = solved_grid_room(s);
    const json result = json::parse(s.get("/v1/jobs/" + id + "/result").body());
    const Response csv = s.get("/v1/jobs/" + id + "/sensors.csv");
    ASSERT_EQ(csv.result(), http::status::ok) << csv.body();
    EXPECT_EQ(csv[http::field::content_type], "text/csv; charset=utf-8; header=present");
    // The same bytes as the CLI's CSV of the same numbers.
    std::vector<radiant::SensorResult> sets;
    for (const json& set : result["sensors"]) {
        radiant::SensorResult r;
        r.name = set["name"];
        for (const json& p : set["points"]) r.points.push_back({p[0], p[1], p[2]});
        r.normal = {set["normal"][0], set["normal"][1], set["normal"][2]};
        r.illuminance = set["illuminance"].get<std::vector<double>>();
        sets.push_back(r);
    }
    EXPECT_EQ(csv.body(), radiant::proto::sensors_csv(sets, radiant::proto::kMaxDigits));
    EXPECT_EQ(std::count(csv.body().begin(), csv.body().end(), '\n'), 1 + 6 + 2);
    EXPECT_NE(csv.body().find("\r\n\"desk, \"\"north\"\"\",1,2.8,3,0.75,0,-1,0,"),
              std::string::npos)
        << csv.body();
}

TEST_P(RouterTest, ThreePicturesOfOneSolveCostOneSolve) {
    Service s(store());
    const std::string id = solved_grid_room(s);
    const std::string base = "/v1/jobs/" + id;
    for (const std::string picture :
         {"/plan.png?sensors=grid&size=300", "/view.png?width=120&height=90",
          "/view.png?width=120&height=90&falsecolor=1&eye=0.5,0.5,2&target=3,3,0.5"}) {
        const Response png = s.get(base + picture);
        ASSERT_EQ(png.result(), http::status::ok) << picture << ": " << png.body();
        EXPECT_EQ(png[http::field::content_type], "image/png");
        EXPECT_EQ(png.body().substr(1, 3), "PNG") << picture;
    }
    const std::string metrics = s.get("/metrics").body();
    EXPECT_NE(metrics.find("\nradiant_solves_total 1\n"), std::string::npos) << metrics;
}

TEST_P(RouterTest, PictureQueriesAreChecked) {
    Service s(store());
    const std::string id = solved_grid_room(s);
    const std::string base = "/v1/jobs/" + id;
    for (const char* bad :
         {"/view.png?eye=1,2", "/view.png?width=100000", "/view.png?zoom=2", "/view.png?fov=180",
          "/view.png?falsecolor=maybe", "/view.png?eye=1,1,1&target=1,1,1", "/plan.png?size=nan",
          "/view.png?width=2048&height=2048"}) {
        const Response r = s.get(base + bad);
        EXPECT_EQ(r.result(), http::status::bad_request) << bad << ": " << r.body();
        EXPECT_EQ(json::parse(r.body())["error"]["code"], "invalid_query") << bad;
    }
    EXPECT_EQ(s.get(base + "/plan.png?sensors=nope").result(), http::status::not_found);
    EXPECT_EQ(s.get("/v1/jobs/ffffffffffffffffffffffffffffffff/view.png").result(),
              http::status::not_found);
    EXPECT_EQ(s.call(http::verb::post, base + "/plan.png").response.result(),
              http::status::method_not_allowed);
}

TEST_P(RouterTest, OpenApiIsServed) {
    Service s(store());
    const Response r = s.get("/v1/openapi.yaml");
    ASSERT_EQ(r.result(), http::status::ok);
    EXPECT_EQ(r[http::field::content_type], "application/yaml");
    EXPECT_EQ(r.body(),
              radiant::test::read_text(fs::path(RADIANT_SOURCE_DIR) / "proto/openapi.yaml"));
}

TEST_P(RouterTest, BadJsonIs400) {
    Service s(store());
    const Response r = s.post("{not json");
    EXPECT_EQ(r.result(), http::status::bad_request);
    EXPECT_EQ(json::parse(r.body())["error"]["code"], "invalid_json");
}

TEST_P(RouterTest, BadSceneIs400WithTheValidatePointers) {
    Service s(store());
    const std::string text =
        radiant::test::read_text(std::string(RADIANT_TEST_DATA) + "/bad/unknown-material.json");
    const Response r = s.post(text);
    ASSERT_EQ(r.result(), http::status::bad_request);
    const json error = json::parse(r.body())["error"];
    EXPECT_EQ(error["code"], "invalid_scene");
    const auto expected = radiant::proto::parse_scene(text).problems;
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(error["pointer"], expected.front().pointer);
    EXPECT_EQ(error["message"], expected.front().message);
    EXPECT_EQ(error["problems"].size(), expected.size());
}

TEST_P(RouterTest, TooLargeIs413) {
    Service s(store(), {}, 100);
    EXPECT_EQ(s.post(radiant::test::tiny_room()).result(), http::status::payload_too_large);
}

TEST_P(RouterTest, UnknownJobsRoutesAndMethods) {
    Service s(store());
    EXPECT_EQ(s.get("/v1/jobs/nope").result(), http::status::not_found);
    EXPECT_EQ(s.get("/v1/jobs/nope/result").result(), http::status::not_found);
    EXPECT_EQ(s.del("/v1/jobs/nope").result(), http::status::not_found);
    EXPECT_EQ(s.get("/v1/jobs/nope/events").result(), http::status::not_found);
    EXPECT_EQ(s.get("/nowhere").result(), http::status::not_found);
    EXPECT_EQ(s.del("/v1/jobs").result(), http::status::method_not_allowed);
    EXPECT_EQ(json::parse(s.get("/nowhere").body())["error"]["code"], "not_found");
}

TEST_P(RouterTest, FullQueueIs429WithRetryAfterAndCancelWorks) {
    JobQueueOptions options;
    options.queue_limit = 1;
    Service s(store(), options);
    const std::string running = id_of(s.post(radiant::test::slow_room()));
    ASSERT_EQ(s.wait_for(running, "running")["status"], "running");
    const std::string queued = id_of(s.post(radiant::test::tiny_room()));
    const Response full = s.post(radiant::test::tiny_room());
    EXPECT_EQ(full.result(), http::status::too_many_requests);
    EXPECT_EQ(full[http::field::retry_after], "5");
    EXPECT_EQ(json::parse(full.body())["error"]["code"], "queue_full");
    EXPECT_EQ(s.get("/v1/jobs/" + queued + "/result").result(), http::status::not_found);

    // A queued job is cancelled at once; a running one within about a second.
    const Response cancelled_queued = s.del("/v1/jobs/" + queued);
    EXPECT_EQ(cancelled_queued.result(), http::status::ok);
    EXPECT_EQ(json::parse(cancelled_queued.body())["status"], "cancelled");
    const auto asked = std::chrono::steady_clock::now();
    EXPECT_EQ(s.del("/v1/jobs/" + running).result(), http::status::accepted);
    EXPECT_EQ(s.wait_for(running, "cancelled", 5)["status"], "cancelled");
    EXPECT_LT(std::chrono::steady_clock::now() - asked, std::chrono::seconds(2));
    // The best result so far stays readable.
    const Response result = s.get("/v1/jobs/" + running + "/result");
    ASSERT_EQ(result.result(), http::status::ok);
    EXPECT_EQ(json::parse(result.body())["format"], "radiant-result/1");
}

TEST_P(RouterTest, RunningResultIsAProgressSnapshot) {
    Service s(store());
    const std::string id = id_of(s.post(radiant::test::slow_room()));
    ASSERT_EQ(s.wait_for(id, "running")["status"], "running");
    const json doc = json::parse(s.get("/v1/jobs/" + id + "/result").body());
    EXPECT_EQ(doc["status"], "running");
    EXPECT_EQ(doc["scene"], "tiny-room");
    EXPECT_TRUE(doc["stats"].contains("iterations"));
    EXPECT_TRUE(doc["progress"].contains("fraction"));

    // Once the engine has published a snapshot, the running result names it and carries its mesh.
    json running;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    do {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        running = json::parse(s.get("/v1/jobs/" + id + "/result?include=mesh").body());
    } while (!running.contains("mesh") && std::chrono::steady_clock::now() < deadline);
    ASSERT_TRUE(running.contains("mesh")) << running.dump();
    EXPECT_GE(running["snapshot"]["version"].get<int>(), 1);
    const json& mesh = running["mesh"];
    EXPECT_GT(mesh["triangles"].size(), 0u);
    EXPECT_EQ(mesh["triangle_radiosity"].size(), mesh["triangles"].size());
    EXPECT_EQ(mesh["vertex_radiosity"].size(), mesh["vertices"].size());

    // The store has the running job's progress within about a second (polled: on a loaded
    // machine a store's write can take longer, and the full suite failed here now and then).
    const auto persisted = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (s.store().find(id, false)->progress.sequence == 0 &&
           std::chrono::steady_clock::now() < persisted) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    EXPECT_GT(s.store().find(id, false)->progress.sequence, 0u);

    // Cancelled: the best result so far keeps its mesh.
    s.del("/v1/jobs/" + id);
    ASSERT_EQ(s.wait_for(id, "cancelled")["status"], "cancelled");
    const json stopped = json::parse(s.get("/v1/jobs/" + id + "/result?include=mesh").body());
    EXPECT_EQ(stopped["status"], "stopped");
    EXPECT_GT(stopped["mesh"]["triangles"].size(), 0u);
    EXPECT_FALSE(stopped.contains("progress"));
}

TEST_P(RouterTest, IdempotencyKeyReturnsTheSameJob) {
    Service s(store());
    const std::string a = id_of(s.post(radiant::test::tiny_room(), "key-1"));
    const std::string b = id_of(s.post(radiant::test::tiny_room(), "key-1"));
    const std::string c = id_of(s.post(radiant::test::tiny_room(), "key-2"));
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST_P(RouterTest, ListIsNewestFirstAndPaged) {
    Service s(store());
    std::vector<std::string> ids;
    for (int i = 0; i < 3; ++i) ids.push_back(id_of(s.post(radiant::test::tiny_room())));
    const json first = json::parse(s.get("/v1/jobs?limit=2").body());
    ASSERT_EQ(first["jobs"].size(), 2u);
    EXPECT_EQ(first["jobs"][0]["id"], ids[2]);
    EXPECT_EQ(first["jobs"][1]["id"], ids[1]);
    ASSERT_EQ(first["next"], ids[1]);
    const json second =
        json::parse(s.get("/v1/jobs?limit=2&after=" + first["next"].get<std::string>()).body());
    ASSERT_EQ(second["jobs"].size(), 1u);
    EXPECT_EQ(second["jobs"][0]["id"], ids[0]);
    EXPECT_TRUE(second["next"].is_null());
    EXPECT_EQ(s.get("/v1/jobs?limit=0").result(), http::status::bad_request);
    for (const std::string& id : ids) s.wait_for(id, "done");
}

TEST_P(RouterTest, ShuttingDownIs503) {
    Service s(store());
    s.jobs().shutdown();
    const Response r = s.post(radiant::test::tiny_room());
    EXPECT_EQ(r.result(), http::status::service_unavailable);
    EXPECT_EQ(json::parse(r.body())["error"]["code"], "shutting_down");
    EXPECT_EQ(s.get("/healthz").result(), http::status::ok) << "alive while it stops";
    const Response ready = s.get("/readyz");
    EXPECT_EQ(ready.result(), http::status::service_unavailable);
    EXPECT_EQ(json::parse(ready.body())["error"]["code"], "shutting_down");
}

TEST_P(RouterTest, ReadyWhileTheStoreTakesWrites) {
    Service s(store());
    const Response r = s.get("/readyz");
    EXPECT_EQ(r.result(), http::status::ok);
    EXPECT_EQ(json::parse(r.body())["status"], "ready");
    EXPECT_EQ(s.call(http::verb::post, "/readyz").response.result(),
              http::status::method_not_allowed);
}

TEST(Router, AReplicaNameLabelsEveryMetric) {
    Metrics metrics("r\"1\\");
    metrics.count_request(200);
    const std::string text = metrics.render({{JobStatus::queued, 3}}, 2);
    for (const char* line :
         {"radiant_jobs{replica=\"r\\\"1\\\\\",state=\"queued\"} 3",
          "radiant_queue_length{replica=\"r\\\"1\\\\\"} 2",
          "radiant_solves_total{replica=\"r\\\"1\\\\\"} 0",
          "radiant_http_requests_total{replica=\"r\\\"1\\\\\",status=\"200\"} 1"}) {
        EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
    }
    EXPECT_EQ(Metrics().render({}, 0).find("replica="), std::string::npos);
}

TEST_P(RouterTest, HealthAndMetrics) {
    Service s(store());
    EXPECT_EQ(s.get("/healthz").result(), http::status::ok);
    s.metrics().count_request(200);
    const std::string text = s.get("/metrics").body();
    for (const char* name : {"radiant_jobs{state=\"queued\"} 0", "radiant_queue_length 0",
                             "radiant_solve_seconds_total", "radiant_rays_total",
                             "radiant_http_requests_total{status=\"200\"} 1"}) {
        EXPECT_NE(text.find(name), std::string::npos) << name << "\n" << text;
    }
}

TEST_P(RouterTest, EventsStartAStreamForKnownJobs) {
    Service s(store());
    const std::string id = id_of(s.post(radiant::test::tiny_room()));
    RouteResult r = s.call(http::verb::get, "/v1/jobs/" + id + "/events");
    ASSERT_TRUE(r.events);
    EXPECT_EQ(r.events->job_id, id);
    EXPECT_EQ(r.response[http::field::content_type], "text/event-stream");
    s.wait_for(id, "done");
}

using JobQueueTest = RouterTest;
INSTANTIATE_TEST_SUITE_P(Stores, JobQueueTest, radiant::test::both_stores(),
                         radiant::test::store_name);

TEST_P(JobQueueTest, UnfinishedJobsRunAgainAfterRestart) {
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_requeue_test_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    JobRecord job;
    job.id = new_job_id();
    job.scene_json = radiant::test::tiny_room();
    job.created = now_millis();
    {
        // As if the process died mid-solve (on a shared store, under a lease that ends at once).
        const std::unique_ptr<JobStore> died = store().open(dir);
        died->insert(job);
        if (died->shared()) {
            ASSERT_TRUE(died->claim("died", std::chrono::milliseconds(1), kMaxJobAttempts));
        } else {
            died->mark_running(job.id, now_millis());
        }
        JobProgress seen;
        seen.sequence = 50;  // event ids a client may have seen
        died->save_progress(job.id, seen);
    }
    {
        const std::unique_ptr<JobStore> restarted = store().open(dir);
        Metrics metrics;
        JobQueue queue(*restarted, metrics, {});
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
        while (queue.find(job.id)->status != JobStatus::done &&
               std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        EXPECT_EQ(queue.find(job.id)->status, JobStatus::done);
        // The new run's event ids continue above the old ones.
        EXPECT_GT(queue.find(job.id)->progress.sequence, 1000050u);
        EXPECT_GT(queue.snapshot(job.id)->info().mesh_event_id, 1000050u);
        EXPECT_TRUE(restarted->result(job.id).has_value());
    }
    fs::remove_all(dir);
}

Request scene_request(const std::string& body, const std::map<std::string, std::string>& headers) {
    Request request{http::verb::post, "/v1/jobs", 11};
    for (const auto& [name, value] : headers) request.set(name, value);
    request.body() = body;
    request.prepare_payload();
    return request;
}

TEST_P(RouterTest, SceneNeedsTheJsonContentType) {
    Service s(store());
    for (const char* type : {"", "text/plain", "application/x-www-form-urlencoded"}) {
        std::map<std::string, std::string> headers;
        if (*type) headers["Content-Type"] = type;
        const Response r = s.send(scene_request(radiant::test::tiny_room(), headers));
        EXPECT_EQ(r.result(), http::status::unsupported_media_type) << type;
        EXPECT_EQ(json::parse(r.body())["error"]["code"], "unsupported_media_type");
    }
    EXPECT_EQ(s.store().list(10, "").size(), 0u) << "nothing was queued";
    const Response ok = s.send(scene_request(
        radiant::test::tiny_room(), {{"Content-Type", "Application/JSON; charset=utf-8"}}));
    EXPECT_EQ(ok.result(), http::status::accepted) << ok.body();
}

TEST_P(RouterTest, InvalidUtf8Is400WithAPointerNot500) {
    Service s(store());
    const Response body = s.post("{\"format\": \"radiant-scene/1\", \"name\": \"\xff\xfe\"}");
    ASSERT_EQ(body.result(), http::status::bad_request) << body.body();
    const json error = json::parse(body.body())["error"];
    EXPECT_EQ(error["code"], "invalid_json");
    EXPECT_EQ(error["pointer"], "/name");
    for (const std::string& key : {std::string("\xff\xfe"), std::string(201, 'k')}) {
        const Response refused = s.post(radiant::test::tiny_room(), key);
        EXPECT_EQ(refused.result(), http::status::bad_request) << refused.body();
        EXPECT_EQ(json::parse(refused.body())["error"]["code"], "bad_request");
    }
    const Response path = s.get("/v1/jobs/\xff\xfe");
    EXPECT_EQ(path.result(), http::status::not_found) << "the id is quoted, not thrown on";
    EXPECT_TRUE(json::accept(path.body()));
}

TEST_P(RouterTest, OverTheJsonBudgetIs413WithAPointer) {
    Service s(store(), {}, 64u << 20);
    const Response r = s.post(std::string(1'000'000, '['));
    ASSERT_EQ(r.result(), http::status::payload_too_large) << r.body();
    const json error = json::parse(r.body())["error"];
    EXPECT_EQ(error["code"], "too_complex");
    EXPECT_EQ(error["message"], "nested deeper than 64 levels");
    EXPECT_FALSE(error["pointer"].get<std::string>().empty());
}

TEST_P(RouterTest, TokenIsNeededOnEveryRouteButHealthz) {
    Service s(store());
    s.context().access.token = "s3cret-token";
    for (const char* target : {"/v1/jobs", "/metrics", "/v1/jobs/x", "/nowhere"}) {
        const Response r = s.get(target);
        EXPECT_EQ(r.result(), http::status::unauthorized) << target;
        EXPECT_EQ(json::parse(r.body())["error"]["code"], "unauthorized");
        EXPECT_EQ(r[http::field::www_authenticate], "Bearer realm=\"radiantd\"");
    }
    const Response alive = s.get("/healthz");
    EXPECT_EQ(alive.result(), http::status::ok);
    EXPECT_EQ(json::parse(alive.body())["store"], "writable") << alive.body();
    EXPECT_EQ(s.get("/readyz").result(), http::status::ok) << "probes carry no token";
    Request wrong{http::verb::get, "/v1/jobs", 11};
    wrong.set(http::field::authorization, "Bearer s3cret-tokeN");
    EXPECT_EQ(s.send(wrong).result(), http::status::unauthorized);
    const Response refused =
        s.send(scene_request(radiant::test::tiny_room(), {{"Content-Type", "application/json"},
                                                          {"Authorization", "Bearer s3cret"}}));
    EXPECT_EQ(refused.result(), http::status::unauthorized);
    EXPECT_EQ(s.store().list(10, "").size(), 0u) << "a refused request changes nothing";
    const Response accepted = s.send(scene_request(
        radiant::test::tiny_room(),
        {{"Content-Type", "application/json"}, {"Authorization", "bearer s3cret-token"}}));
    EXPECT_EQ(accepted.result(), http::status::accepted) << accepted.body();
}

TEST_P(RouterTest, ForeignHostsAreRefusedAgainstDnsRebinding) {
    Service s(store());
    Request request{http::verb::get, "/v1/jobs", 11};
    for (const char* host : {"localhost:8080", "127.0.0.1:8080", "[::1]:8080", "LOCALHOST"}) {
        request.set(http::field::host, host);
        EXPECT_EQ(s.send(request).result(), http::status::ok) << host;
    }
    for (const char* host : {"evil.example:8080", "127.0.0.1.evil.example", "localhost.evil"}) {
        request.set(http::field::host, host);
        const Response r = s.send(request);
        EXPECT_EQ(r.result(), http::status::forbidden) << host;
        EXPECT_EQ(json::parse(r.body())["error"]["code"], "host_not_allowed");
    }
    request.set(http::field::host, "render-farm:8080");
    s.context().access.allowed_hosts = {"render-farm"};
    EXPECT_EQ(s.send(request).result(), http::status::ok);
    s.context().listen_host = "10.1.2.3";
    request.set(http::field::host, "10.1.2.3:8080");
    EXPECT_EQ(s.send(request).result(), http::status::ok) << "the listen address";
}

TEST_P(RouterTest, CrossOriginBrowserRequestsNeedAnAllowedOrigin) {
    Service s(store());
    const auto post_from = [&](const char* origin) {
        return s.send(
            scene_request(radiant::test::tiny_room(), {{"Content-Type", "application/json"},
                                                       {"Host", "127.0.0.1:8080"},
                                                       {"Origin", origin}}));
    };
    const Response foreign = post_from("https://evil.example");
    EXPECT_EQ(foreign.result(), http::status::forbidden);
    EXPECT_EQ(json::parse(foreign.body())["error"]["code"], "origin_not_allowed");
    EXPECT_EQ(s.store().list(10, "").size(), 0u);
    EXPECT_EQ(post_from("http://127.0.0.1:8080").result(), http::status::accepted)
        << "the page's own origin";

    s.context().access.cors_origins = {"https://app.example"};
    const Response allowed = post_from("https://app.example");
    EXPECT_EQ(allowed.result(), http::status::accepted);
    EXPECT_EQ(allowed[http::field::access_control_allow_origin], "https://app.example");
    EXPECT_EQ(allowed[http::field::vary], "Origin");

    Request preflight{http::verb::options, "/v1/jobs", 11};
    preflight.set(http::field::origin, "https://app.example");
    preflight.set(http::field::access_control_request_method, "POST");
    const Response answer = s.send(preflight);
    EXPECT_EQ(answer.result(), http::status::no_content);
    EXPECT_EQ(answer[http::field::access_control_allow_origin], "https://app.example");
    EXPECT_NE(answer[http::field::access_control_allow_headers].find("Content-Type"),
              std::string::npos);
    preflight.set(http::field::origin, "https://evil.example");
    EXPECT_EQ(s.send(preflight).result(), http::status::forbidden);
}

TEST(AccessPolicy, ConstantTimeEqual) {
    EXPECT_TRUE(constant_time_equal("abc", "abc"));
    EXPECT_FALSE(constant_time_equal("abc", "abd"));
    EXPECT_FALSE(constant_time_equal("abc", "abcd"));
    EXPECT_FALSE(constant_time_equal("", "a"));
    EXPECT_TRUE(constant_time_equal("", ""));
}

/// A scene of tests/data/warnings, with `settings` added.
std::string mistake(const std::string& name, const json& settings = json::object()) {
    json scene =
        json::parse(radiant::test::read_text(std::string(RADIANT_TEST_DATA) + "/warnings/" + name));
    scene["settings"] = settings;
    return scene.dump();
}

TEST_P(RouterTest, StrictSceneWithWarningsIs400WithTheirPointersAndQueuesNothing) {
    Service s(store());
    const Response r = s.post(mistake("luminaire-above-ceiling.json", {{"strict", true}}));
    ASSERT_EQ(r.result(), http::status::bad_request) << r.body();
    const json error = json::parse(r.body())["error"];
    EXPECT_EQ(error["code"], "strict_warnings");
    EXPECT_EQ(error["pointer"], "/luminaires/0/position");
    ASSERT_EQ(error["problems"].size(), 1u) << error;
    EXPECT_TRUE(error["message"].get<std::string>().ends_with(" [luminaire_behind_surface]"))
        << error;
    EXPECT_EQ(json::parse(s.get("/v1/jobs").body())["jobs"].size(), 0u);
    // Without warnings a strict scene is accepted.
    EXPECT_EQ(s.post(radiant::test::tiny_room(R"({"tolerance": 0.1, "strict": true})")).result(),
              http::status::accepted);
}

TEST_P(RouterTest, JobsAndResultsCarryTheWarnings) {
    Service s(store());
    const std::string warned =
        id_of(s.post(mistake("ceiling-wound-wrong.json", {{"tolerance", 0.1}})));
    const std::string clean = id_of(s.post(radiant::test::tiny_room()));
    const json job = s.wait_for(warned, "done");
    ASSERT_EQ(job["status"], "done") << job;
    ASSERT_EQ(job["warnings"].size(), 1u) << job;
    EXPECT_EQ(job["warnings"][0]["code"], "back_face_light");
    EXPECT_EQ(job["warnings"][0]["pointer"], "/surfaces/5");
    const json result = json::parse(s.get("/v1/jobs/" + warned + "/result").body());
    EXPECT_EQ(result["warnings"], job["warnings"]);
    EXPECT_EQ(s.wait_for(clean, "done")["warnings"], json::array());
    // The store keeps them: a listing reads them back from it.
    const json listed = json::parse(s.get("/v1/jobs").body())["jobs"];
    const auto stored = std::find_if(listed.begin(), listed.end(),
                                     [&](const json& j) { return j["id"] == warned; });
    ASSERT_NE(stored, listed.end()) << listed;
    EXPECT_EQ((*stored)["warnings"], job["warnings"]);
}

TEST_P(RouterTest, AStrictSolveThatEndsWithAWarningFails) {
    Service s(store());
    const std::string id =
        id_of(s.post(radiant::test::tiny_room(R"({"tolerance": 0.001, "max_seconds": 0.05,
                                                  "strict": true})")));
    const json job = s.wait_for(id, "failed");
    ASSERT_EQ(job["status"], "failed") << job;
    EXPECT_NE(job["error"].get<std::string>().find("time_limit"), std::string::npos) << job;
    ASSERT_EQ(job["warnings"].size(), 1u) << job;
    EXPECT_EQ(job["warnings"][0]["pointer"], "/settings/max_seconds");
}

TEST(Query, ParsesAndDecodes) {
    const Query q = parse_query("limit=5&after=a%20b&flag&x=1+2");
    EXPECT_EQ(q.at("limit"), "5");
    EXPECT_EQ(q.at("after"), "a b");
    EXPECT_EQ(q.at("flag"), "");
    EXPECT_EQ(q.at("x"), "1 2");
}

TEST(Config, ParseListen) {
    EXPECT_EQ(parse_listen("127.0.0.1:8080")->port, 8080);
    EXPECT_EQ(parse_listen("[::1]:0")->host, "::1");
    EXPECT_FALSE(parse_listen("localhost"));
    EXPECT_FALSE(parse_listen("a:99999"));
    EXPECT_EQ(iso8601(0), "1970-01-01T00:00:00.000Z");
}

}  // namespace
