#include "radiant/proto/scene_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_files.h"

namespace radiant::proto {
namespace {

const char* const kMinimal = R"({
  "format": "radiant-scene/1",
  "materials": { "m": { "reflectance": 0.5 } },
  "surfaces": [ { "name": "s", "material": "m", "polygon": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]] } ]
})";

std::vector<std::string> pointers(const ParseOutcome& outcome) {
    std::vector<std::string> out;
    for (const Problem& p : outcome.problems) out.push_back(p.pointer);
    return out;
}

/// The minimal scene with `patch` merged in (RFC 7386), to state each case as a small diff;
/// ordered_json keeps key order, which the material order test relies on.
ParseOutcome parse_patched(const char* patch) {
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(kMinimal);
    doc.merge_patch(nlohmann::ordered_json::parse(patch));
    return parse_scene(doc.dump());
}

TEST(SceneJson, GoodScenesParse) {
    for (const auto& file : test::good_scenes()) {
        const ParseOutcome outcome = load_scene_file(file);
        EXPECT_TRUE(outcome.ok()) << file << ": "
                                  << (outcome.ok() ? "" : format_problem("", outcome.problems[0]));
        EXPECT_EQ(outcome.scene.has_value(), outcome.ok());
    }
}

TEST(SceneJson, MinimalSceneMapsToEngineTypes) {
    const ParseOutcome outcome = parse_scene(kMinimal);
    ASSERT_TRUE(outcome.ok());
    const Scene& scene = *outcome.scene;
    EXPECT_EQ(scene.units, LengthUnit::m);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].reflectance, (Rgb{0.5, 0.5, 0.5}));
    EXPECT_FALSE(scene.materials[0].rgb_reflectance);
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(std::get<Polygon>(scene.surfaces[0].geometry).size(), 4u);
    EXPECT_EQ(scene.settings.method, "auto");
}

TEST(SceneJson, MaterialsKeepDocumentOrderAndRgb) {
    const ParseOutcome outcome = parse_patched(
        R"({"materials": {"zeta": {"reflectance": [0.1, 0.2, 0.3]}, "alpha": {"reflectance": 0.4,
            "emission": {"flux": 5, "color": [1, 1, 1]}, "two_sided": true}}})");
    ASSERT_TRUE(outcome.ok()) << outcome.problems[0].pointer << outcome.problems[0].message;
    const auto& m = outcome.scene->materials;
    ASSERT_EQ(m.size(), 3u);
    EXPECT_EQ(m[0].name, "m");
    EXPECT_EQ(m[1].name, "zeta");
    EXPECT_TRUE(m[1].rgb_reflectance);
    EXPECT_EQ(m[1].reflectance, (Rgb{0.1, 0.2, 0.3}));
    EXPECT_EQ(m[2].name, "alpha");
    ASSERT_TRUE(m[2].emission);
    EXPECT_EQ(m[2].emission->kind, Emission::Kind::flux);
    EXPECT_TRUE(m[2].two_sided);
}

TEST(SceneJson, GridExpandsRowMajorUFastest) {
    const ParseOutcome outcome = parse_patched(R"({"sensors": [{"name": "g", "normal": [0,0,1],
        "grid": {"origin": [0,0,1], "u": [2,0,0], "v": [0,4,0], "nu": 2, "nv": 2}}]})");
    ASSERT_TRUE(outcome.ok());
    const auto& points = outcome.scene->sensors[0].points;
    ASSERT_EQ(points.size(), 4u);
    EXPECT_EQ(points[0], (Vec3{0.5, 1, 1}));
    EXPECT_EQ(points[1], (Vec3{1.5, 1, 1}));
    EXPECT_EQ(points[2], (Vec3{0.5, 3, 1}));
    EXPECT_EQ(points[3], (Vec3{1.5, 3, 1}));
}

TEST(SceneJson, UnitsAreKeptNotConverted) {
    const ParseOutcome outcome = parse_patched(R"({"units": "mm"})");
    ASSERT_TRUE(outcome.ok());
    EXPECT_EQ(outcome.scene->units, LengthUnit::mm);
    EXPECT_EQ(std::get<Polygon>(outcome.scene->surfaces[0].geometry)[1], (Vec3{1, 0, 0}));
}

TEST(SceneJson, LuminaireDefaults) {
    const ParseOutcome outcome =
        parse_patched(R"({"luminaires": [{"name": "l", "position": [0,0,1], "flux": 10}]})");
    ASSERT_TRUE(outcome.ok());
    EXPECT_EQ(outcome.scene->luminaires[0].distribution, Distribution::isotropic);
    EXPECT_EQ(outcome.scene->luminaires[0].aim, (Vec3{0, 0, -1}));
}

