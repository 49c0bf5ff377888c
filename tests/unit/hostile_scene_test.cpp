// Hostile scene documents: each is refused (or read) at a cost bounded by the documented limits,
// checked on totals before anything is expanded, and never crashes the reader.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "glb_writer.h"
#include "radiant/proto/honeybee.h"
#include "radiant/proto/scene_json.h"

namespace radiant::proto {
namespace {

using Json = nlohmann::ordered_json;

Json room(const Json& surface) {
    return {{"format", "radiant-scene/1"},
            {"materials", {{"wall", {{"reflectance", 0.5}}}}},
            {"surfaces", Json::array({surface})}};
}

Json gltf_surface(const std::string& glb) {
    return {{"name", "model"}, {"material", "wall"}, {"gltf", test::base64(glb)}};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(HostileScene, GltfNodeChainIsWalkedWithoutRecursion) {
    // 100,000 nested nodes overflowed the 8 MB stack of a recursive walk.
    const ParseOutcome outcome =
        parse_scene(room(gltf_surface(test::node_graph_glb(100000, 0))).dump());
    ASSERT_TRUE(outcome.ok()) << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
    EXPECT_EQ(std::get<MeshGeometry>(outcome.scene->surfaces[0].geometry).faces.size(), 1u);
}

TEST(HostileScene, GltfInstancesCountAgainstTheVertexLimitBeforeExpansion) {
    ParseLimits limits;
    limits.scene.max_vertices = 300;
    const std::string scene = room(gltf_surface(test::node_graph_glb(0, 1000))).dump();
    const ParseOutcome outcome = parse_scene(scene, limits);
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/surfaces/0/gltf");
    EXPECT_NE(outcome.problems[0].message.find("more than 300 vertices"), std::string::npos)
        << outcome.problems[0].message;
    limits.scene.max_vertices = 3000;
    EXPECT_TRUE(parse_scene(scene, limits).ok()) << "1000 instances of 3 vertices fit";
    limits.max_faces = 500;
    const ParseOutcome faces = parse_scene(scene, limits);
    ASSERT_EQ(faces.problems.size(), 1u);
    EXPECT_EQ(faces.problems[0].pointer, "/surfaces/0/gltf");
    EXPECT_NE(faces.problems[0].message.find("more than 500 faces"), std::string::npos)
        << faces.problems[0].message;
}

TEST(HostileScene, GltfJsonNestingIsRefusedBeforeTinygltfRecurses) {
    const std::string deep = std::string(200000, '[') + std::string(200000, ']');
    const std::string gltf = R"({"asset": {"version": "2.0", "extras": )" + deep + "}}";
    const ParseOutcome outcome = parse_scene(room(gltf_surface(gltf)).dump());
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/surfaces/0/gltf");
    EXPECT_NE(outcome.problems[0].message.find("nested deeper than 64"), std::string::npos)
        << outcome.problems[0].message;
}

Json grid_sensor(int n) {
    return {{"name", "g"},
            {"normal", {0, 0, 1}},
            {"grid",
             {{"origin", {0, 0, 1}}, {"u", {1, 0, 0}}, {"v", {0, 1, 0}}, {"nu", n}, {"nv", n}}}};
}

TEST(HostileScene, GridsAreLimitedOnTheirTotalBeforeExpansion) {
    ParseLimits limits;
    limits.scene.max_sensor_points = 100;
    Json doc = room(
        {{"name", "floor"}, {"material", "wall"}, {"polygon", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}}});
    doc["sensors"] = {grid_sensor(7), grid_sensor(8)};  // 49 + 64 points: each fits alone
    const ParseOutcome outcome = parse_scene(doc.dump(), limits);
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/sensors/1/grid");
    EXPECT_NE(outcome.problems[0].message.find("with the 49 sensor points before it"),
              std::string::npos)
        << outcome.problems[0].message;
}

TEST(HostileScene, AThousandMillionPointGridsCostOneGrid) {
    // 1,000 grid sets of 10⁶ points each in a few kilobytes: expanding them all would take 24 GB.
    Json doc = room(
        {{"name", "floor"}, {"material", "wall"}, {"polygon", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}}});
    doc["sensors"] = Json::array();
    for (int k = 0; k < 1000; ++k) doc["sensors"].push_back(grid_sensor(1000));
    const auto start = std::chrono::steady_clock::now();
    const ParseOutcome outcome = parse_scene(doc.dump());
    EXPECT_LT(seconds_since(start), 10.0);
    ASSERT_FALSE(outcome.ok());
    EXPECT_EQ(outcome.problems[0].pointer, "/sensors/1/grid");
    EXPECT_EQ(outcome.problems.size(), kMaxListedProblems + 1) << "listed, then counted";
    EXPECT_EQ(outcome.problems.back().message, "899 more problems are not listed");
}

TEST(HostileScene, DeepNestingIsRefusedAtItsPointerWithoutBuildingIt) {
    const ParseOutcome outcome = parse_scene(std::string(60'000'000, '['));
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.refusal, Refusal::over_budget);
    EXPECT_EQ(outcome.problems[0].message, "nested deeper than 64 levels");
    EXPECT_EQ(outcome.problems[0].pointer.size(), 64 * 2u) << "/0 for each level";
}

