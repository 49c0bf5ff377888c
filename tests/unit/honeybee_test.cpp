// Honeybee models (HBJSON) → radiant-scene/1: geometry, orientation, materials, sensor grids,
// refusals at the HBJSON pointer, and `radiant import` end to end.
#include "radiant/proto/honeybee.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"
#include "scene_files.h"
#include "test_files.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

const fs::path kModel = testing::data_path("honeybee/office-window.hbjson");

Json model() { return Json::parse(test::read_text(kModel)); }

Json converted(const Json& hbjson) {
    const HoneybeeOutcome outcome = honeybee_to_scene(hbjson.dump());
    for (const Problem& p : outcome.problems) ADD_FAILURE() << p.pointer << ": " << p.message;
    return outcome.scene.value_or(Json());
}

const Json* surface(const Json& scene, const std::string& name) {
    for (const Json& s : scene["surfaces"])
        if (s["name"] == name) return &s;
    return nullptr;
}

/// The outcome's pointers, for refusal cases stated as patches on the test model.
std::vector<std::string> pointers_after(const char* pointer, const Json& value) {
    Json hb = model();
    hb[Json::json_pointer(pointer)] = value;
    std::vector<std::string> out;
    for (const Problem& p : honeybee_to_scene(hb.dump()).problems) out.push_back(p.pointer);
    return out;
}

TEST(Honeybee, RoomWithWindowBecomesInwardFacingPolygons) {
    const Json scene = converted(model());
    EXPECT_EQ(scene["format"], "radiant-scene/1");
    EXPECT_EQ(scene["name"], "office_with_window");
    EXPECT_EQ(scene["units"], "m");
    ASSERT_EQ(scene["surfaces"].size(), 8u) << "6 faces, 1 aperture, 1 shade";
    // The floor faced down (out of the room) in Honeybee; it faces up into the room now.
    const Json* floor = surface(scene, "floor");
    ASSERT_NE(floor, nullptr);
    const auto p = (*floor)["polygon"].get<std::vector<std::array<double, 3>>>();
    const Vec3 a{p[0][0], p[0][1], p[0][2]}, b{p[1][0], p[1][1], p[1][2]},
        c{p[2][0], p[2][1], p[2][2]};
    EXPECT_GT(cross(b - a, c - a).z, 0);
    EXPECT_EQ((*floor)["material"], "carpet");
    EXPECT_EQ(scene["materials"]["carpet"]["reflectance"], Json::array({0.3, 0.25, 0.2}));
    const Json* window = surface(scene, "south_window");
    ASSERT_NE(window, nullptr);
    EXPECT_EQ(scene["materials"][(*window)["material"].get<std::string>()]["reflectance"], 0.08);
    EXPECT_EQ(scene["materials"][(*surface(scene, "ceiling"))["material"].get<std::string>()]
                   ["reflectance"],
              0.8);
    EXPECT_EQ(scene["materials"][(*surface(scene, "overhang"))["material"].get<std::string>()]
                   ["two_sided"],
              true);
    ASSERT_EQ(scene["sensors"].size(), 1u);
    EXPECT_EQ(scene["sensors"][0]["name"], "workplane");
    EXPECT_EQ(scene["sensors"][0]["normal"], Json::array({0, 0, 1}));
    EXPECT_EQ(scene["sensors"][0]["points"].size(), 9u);
}

TEST(Honeybee, ImportedRoomSolvesAndTheWindowHidesTheWall) {
    Json scene = converted(model());
    scene["luminaires"] =
        Json::array({{{"name", "bulb"}, {"position", {2, 2, 2.5}}, {"flux", 1000}}});
    const ParseOutcome parsed = parse_scene(scene.dump());
    ASSERT_TRUE(parsed.ok()) << parsed.problems[0].pointer << ": " << parsed.problems[0].message;
    SolveOptions options;
    options.tolerance = 0.1;
    const Result result = solve(*parsed.scene, options);
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    ASSERT_EQ(result.sensors.size(), 1u);
    EXPECT_GT(result.sensors[0].min, 0);
    const SurfaceResult* south = testing::find_surface(result, "wall_south");
    const SurfaceResult* window = testing::find_surface(result, "south_window");
    ASSERT_TRUE(south && window);
    EXPECT_NEAR(window->area_m2, 1.5 * 1.2, 1e-9);
    // The dark window reflects less than the wall around it.
    EXPECT_LT(window->average_radiosity, south->average_radiosity);
}

TEST(Honeybee, AirBoundariesLetLightThroughAndGridsSplitByDirection) {
    Json hb = model();
    hb["rooms"][0]["faces"][5]["face_type"] = "AirBoundary";
    hb["properties"]["radiance"]["sensor_grids"][0]["sensors"][4]["dir"] = {1, 0, 0};
    const Json scene = converted(hb);
    EXPECT_EQ(surface(scene, "wall_west"), nullptr);
    ASSERT_EQ(scene["sensors"].size(), 2u);
    EXPECT_EQ(scene["sensors"][1]["name"], "workplane #2");
    EXPECT_EQ(scene["sensors"][1]["points"].size(), 1u);
}

