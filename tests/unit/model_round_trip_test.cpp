// The same furnished room three ways — native polygons and boxes, an OBJ export and a glTF
// export of the same faces — solves to the same sensor values within the solve tolerance.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glb_writer.h"
#include "gltf_axes.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Quad = std::array<Vec3, 4>;

constexpr double kTolerance = 0.02;

/// Faces of an axis-aligned box, counter-clockwise seen from outside (or inside when `inward`).
std::vector<Quad> box_faces(const Vec3& lo, const Vec3& hi, bool inward) {
    const auto at = [&](int i) {
        return Vec3{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    };
    // Corner indices of each face, counter-clockwise seen from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<Quad> out;
    for (const auto& f : faces) {
        Quad q{at(f[0]), at(f[1]), at(f[2]), at(f[3])};
        if (inward) std::swap(q[1], q[3]);
        out.push_back(q);
    }
    return out;
}

std::vector<Quad> room_faces() {
    std::vector<Quad> faces = box_faces({0, 0, 0}, {5, 4, 3}, true);
    for (const Quad& q : box_faces({1.5, 1.2, 0.7}, {3.1, 2.0, 0.75}, false)) faces.push_back(q);
    return faces;
}

Json base_scene() {
    return {{"format", "radiant-scene/1"},
            {"name", "round-trip"},
            {"materials", {{"wall", {{"reflectance", 0.6}}}}},
            {"luminaires",
             {{{"name", "L"},
               {"position", {2.5, 1.0, 2.6}},
               {"flux", 3000},
               {"distribution", "lambertian"}}}},
            {"sensors",
             {{{"name", "grid"},
               {"grid",
                {{"origin", {0.25, 0.25, 0.8}},
                 {"u", {4.5, 0, 0}},
                 {"v", {0, 3.5, 0}},
                 {"nu", 6},
                 {"nv", 5}}},
               {"normal", {0, 0, 1}}}}},
            {"settings", {{"tolerance", kTolerance}}}};
}

std::string obj_text(const std::vector<Quad>& faces) {
    std::ostringstream out;
    out.precision(17);
    for (const Quad& q : faces) {
        for (const Vec3& v : q) out << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    }
    for (std::size_t f = 0; f < faces.size(); ++f) {
        out << "f " << 4 * f + 1 << ' ' << 4 * f + 2 << ' ' << 4 * f + 3 << ' ' << 4 * f + 4
            << '\n';
    }
    return out.str();
}

/// A self-contained .glb of the faces as triangles, y up as glTF wants.
std::string glb_bytes(const std::vector<Quad>& faces) {
    std::vector<float> positions;
    std::vector<std::uint32_t> indices;
    for (const Quad& q : faces) {
        const auto base = static_cast<std::uint32_t>(positions.size() / 3);
        for (const Vec3& v : q) {
            const Vec3 g = to_gltf_axes(v);
            positions.insert(positions.end(), {static_cast<float>(g.x), static_cast<float>(g.y),
                                               static_cast<float>(g.z)});
        }
        indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return test::single_primitive_glb(positions, indices, TINYGLTF_MODE_TRIANGLES);
}

class ModelRoundTrip : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("radiant_round_trip_" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::vector<double> solve_file(const Json& scene) {
        std::ofstream(dir_ / "scene.json") << scene.dump();
        const ParseOutcome outcome = load_scene_file(dir_ / "scene.json");
        EXPECT_TRUE(outcome.ok()) << (outcome.ok() ? ""
                                                   : outcome.problems[0].pointer + ": " +
                                                         outcome.problems[0].message);
        if (!outcome.ok()) return {};
        const Result result = solve(*outcome.scene, options_from(outcome.scene->settings));
        EXPECT_EQ(result.status, SolveStatus::converged) << result.error;
        return result.sensors.at(0).illuminance;
    }

    fs::path dir_;
};

TEST_F(ModelRoundTrip, ObjAndGltfExportsGiveTheNativeResult) {
    Json native = base_scene();
    native["surfaces"] = Json::array(
        {{{"name", "room"},
          {"material", "wall"},
          {"box", {{"min", {0, 0, 0}}, {"max", {5, 4, 3}}, {"facing", "in"}}}},
         {{"name", "desk"},
          {"material", "wall"},
          {"box", {{"min", {1.5, 1.2, 0.7}}, {"max", {3.1, 2.0, 0.75}}, {"facing", "out"}}}}});
    Json from_obj = base_scene();
    from_obj["surfaces"] =
        Json::array({{{"name", "model"}, {"material", "wall"}, {"obj", obj_text(room_faces())}}});
    std::ofstream(dir_ / "room.glb", std::ios::binary) << glb_bytes(room_faces());
    Json from_gltf = base_scene();
    from_gltf["surfaces"] =
        Json::array({{{"name", "model"}, {"material", "wall"}, {"gltf_file", "room.glb"}}});

    const std::vector<double> reference = solve_file(native);
    ASSERT_EQ(reference.size(), 30u);
    double mean = 0;
    for (const double e : reference) mean += e / static_cast<double>(reference.size());
    ASSERT_GT(mean, 0);
    for (const auto* variant : {&from_obj, &from_gltf}) {
        const std::vector<double> got = solve_file(*variant);
        ASSERT_EQ(got.size(), reference.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
            EXPECT_NEAR(got[i] / mean, reference[i] / mean, kTolerance)
                << (variant == &from_obj ? "obj" : "gltf") << " point " << i;
        }
    }
}

}  // namespace
}  // namespace radiant::proto