/// Seconds to parse a scene with `count` materials. The text is written by hand: building it
/// with ordered_json would itself be quadratic.
double seconds_to_parse_materials(int count) {
    std::string text = R"({"format": "radiant-scene/1", "materials": {)";
    for (int k = 0; k < count; ++k) {
        text += "\"m";  // appended: GCC 12 misreads "m" + std::to_string(k) (-Wrestrict)
        text += std::to_string(k);
        text += "\": {\"reflectance\": 0.5}, ";
    }
    text += R"("wall": {"reflectance": 0.5}}, "surfaces": [{"name": "floor", "material": "wall",
        "polygon": [[0, 0, 0], [1, 0, 0], [1, 1, 0]]}]})";
    const auto start = std::chrono::steady_clock::now();
    const ParseOutcome outcome = parse_scene(text);
    const double seconds = seconds_since(start);
    EXPECT_TRUE(outcome.ok());
    EXPECT_EQ(outcome.scene->materials.size(), static_cast<std::size_t>(count) + 1);
    return seconds;
}

TEST(HostileScene, ManyKeysParseInLinearTime) {
    // ordered_json looked each new key up in a vector: 4 times the keys took 16 times as long
    // (200,000 keys, minutes). Compared with itself, so that a busy machine does not matter.
    const double small = seconds_to_parse_materials(50000);
    const double large = seconds_to_parse_materials(200000);
    EXPECT_LT(large, 8 * small + 0.5) << small << " s for 50,000 keys";
}

TEST(HostileScene, BudgetCountsKeysValuesAndContainers) {
    const std::string text = room({{"name", "floor"},
                                   {"material", "wall"},
                                   {"polygon", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}}})
                                 .dump();
    ParseLimits keys;
    keys.json.max_keys = 5;
    ParseLimits values;
    values.json.max_values = 10;
    ParseLimits containers;
    containers.json.max_containers = 4;
    for (const ParseLimits& limits : {keys, values, containers}) {
        const ParseOutcome outcome = parse_scene(text, limits);
        ASSERT_EQ(outcome.problems.size(), 1u);
        EXPECT_EQ(outcome.refusal, Refusal::over_budget);
        EXPECT_EQ(outcome.problems[0].message.rfind("more than ", 0), 0u)
            << outcome.problems[0].message;
        EXPECT_FALSE(outcome.problems[0].pointer.empty());
    }
    EXPECT_TRUE(parse_scene(text).ok());
}