TEST(Honeybee, FacesWithHolesBecomeMeshesThatLetLightOut) {
    Json hb = model();
    // A skylight opening (listed like the boundary) and a triangular one (listed the other way).
    hb["rooms"][0]["faces"][1]["geometry"]["holes"] =
        Json::array({Json::array({{1, 1, 3}, {2, 1, 3}, {2, 2, 3}, {1, 2, 3}}),
                     Json::array({{2.5, 2.5, 3}, {2.5, 3, 3}, {3, 3, 3}})});
    Json scene = converted(hb);
    const Json* ceiling = surface(scene, "ceiling");
    ASSERT_NE(ceiling, nullptr);
    ASSERT_TRUE(ceiling->contains("mesh"));
    const auto vertices = (*ceiling)["mesh"]["vertices"].get<std::vector<std::array<double, 3>>>();
    double area = 0;
    for (const auto& face : (*ceiling)["mesh"]["faces"]) {
        const auto v = [&](int k) {
            const auto& p = vertices[face[static_cast<std::size_t>(k)].get<std::size_t>()];
            return Vec3{p[0], p[1], p[2]};
        };
        const Vec3 n = cross(v(1) - v(0), v(2) - v(0));
        EXPECT_LT(n.z, 0) << "every piece faces down into the room";
        area += length(n) / 2;
    }
    EXPECT_NEAR(area, 16 - 1 - 0.125, 1e-12);

    scene["luminaires"] =
        Json::array({{{"name", "bulb"}, {"position", {2, 2, 1.5}}, {"flux", 1000}}});
    const ParseOutcome parsed = parse_scene(scene.dump());
    ASSERT_TRUE(parsed.ok()) << parsed.problems[0].pointer << ": " << parsed.problems[0].message;
    SolveOptions options;
    options.tolerance = 0.05;
    const Result result = solve(*parsed.scene, options);
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    EXPECT_NEAR(testing::find_surface(result, "ceiling")->area_m2, 14.875, 1e-9);
    // Light leaves through the openings (and the window's glass): not all of it is absorbed.
    EXPECT_LT(result.stats.absorbed_flux_lm, 0.97 * result.stats.emitted_flux_lm);
}

TEST(Honeybee, UnitsCarryOver) {
    Json hb = model();
    hb["units"] = "Millimeters";
    EXPECT_EQ(converted(hb)["units"], "mm");
    EXPECT_EQ(pointers_after("/units", "Miles"), std::vector<std::string>{"/units"});
}

TEST(Honeybee, MalformedModelsAreRefusedWithTheirPointer) {
    using V = std::vector<std::string>;
    EXPECT_EQ(pointers_after("/type", "Room"), V{"/type"});
    EXPECT_EQ(pointers_after("/rooms/0/faces/2/geometry/boundary/1", "x"),
              V{"/rooms/0/faces/2/geometry/boundary/1"});
    EXPECT_EQ(pointers_after("/rooms/0/faces/0/face_type", "Roof"),
              V{"/rooms/0/faces/0/face_type"});
    EXPECT_EQ(pointers_after("/rooms/0/faces/2/apertures/0/geometry/boundary", Json::array()),
              V{"/rooms/0/faces/2/apertures/0/geometry/boundary"});
    EXPECT_EQ(pointers_after("/properties/radiance/modifiers/0/g_reflectance", 1.5),
              V{"/properties/radiance/modifiers/0/g_reflectance"});
    EXPECT_EQ(
        pointers_after("/properties/radiance/sensor_grids/0/sensors/3/dir", Json::array({0, 0})),
        V{"/properties/radiance/sensor_grids/0/sensors/3/dir"});
    EXPECT_EQ(pointers_after("/rooms/0/faces/1/geometry/holes",
                             Json::array({Json::array({{1, 1, 3}, {2, 1, 3}})})),
              V{"/rooms/0/faces/1/geometry/holes/0"});
    EXPECT_EQ(pointers_after("/rooms/0/faces/1/geometry/holes",
                             Json::array({Json::array({{3, 3, 3}, {5, 3, 3}, {5, 5, 3}})})),
              V{"/rooms/0/faces/1/geometry/holes"})
        << "a hole reaching outside the boundary";
    EXPECT_EQ(
        pointers_after("/rooms/0/faces/1/geometry/holes",
                       Json::array({Json::array({{1, 1, 3}, {2, 1, 3}, {2, 2, 3}}),
                                    Json::array({{1.5, 1.2, 3}, {2.5, 1.2, 3}, {2.5, 2, 3}})})),
        V{"/rooms/0/faces/1/geometry/holes"})
        << "overlapping holes";
    EXPECT_EQ(pointers_after("/rooms/0/faces/1/geometry/boundary/2", Json::array({4, 4, 9})),
              V{"/rooms/0/faces/1/geometry/boundary"})
        << "a non-planar face, found by the scene's own checks";
    EXPECT_EQ(pointers_after("/rooms", 3), V{"/rooms"});
    const HoneybeeOutcome syntax = honeybee_to_scene("{\"type\": \"Model\",");
    ASSERT_EQ(syntax.problems.size(), 1u);
    EXPECT_FALSE(syntax.scene);
}

TEST(Honeybee, CliImportPrintsAValidScene) {
    const fs::path out = fs::temp_directory_path() / ("radiant_hb_" + std::to_string(getpid()));
    fs::create_directories(out);
    const std::string radiant = std::string(RADIANT_BIN_DIR) + "/radiant";
    const std::string ok =
        radiant + " import '" + kModel.string() + "' > '" + (out / "scene.json").string() + "'";
    ASSERT_EQ(std::system(ok.c_str()), 0);
    EXPECT_TRUE(load_scene_file(out / "scene.json").ok());
    Json bad = model();
    bad["rooms"][0]["faces"][0]["face_type"] = "Roof";
    std::ofstream(out / "bad.hbjson") << bad.dump();
    const std::string refused = radiant + " import '" + (out / "bad.hbjson").string() + "' 2> '" +
                                (out / "err").string() + "'";
    const int status = std::system(refused.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_EQ(test::read_text(out / "err"),
              (out / "bad.hbjson").string() +
                  ": /rooms/0/faces/0/face_type: face_type must be Floor, Wall, RoofCeiling or "
                  "AirBoundary\n");
    fs::remove_all(out);
}

}  // namespace
}  // namespace radiant::proto
