// The acceptance check of issue 4 for streaming: on a solve of several seconds the event stream
// carries a radiosity snapshot at least every second of solve time, in one id sequence with
// progress and done, and its final values are the stored result's mesh.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/proto/base64.h"

#include "daemon.h"
#include "sse.h"
#include "store_under_test.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using boost::beast::http::verb;
using nlohmann::json;
using radiant::test::Daemon;
using radiant::test::http_call;
using radiant::test::parse_sse;
using radiant::test::SseEvent;

/// The example office, solved hierarchically: several seconds on two cores (its default, the
/// Monte Carlo method, takes a fraction of one).
std::string office() {
    json scene = json::parse(
        radiant::test::read_text(fs::path(RADIANT_SOURCE_DIR) / "proto/examples/office.json"));
    scene["settings"]["method"] = "hierarchical";
    return scene.dump();
}

class RadiosityStream : public radiant::test::StoreTest {
protected:
    void SetUp() override {
        StoreTest::SetUp();
        if (IsSkipped()) return;
        dir_ = fs::temp_directory_path() / ("radiant_stream_test_" + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        if (HasFailure()) std::cerr << radiant::test::read_text(dir_ / "radiantd.log") << '\n';
        fs::remove_all(dir_);
    }
    fs::path dir_;
};
INSTANTIATE_TEST_SUITE_P(Stores, RadiosityStream, radiant::test::both_stores(),
                         radiant::test::store_name);

/// The values of a base64 float32 (or int32) array of an event.
template <typename T>
std::vector<T> values(const json& base64) {
    const auto bytes = radiant::proto::decode_base64(base64.get<std::string>());
    EXPECT_TRUE(bytes && bytes->size() % sizeof(T) == 0);
    std::vector<T> out(bytes ? bytes->size() / sizeof(T) : 0);
    if (bytes) std::memcpy(out.data(), bytes->data(), sizeof(T) * out.size());
    return out;
}

/// A JSON array of numbers as floats (the stored mesh's float32 values, written shortest).
std::vector<float> as_floats(const json& array, bool nested = false) {
    std::vector<float> out;
    for (const json& v : array) {
        if (nested) {
            for (const json& c : v) out.push_back(c.get<float>());
        } else {
            out.push_back(v.get<float>());
        }
    }
    return out;
}

TEST_P(RadiosityStream, AtLeastOneSnapshotPerSecondAndTheFinalOneIsTheResult) {
    Daemon d(dir_ / "data", flags(), dir_ / "radiantd.log");
    const auto posted = http_call(d.port(), verb::post, "/v1/jobs", office());
    ASSERT_EQ(posted.status, 202u) << posted.body;
    const std::string id = json::parse(posted.body)["id"];
    const std::string job = "/v1/jobs/" + id;

    const auto stream = http_call(d.port(), verb::get, job + "/events");
    ASSERT_EQ(stream.status, 200u);
    const std::vector<SseEvent> events = parse_sse(stream.body);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back().name, "done");

    std::uint64_t previous_id = 0;
    std::uint64_t mesh_seen = 0;
    std::vector<json> radiosity;
    json mesh;
    std::set<std::uint64_t> values_sent;  // radiosity events that carried their arrays
    std::size_t repeats = 0, repeat_bytes = 0;
    for (const SseEvent& e : events) {
        EXPECT_GT(e.id, previous_id) << e.name << " ids must increase";
        previous_id = e.id;
        if (e.name == "mesh") {
            mesh = json::parse(e.data);
            mesh_seen = mesh["mesh_version"];
        } else if (e.name == "radiosity") {
            radiosity.push_back(json::parse(e.data));
            const json& r = radiosity.back();
            EXPECT_EQ(r["mesh_version"], mesh_seen) << "mesh before radiosity";
            if (r.contains("values_event")) {
                // A repeat of values this connection already has: no arrays, a few hundred bytes.
                EXPECT_TRUE(values_sent.contains(r["values_event"])) << r.dump();
                EXPECT_FALSE(r.contains("vertex_radiosity"));
                ++repeats;
                repeat_bytes = std::max(repeat_bytes, e.data.size());
            } else {
                values_sent.insert(e.id);
                EXPECT_EQ(3 * values<float>(r["triangle_radiosity"]).size(),
                          values<std::int32_t>(mesh["triangles"]).size());
                EXPECT_EQ(3 * values<float>(r["vertex_radiosity"]).size(),
                          values<float>(mesh["vertices"]).size());
            }
        }
    }
    ASSERT_GE(radiosity.size(), 2u) << stream.body.substr(0, 2000);
    // While the hierarchical solver links, gathers sensors and checks its mesh it repeats its
    // values; those repeats must not resend them.
    EXPECT_GT(repeats, 0u);
    EXPECT_LT(repeat_bytes, 1000u);