TEST(SceneJson, ReportsAllProblemsWithPointers) {
    const ParseOutcome outcome = parse_patched(R"({"bogus": 1,
        "materials": {"m": {"reflectance": 1.0}},
        "surfaces": [{"name": "s", "material": "foo", "polygon": [[0,0,0],[1,0,0],[1,"x",0]]}]})");
    EXPECT_FALSE(outcome.scene);
    EXPECT_EQ(pointers(outcome), (std::vector<std::string>{"/bogus", "/surfaces/0/polygon/2/1",
                                                           "/materials/m/reflectance"}));
}

TEST(SceneJson, SemanticProblemsOfIntactEntitiesAreReported) {
    const ParseOutcome outcome = parse_patched(R"({"bogus": 1,
        "surfaces": [{"name": "s", "material": "foo", "polygon": [[0,0,0],[1,0,0],[1,1,0]]}]})");
    EXPECT_EQ(pointers(outcome), (std::vector<std::string>{"/bogus", "/surfaces/0/material"}));
    EXPECT_EQ(outcome.problems[1].message, "unknown material \"foo\"");
}

TEST(SceneJson, OverflowingNumberIsRefusedAtItsPointer) {
    const ParseOutcome outcome = parse_scene(R"({"format": "radiant-scene/1",
        "materials": {}, "surfaces": [{"name": "s", "material": "m",
        "polygon": [[0,0,0],[1,0,0],[1,1e999,0]]}]})");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/surfaces/0/polygon/2/1");
}

TEST(SceneJson, SyntaxErrorGivesLineAndColumn) {
    const ParseOutcome outcome = parse_scene("{\n  \"format\": \"radiant-scene/1\",\n  ,\n}");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "");
    EXPECT_NE(outcome.problems[0].message.find("line 3, column 3"), std::string::npos)
        << outcome.problems[0].message;
}

TEST(SceneJson, GridProblemsPointAtTheGrid) {
    const ParseOutcome outcome = parse_patched(R"({"sensors": [{"name": "g", "normal": [0,0,1],
        "grid": {"origin": [0,0,1], "u": [1,0,0], "v": [0,1,0], "nu": 0, "nv": 2}}]})");
    EXPECT_EQ(pointers(outcome), (std::vector<std::string>{"/sensors/0/grid/nu"}));
}

TEST(SceneJson, EscapesPointerTokens) {
    const ParseOutcome outcome = parse_patched(R"({"materials": {"a/b~c": {"reflectance": -1}}})");
    EXPECT_EQ(pointers(outcome), (std::vector<std::string>{"/materials/a~1b~0c/reflectance"}));
}

TEST(SceneJson, DocumentSizeLimit) {
    ParseLimits limits;
    limits.max_bytes = 10;
    const ParseOutcome outcome = parse_scene(kMinimal, limits);
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "");
}

TEST(SceneJson, GridOverTheLimitIsNotExpanded) {
    ParseLimits limits;
    limits.scene.max_sensor_points = 100;
    nlohmann::json doc = nlohmann::json::parse(kMinimal);
    doc["sensors"] = nlohmann::json::parse(R"([{"name": "g", "normal": [0,0,1],
        "grid": {"origin": [0,0,1], "u": [1,0,0], "v": [0,1,0], "nu": 50, "nv": 50}}])");
    EXPECT_EQ(pointers(parse_scene(doc.dump(), limits)),
              (std::vector<std::string>{"/sensors/0/grid"}));
}

TEST(SceneJson, SurfaceLimitPointsAtTheArray) {
    ParseLimits limits;
    limits.scene.max_surfaces = 0;
    EXPECT_EQ(pointers(parse_scene(kMinimal, limits)), (std::vector<std::string>{"/surfaces"}));
}

TEST(SceneJson, IesTextThatIsNoFileIsRefusedAtItsPointer) {
    const ParseOutcome outcome = parse_patched(
        R"({"luminaires": [{"name": "l", "position": [0,0,1], "flux": 1, "distribution": {"ies": "x"}}]})");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/luminaires/0/distribution/ies");
    EXPECT_EQ(outcome.problems[0].message, "ies: no TILT= line: not an IES LM-63 file");
}

TEST(SceneJson, PhotometricDistributionNeedsOneFile) {
    const ParseOutcome outcome = parse_patched(
        R"({"luminaires": [{"name": "l", "position": [0,0,1], "distribution": {"ies": "x", "ldt": "y"}}]})");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/luminaires/0/distribution");
}

TEST(SceneJson, UnreadableFile) {
    const ParseOutcome outcome = load_scene_file("/nonexistent/scene.json");
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "");
}

TEST(SceneJson, FormatProblem) {
    EXPECT_EQ(format_problem("a.json", {"/surfaces/0", "bad"}), "a.json: /surfaces/0: bad");
}

}  // namespace
}  // namespace radiant::proto