TEST(HostileScene, DuplicateKeysAreRefusedAtTheKey) {
    const ParseOutcome outcome = parse_scene(
        R"({"format": "radiant-scene/1", "materials": {"wall": {"reflectance": 0.5, "reflectance": 0.9}}, "surfaces": []})");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.refusal, Refusal::not_json);
    EXPECT_EQ(outcome.problems[0].pointer, "/materials/wall/reflectance");
    EXPECT_EQ(outcome.problems[0].message, "duplicate key \"reflectance\"");
    std::string big = "{";
    for (int k = 0; k < 100; ++k) big += "\"k" + std::to_string(k) + "\": 1, ";
    big += "\"k7\": 2}";
    const ParseOutcome sorted = parse_scene(big);
    ASSERT_EQ(sorted.problems.size(), 1u);
    EXPECT_EQ(sorted.problems[0].pointer, "/k7");
}

TEST(HostileScene, InvalidUtf8IsRefusedAtTheString) {
    const ParseOutcome outcome =
        parse_scene("{\"format\": \"radiant-scene/1\", \"name\": \"caf\xe9\", \"surfaces\": []}");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.refusal, Refusal::not_json);
    EXPECT_EQ(outcome.problems[0].pointer, "/name");
    EXPECT_EQ(outcome.problems[0].message.rfind("invalid UTF-8 in a string (line 1, column ", 0),
              0u)
        << outcome.problems[0].message;
    const ParseOutcome outside = parse_scene("{\"format\": \xff}");
    ASSERT_EQ(outside.problems.size(), 1u);
    EXPECT_TRUE(nlohmann::json::accept(Json(outside.problems[0].message).dump()))
        << "the message quotes the bytes as valid JSON text";
}

TEST(HostileScene, MillionsOfBadValuesGiveAShortList) {
    Json polygon = Json::array();
    for (int k = 0; k < 100000; ++k) polygon.push_back({"x", 0, 0});
    const ParseOutcome outcome =
        parse_scene(room({{"name", "s"}, {"material", "wall"}, {"polygon", polygon}}).dump());
    ASSERT_EQ(outcome.problems.size(), kMaxListedProblems + 1);
    EXPECT_EQ(outcome.problems.back().message, "99900 more problems are not listed");
}

TEST(HostileScene, HoneybeeGridWithManyDirectionsConvertsInLinearTime) {
    Json sensors = Json::array();
    for (int k = 0; k < 50000; ++k) {
        sensors.push_back(
            {{"pos", {0.5, 0.5, 0.8}}, {"dir", {0, std::sin(k * 1e-5), std::cos(k * 1e-5)}}});
    }
    const Json model = {
        {"type", "Model"},
        {"orphaned_shades",
         {{{"identifier", "s"},
           {"geometry", {{"type", "Face3D"}, {"boundary", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}}}}}}},
        {"properties",
         {{"radiance", {{"sensor_grids", {{{"identifier", "g"}, {"sensors", sensors}}}}}}}}};
    const auto start = std::chrono::steady_clock::now();
    const HoneybeeOutcome outcome = honeybee_to_scene(model.dump());
    EXPECT_LT(seconds_since(start), 10.0);
    ASSERT_TRUE(outcome.problems.empty())
        << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
    EXPECT_EQ((*outcome.scene)["sensors"].size(), 50000u);
}

TEST(HostileScene, HoneybeeFaceWithHolesIsLimitedBeforeEarClipping) {
    Json boundary = Json::array();
    for (int k = 0; k < 5000; ++k) {
        const double a = 2 * 3.141592653589793 * k / 5000;
        boundary.push_back({10 * std::cos(a), 10 * std::sin(a), 0});
    }
    const Json hole = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    const Json model = {
        {"type", "Model"},
        {"orphaned_shades",
         {{{"identifier", "s"},
           {"geometry",
            {{"type", "Face3D"}, {"boundary", boundary}, {"holes", Json::array({hole})}}}}}}};
    const HoneybeeOutcome outcome = honeybee_to_scene(model.dump());
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/orphaned_shades/0/geometry/holes");
    EXPECT_EQ(outcome.problems[0].message,
              "a face with holes may have at most 1000 vertices, not 5003");
}

}  // namespace
}  // namespace radiant::proto