    const json status = json::parse(http_call(d.port(), verb::get, job).body);
    ASSERT_EQ(status["status"], "done");
    const double solve_seconds = status["progress"]["elapsed_seconds"];
    EXPECT_GT(solve_seconds, 1.0) << "the scene should keep the solver busy for a while";
    // Radiosity events per second of solve, and no second of solve without one (from the
    // first mesh on; meshing and visibility come before any mesh exists).
    const double first = radiosity.front()["elapsed_seconds"];
    EXPECT_LT(first, 1.0);
    double longest_gap = 0;
    for (std::size_t k = 1; k < radiosity.size(); ++k) {
        const double gap = radiosity[k]["elapsed_seconds"].get<double>() -
                           radiosity[k - 1]["elapsed_seconds"].get<double>();
        longest_gap = std::max(longest_gap, gap);
    }
    EXPECT_LT(longest_gap, 1.0);
    EXPECT_GE(static_cast<double>(radiosity.size()), solve_seconds)
        << radiosity.size() << " radiosity events in " << solve_seconds << " s";
    // Bounded rate: at most two a second, plus the final one.
    EXPECT_LE(static_cast<double>(radiosity.size()), 2 * solve_seconds + 2);

    const json& last = radiosity.back();
    EXPECT_TRUE(last["final"].get<bool>());
    const auto result = http_call(d.port(), verb::get, job + "/result?include=mesh");
    ASSERT_EQ(result.status, 200u);
    const json stored = json::parse(result.body);
    EXPECT_EQ(stored["status"], "converged");
    ASSERT_TRUE(stored.contains("mesh"));
    EXPECT_EQ(values<float>(last["triangle_radiosity"]),
              as_floats(stored["mesh"]["triangle_radiosity"]));
    EXPECT_EQ(values<float>(last["vertex_radiosity"]),
              as_floats(stored["mesh"]["vertex_radiosity"]));
    std::vector<std::int32_t> triangles;
    for (const json& t : stored["mesh"]["triangles"]) {
        for (const json& v : t) triangles.push_back(v.get<std::int32_t>());
    }
    EXPECT_EQ(values<std::int32_t>(mesh["triangles"]), triangles);
    EXPECT_EQ(values<float>(mesh["vertices"]), as_floats(stored["mesh"]["vertices"], true));
    EXPECT_FALSE(
        json::parse(http_call(d.port(), verb::get, job + "/result").body).contains("mesh"));

    // Resuming: a client that missed the last mesh event gets it again; one that saw it does not.
    std::uint64_t mesh_id = 0;
    for (const SseEvent& e : events) {
        if (e.name == "mesh") mesh_id = e.id;
    }
    auto resumed_names = [&](std::uint64_t last_id) {
        std::string names;
        const auto r = http_call(d.port(), verb::get, job + "/events", "",
                                 {{"Last-Event-ID", std::to_string(last_id)}});
        for (const SseEvent& e : parse_sse(r.body)) names += e.name + " ";
        return names;
    };
    EXPECT_EQ(resumed_names(mesh_id - 1), "mesh radiosity progress done ");
    EXPECT_EQ(resumed_names(mesh_id), "radiosity progress done ");
}

}  // namespace
