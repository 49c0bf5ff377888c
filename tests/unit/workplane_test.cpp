// EN 12464-1 work planes: the grid a scene's `workplane` sensor set makes over its floor, the
// points furniture takes away, and the metrics every solver reports with the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant {
namespace {

/// A 6 × 4 × 3 room (in `units`, lengths scaled by `k` per metre) whose floor is a polygon,
/// lit by one bulb, with a work-plane sensor set and extra surfaces.
std::string room(const std::string& workplane, const std::string& extra_surfaces = "",
                 const std::string& units = "m", double k = 1) {
    const auto n = [&](double metres) { return std::to_string(metres * k); };
    return R"({"format": "radiant-scene/1", "name": "wp", "units": ")" + units + R"(",
      "materials": {"wall": {"reflectance": 0.5}},
      "surfaces": [
        {"name": "floor", "material": "wall",
         "polygon": [[0,0,0],[)" +
           n(6) + R"(,0,0],[)" + n(6) + "," + n(4) + R"(,0],[0,)" + n(4) +
           R"(,0]]},
        {"name": "room", "material": "wall",
         "box": {"min": [0,0,)" +
           n(-1) + R"(], "max": [)" + n(6) + "," + n(4) + "," + n(3) + R"(], "facing": "in"}})" +
           extra_surfaces + R"(],
      "luminaires": [{"name": "bulb", "position": [)" +
           n(2) + "," + n(1.5) + "," + n(2.5) +
           R"(], "flux": 3000}],
      "sensors": [{"name": "wp", "workplane": )" +
           workplane + R"(}]})";
}

Scene parsed(const std::string& json) {
    auto outcome = proto::parse_scene(json);
    for (const Problem& p : outcome.problems) ADD_FAILURE() << p.pointer << ": " << p.message;
    return *outcome.scene;
}

std::vector<Problem> problems(const std::string& json) { return proto::parse_scene(json).problems; }

// 6 × 4 m floor, 0.5 m border: a 5 × 3 m area, d = 5 m, p = 0.2·5^log10(5) = 0.61601 m, so
// ⌈5/p⌉ = 9 by ⌈3/p⌉ = 5 cells of 5/9 × 0.6 m, points at their centres 0.8 m up.
TEST(Workplane, En12464SpacingAndPointsOnASimpleRoom) {
    const Scene scene = parsed(room(R"({"surfaces": ["floor"], "height": 0.8, "border": 0.5})"));
    const SensorSet& set = scene.sensors[0];
    ASSERT_TRUE(set.grid);
    EXPECT_NEAR(set.grid->spacing, 0.6160118, 1e-6);
    EXPECT_EQ(set.grid->nu, 9);
    EXPECT_EQ(set.grid->nv, 5);
    ASSERT_EQ(set.points.size(), 45u);
    EXPECT_NEAR(set.points[0].x, 0.5 + 5.0 / 18, 1e-9);
    EXPECT_NEAR(set.points[0].y, 0.8, 1e-9);
    EXPECT_NEAR(set.points[0].z, 0.8, 1e-9);
    EXPECT_NEAR(set.points[44].x, 5.5 - 5.0 / 18, 1e-9);
    EXPECT_NEAR(set.points[44].y, 3.2, 1e-9);
    EXPECT_EQ(set.grid->cells[10], (std::array<int, 2>{1, 1}));
    EXPECT_NEAR(set.normal.z, 1, 0);
}

// The EN spacing is computed in metres whatever the units; height and border are scene units.
TEST(Workplane, SpacingIsMetricInAnyUnits) {
    const Scene scene =
        parsed(room(R"({"surfaces": ["floor"], "height": 800, "border": 500})", "", "mm", 1000));
    const SensorSet& set = scene.sensors[0];
    EXPECT_NEAR(set.grid->spacing, 616.0118, 1e-3);
    EXPECT_EQ(set.grid->nu, 9);
    EXPECT_EQ(set.grid->nv, 5);
    EXPECT_NEAR(set.points[0].x, 500 + 5000.0 / 18, 1e-6);
    // Defaults: 0.8 m up and 0.5 m in, in millimetres.
    const Scene defaults = parsed(room(R"({"surfaces": ["floor"]})", "", "mm", 1000));
    EXPECT_NEAR(defaults.sensors[0].points[0].z, 800, 1e-9);
    EXPECT_EQ(defaults.sensors[0].points.size(), 45u);
}

TEST(Workplane, ExplicitSpacing) {
    const Scene scene =
        parsed(room(R"({"surfaces": ["floor"], "height": 0.75, "border": 0, "spacing": 1})"));
    EXPECT_EQ(scene.sensors[0].grid->nu, 6);
    EXPECT_EQ(scene.sensors[0].grid->nv, 4);
    EXPECT_EQ(scene.sensors[0].points.size(), 24u);
    EXPECT_NEAR(scene.sensors[0].points[0].x, 0.5, 1e-9);
}

// Cell centres x = 0.5 + (i + ½)·5/9, y = 0.5 + (j + ½)·0.6. A cabinet box over x, y ∈ (1, 2.1)
// holds i = 1, 2 and j = 1, 2 (4 points); a closed mesh over (3.1, 3.7) × (2.3, 2.9) holds
// i = 5, j = 3 (1 point); a desk 0.75 high is under the work plane and takes none.
TEST(Workplane, FurnitureTakesItsPointsAway) {
    const std::string cube = R"(,
        {"name": "locker", "material": "wall", "mesh": {
          "vertices": [[3.1,2.3,0],[3.7,2.3,0],[3.7,2.9,0],[3.1,2.9,0],
                       [3.1,2.3,1.5],[3.7,2.3,1.5],[3.7,2.9,1.5],[3.1,2.9,1.5]],
          "faces": [[0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7]]}})";
    const std::string boxes = R"(,
        {"name": "cabinet", "material": "wall", "box": {"min": [1,1,0], "max": [2.1,2.1,2], "facing": "out"}},
        {"name": "desk", "material": "wall", "box": {"min": [4,0.6,0], "max": [5.5,1.6,0.75], "facing": "out"}})";
    const Scene scene =
        parsed(room(R"({"surfaces": ["floor"], "height": 0.8, "border": 0.5})", boxes + cube));
    const SensorSet& set = scene.sensors[0];
    EXPECT_EQ(set.points.size(), 40u);
    for (const auto& cell : {std::array<int, 2>{1, 1}, {2, 1}, {1, 2}, {2, 2}, {5, 3}}) {
        EXPECT_EQ(std::find(set.grid->cells.begin(), set.grid->cells.end(), cell),
                  set.grid->cells.end())
            << cell[0] << "," << cell[1];
    }
}

// An L-shaped floor: points outside the polygon, or nearer than the border to its inner corner,
// are left out.
TEST(Workplane, PointsOutsideAnLShapedFloorAreLeftOut) {
    std::string scene_json = room(R"({"surfaces": ["floor"], "height": 0.8, "border": 0.5})");
    scene_json.replace(
        scene_json.find("[[0,0,0],[6.000000,0,0],[6.000000,4.000000,0],[0,4.000000,0]]"), 61,
        "[[0,0,0],[6,0,0],[6,2,0],[3,2,0],[3,4,0],[0,4,0]]");
    const Scene scene = parsed(scene_json);
    const SensorSet& set = scene.sensors[0];
    for (const Vec3& x : set.points) {
        const bool in_lower = x.y <= 2 - 0.5 && x.x >= 0.5 && x.x <= 5.5;
        const bool in_left = x.x <= 3 - 0.5 && x.y >= 0.5 && x.y <= 3.5;
        EXPECT_TRUE(in_lower || in_left) << x.x << ", " << x.y;
    }
    // Rows j = 0, 1 (y = 0.8, 1.4) keep all 9; rows j = 2..4 keep the 4 with x ≤ 2.5.
    EXPECT_EQ(set.points.size(), 2u * 9 + 3u * 4);
}

TEST(Workplane, BadWorkPlanesAreRefusedWithTheirPointer) {
    auto first = [](const std::vector<Problem>& p) {
        return p.empty() ? std::string("none") : p[0].pointer + ": " + p[0].message;
    };
    EXPECT_EQ(first(problems(room(R"({"surfaces": ["flor"]})"))),
              "/sensors/0/workplane/surfaces/0: unknown surface \"flor\"");
    EXPECT_EQ(first(problems(room(R"({"surfaces": ["floor"], "border": 2})"))),
              "/sensors/0/workplane: the border leaves no area on the floor");
    EXPECT_EQ(first(problems(room(R"({"surfaces": ["floor"], "border": -1})"))),
              "/sensors/0/workplane/border: border must be a finite number >= 0");
    EXPECT_EQ(first(problems(room(R"({"surfaces": ["floor"], "spacing": 0})"))),
              "/sensors/0/workplane/spacing: spacing must be a finite number > 0");
    EXPECT_EQ(first(problems(room(R"({"surfaces": ["floor"], "width": 1})"))),
              "/sensors/0/workplane/width: unknown key");
}

// A room modelled as one box facing in: its floor is the box's bottom face. A wall has no
// upward-facing face to lay a grid on.
TEST(Workplane, BoxFloorsAndWallsThatAreNoFloor) {
    const std::string box_room = R"({"format": "radiant-scene/1",
      "materials": {"wall": {"reflectance": 0.5}},
      "surfaces": [
        {"name": "room", "material": "wall", "box": {"min": [0,0,0], "max": [6,4,3], "facing": "in"}},
        {"name": "wall", "material": "wall", "polygon": [[1,1,0],[2,1,0],[2,1,1],[1,1,1]]}],
      "luminaires": [{"name": "bulb", "position": [3,2,2.5], "flux": 1000}],
      "sensors": [{"name": "wp", "workplane": {"surfaces": ["room"]}}]})";
    const Scene scene = parsed(box_room);
    EXPECT_EQ(scene.sensors[0].points.size(), 45u);
    EXPECT_NEAR(scene.sensors[0].points[0].z, 0.8, 1e-12);
    std::string on_wall = box_room;
    on_wall.replace(on_wall.find(R"("surfaces": ["room"])"), 20, R"("surfaces": ["wall"])");
    const auto refused = problems(on_wall);
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused[0].pointer, "/sensors/0/workplane");
    EXPECT_EQ(refused[0].message, "the named surfaces have no upward-facing horizontal face");
}

// Every solver returns the grid with the set, and U₀, U_d computed from its own illuminances.
TEST(Workplane, MetricsAndGridFromEverySolver) {
    const Scene scene = parsed(room(R"({"surfaces": ["floor"], "height": 0.8, "border": 0.5})"));
    for (const char* method : {"direct", "gauss-seidel", "shooting", "hierarchical"}) {
        SolveOptions options;
        options.method = method;
        options.tolerance = 0.05;
        const Result result = solve(scene, options);
        ASSERT_NE(result.status, SolveStatus::failed) << method << ": " << result.error;
        const SensorResult& s = result.sensors[0];
        ASSERT_TRUE(s.grid) << method;
        EXPECT_EQ(s.grid->nu, 9);
        EXPECT_EQ(s.grid->points.size(), 45u);
        EXPECT_EQ(s.illuminance.size(), 45u);
        const auto [lo, hi] = std::minmax_element(s.illuminance.begin(), s.illuminance.end());
        double sum = 0;
        for (const double e : s.illuminance) sum += e;
        const double average = sum / 45;
        EXPECT_NEAR(s.average, average, 1e-9 * average) << method;
        EXPECT_EQ(s.min, *lo);
        EXPECT_EQ(s.max, *hi);
        EXPECT_NEAR(s.u0, *lo / average, 1e-12) << method;
        EXPECT_NEAR(s.ud, *lo / *hi, 1e-12) << method;
        EXPECT_LT(s.ud, s.u0);  // the bulb is off-centre: the plane is far from uniform
        // All digits: the JSON carries the engine's numbers (result_json_test rounds them).
        const auto json = proto::result_to_json(result, proto::kMaxDigits);
        const auto& set = json["sensors"][0];
        EXPECT_EQ(set["u0"], s.u0);
        EXPECT_EQ(set["ud"], s.ud);
        EXPECT_EQ(set["grid"]["nv"], 5);
        EXPECT_EQ(set["grid"]["points"].size(), 45u);
        EXPECT_EQ(set["grid"]["cells"][44], (nlohmann::json{8, 4}));
    }
}

// A millimetre scene reports its grid in metres, like every result.
TEST(Workplane, ResultGridIsInMetres) {
    const Scene scene =
        parsed(room(R"({"surfaces": ["floor"], "height": 800, "border": 500})", "", "mm", 1000));
    SolveOptions options;
    options.tolerance = 0.05;
    const Result result = solve(scene, options);
    const SensorGrid& grid = *result.sensors[0].grid;
    EXPECT_NEAR(grid.spacing, 0.6160118, 1e-6);
    EXPECT_NEAR(grid.points[0].x, 0.5 + 5.0 / 18, 1e-9);
    EXPECT_NEAR(grid.origin.z, 0.8, 1e-12);
    EXPECT_NEAR(grid.u.x, 5, 1e-12);
}

}  // namespace
}  // namespace radiant
