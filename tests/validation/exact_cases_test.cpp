// Scenes with exact answers (shared/validation/README.md §2, §5), built in code, solved with
// default settings unless a test says otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "cube_ceiling.h"
#include "formfactor/point_polygon.h"
#include "radiant/proto/scene_json.h"
#include "scene_builder.h"
#include "scene_files.h"

namespace radiant {
namespace {

using testing::find_sensor;
using testing::find_surface;

Result solve_default(const Scene& scene) { return solve(scene, options_from(scene.settings)); }

/// Why a solve did not converge, for failure messages.
std::string describe(const Result& r) {
    return std::string(to_string(r.status)) + " (" + r.error + ") method " + r.stats.method + ", " +
           std::to_string(r.stats.patches) + " patches, " + std::to_string(r.stats.iterations) +
           " iterations, error estimate " + std::to_string(r.stats.error_estimate) + ", " +
           std::to_string(r.stats.seconds) + " s";
}

// ---------------------------------------------------------------------------------------------
// §2.2 furnace: every surface emits E = 1 and reflects ρ in a closed enclosure: B = 1/(1 − ρ).

struct FurnaceCase {
    double rho;
    double rel_tol;
};

void PrintTo(const FurnaceCase& c, std::ostream* os) {
    *os << "rho " << c.rho << ", tolerance " << c.rel_tol;
}

class FurnaceCube : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(FurnaceCube, AverageRadiosityIsEOverOneMinusRho) {
    const auto [rho, rel_tol] = GetParam();
    const Result r = solve_default(testing::furnace_cube(rho));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    const auto* box = find_surface(r, "box");
    ASSERT_NE(box, nullptr);
    const double exact = 1.0 / (1.0 - rho);
    EXPECT_NEAR(box->average_radiosity / exact, 1.0, rel_tol)
        << "rho " << rho << ": B " << box->average_radiosity << ", exact " << exact << " ("
        << r.stats.patches << " patches, method " << r.stats.method << ")";
}

INSTANTIATE_TEST_SUITE_P(
    Rho, FurnaceCube,
    ::testing::Values(FurnaceCase{0.9, 0.01}, FurnaceCase{0.99, 0.01}, FurnaceCase{0.999, 0.02}),
    [](const auto& param_info) {
        return "rho" + std::to_string(static_cast<int>(std::lround(param_info.param.rho * 1000)));
    });

// Engine bug found by these tests: OcclusionCulling::can_block needs the occluder's bounding box
// to overlap the shaft's with positive volume on all three axes, so a flat axis-aligned occluder
// (zero extent along its normal) is never a candidate and no shadow ray is cast at all. Tests of
// occluded scenes skip (with their measured numbers) only while that signature, rays == 0, holds.
// The scenes below are also run rotated by 30° about the vertical axis: then no piece is axis
// aligned, culling works, and the visibility itself is what is tested.
std::string angle_name(double degrees) {
    return degrees == 0 ? std::string("axis_aligned")
                        : "rotated_" + std::to_string(std::lround(degrees)) + "deg";
}

Scene maybe_rotated(Scene scene, double degrees) {
    return degrees == 0 ? scene : testing::rotated_about_z(std::move(scene), degrees, {2, 2, 0});
}

// §2.2 (2): a room with a free-floating box inside, both closed, all ρ = 0.9, E = 1: B = 10.
class FurnaceRoomWithBox : public ::testing::TestWithParam<double> {};

TEST_P(FurnaceRoomWithBox, BothClosedSurfacesAtTenTimesE) {
    Scene scene;
    scene.name = "furnace-room-box";
    scene.materials = {testing::gray("glow", 0.9, 1.0)};
    scene.surfaces = {testing::box_surface("room", "glow", {0, 0, 0}, {4, 4, 3}, true),
                      testing::box_surface("block", "glow", {1.5, 1.5, 1}, {2.5, 2.5, 2}, false)};
    const Result r = solve_default(maybe_rotated(scene, GetParam()));
    const double room = testing::mean_radiosity_of(r, "room");
    const double block = testing::mean_radiosity_of(r, "block");
    const std::string measured =
        "room B " + std::to_string(room) + ", block B " + std::to_string(block) +
        " (exact 10); absorbed/emitted " +
        std::to_string(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm) + "; " + describe(r);
    ASSERT_EQ(r.status, SolveStatus::converged) << measured;
    EXPECT_NEAR(room / 10.0, 1.0, 0.01) << measured;
    EXPECT_NEAR(block / 10.0, 1.0, 0.01) << measured;
}

INSTANTIATE_TEST_SUITE_P(Angle, FurnaceRoomWithBox, ::testing::Values(0.0, 30.0),
                         [](const auto& param_info) { return angle_name(param_info.param); });

// §2.2 (4): an L-shaped room (occlusion by its own concave corner), ρ = 0.9, E = 1: B = 10.
// Floor and ceiling either as one L-shaped polygon each (as a user would write them) or as two
// rectangles each.
struct LRoomCase {
    double degrees;
    bool single_polygon;
};

void PrintTo(const LRoomCase& c, std::ostream* os) {
    *os << c.degrees << " deg, " << (c.single_polygon ? "L polygon" : "rectangles");
}

class FurnaceLRoom : public ::testing::TestWithParam<LRoomCase> {};

TEST_P(FurnaceLRoom, EverySurfaceAtTenTimesE) {
    const auto [degrees, single_polygon] = GetParam();
    const double h = 3;
    const Polygon plan{{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {2, 2, 0}, {2, 4, 0}, {0, 4, 0}};
    Scene scene;
    scene.name = "furnace-l-room";
    scene.materials = {testing::gray("glow", 0.9, 1.0)};
    if (single_polygon) {
        scene.surfaces.push_back(testing::polygon_surface("floor", "glow", plan));
        Polygon ceiling;
        for (auto it = plan.rbegin(); it != plan.rend(); ++it) {
            ceiling.push_back(*it + Vec3{0, 0, h});
        }
        scene.surfaces.push_back(testing::polygon_surface("ceiling", "glow", ceiling));
    } else {
        scene.surfaces.push_back(testing::polygon_surface(
            "floor/0", "glow", testing::rect({0, 0, 0}, {4, 0, 0}, {0, 2, 0})));
        scene.surfaces.push_back(testing::polygon_surface(
            "floor/1", "glow", testing::rect({0, 2, 0}, {2, 0, 0}, {0, 2, 0})));
        scene.surfaces.push_back(
            testing::polygon_surface("ceiling/0", "glow", testing::ceiling_rect(0, 4, 0, 2, h)));
        scene.surfaces.push_back(
            testing::polygon_surface("ceiling/1", "glow", testing::ceiling_rect(0, 2, 2, 4, h)));
    }
    for (std::size_t i = 0; i < plan.size(); ++i) {
        const Vec3 p = plan[i], q = plan[(i + 1) % plan.size()];
        scene.surfaces.push_back(testing::polygon_surface("wall-" + std::to_string(i), "glow",
                                                          testing::rect(p, {0, 0, h}, q - p)));
    }
    const Result r = solve_default(maybe_rotated(scene, degrees));
    const double mean = testing::mean_radiosity(r);
    double worst = 0, floor_area = 0;
    std::string worst_name;
    for (const auto& surf : r.surfaces) {
        if (surf.name.rfind("floor", 0) == 0) floor_area += surf.area_m2;
        if (std::abs(surf.average_radiosity / 10 - 1) >= worst) {
            worst = std::abs(surf.average_radiosity / 10 - 1);
            worst_name = surf.name + " B " + std::to_string(surf.average_radiosity);
        }
    }
    const std::string measured =
        "mean B " + std::to_string(mean) + " (exact 10), worst " + worst_name + "; floor area " +
        std::to_string(floor_area) + " m² (exact 12); absorbed/emitted " +
        std::to_string(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm) + "; " + describe(r);
    // Known engine bug (see polygon_split_test.cpp): convex_pieces ear-clips the L-shaped floor
    // into a reversed triangle over the missing quadrant, so the floor covers 16 m², not 12.
    ASSERT_EQ(r.status, SolveStatus::converged) << measured;
    EXPECT_NEAR(floor_area, 12.0, 1e-9) << measured;
    EXPECT_NEAR(mean / 10.0, 1.0, 0.01) << measured;
    EXPECT_LE(worst, 0.01) << measured;
}

INSTANTIATE_TEST_SUITE_P(Angle, FurnaceLRoom,
                         ::testing::Values(LRoomCase{0, false}, LRoomCase{30, false},
                                           LRoomCase{30, true}),
                         [](const auto& param_info) {
                             return angle_name(param_info.param.degrees) +
                                    (param_info.param.single_polygon ? "_l_polygon"
                                                                     : "_rectangles");
                         });

// ---------------------------------------------------------------------------------------------
// §2.3 energy balance in a closed room: absorbed flux = emitted flux.

TEST(EnergyBalance, ClosedRoomCeilingPanel) {
    const Scene scene = testing::room_with_ceiling_panel(0.5, 1000.0);
    const Result r = solve_default(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_NEAR(r.stats.emitted_flux_lm, 1000.0, 1e-9 * 1000.0);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm, 1.0, 1e-3)
        << "absorbed " << r.stats.absorbed_flux_lm << " lm, emitted " << r.stats.emitted_flux_lm
        << " lm";
    // Σ A B = Σ A E / (1 − ρ) (exact for any closed geometry with uniform ρ).
    double sum_ab = 0;
    for (const auto& s : r.surfaces) sum_ab += s.area_m2 * s.average_radiosity;
    EXPECT_NEAR(sum_ab / 2000.0, 1.0, 1e-3) << "sum A B " << sum_ab << " lm, exact 2000 lm";
}

TEST(EnergyBalance, ClosedRoomPointLuminaire) {
    Scene scene;
    scene.name = "room-point";
    scene.materials = {testing::gray("wall", 0.5)};
    scene.surfaces = {testing::box_surface("room", "wall", {0, 0, 0}, {4, 4, 3}, true)};
    scene.luminaires = {testing::luminaire("L", {2, 2, 2}, 1000.0)};
    const Result r = solve_default(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_NEAR(r.stats.emitted_flux_lm, 1000.0, 1e-9 * 1000.0);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm, 1.0, 1e-3)
        << "absorbed " << r.stats.absorbed_flux_lm << " lm, emitted " << r.stats.emitted_flux_lm
        << " lm";
    // Mean total irradiance = Φ / (S_T (1 − ρ)), S_T = 2 (16 + 12 + 12) = 80 m².
    const auto* room = find_surface(r, "room");
    ASSERT_NE(room, nullptr);
    EXPECT_NEAR(room->average_irradiance / 25.0, 1.0, 1e-3)
        << "mean irradiance " << room->average_irradiance << " lx, exact 25 lx";
}

// ---------------------------------------------------------------------------------------------
// §2.7a unit cube, ceiling E = 1, ρ = 0.5: converged face means, for every solver.

class CubeCeiling : public ::testing::TestWithParam<std::string> {};

TEST_P(CubeCeiling, FaceMeansWithinHalfPercent) {
    const Scene scene = testing::load_scene(testing::data_path("scenes/cube-ceiling-rho0.5.json"));
    SolveOptions options = options_from(scene.settings);
    options.method = GetParam();
    const Result r = solve(scene, options);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    testing::expect_cube_ceiling_face_means(r, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Solvers, CubeCeiling,
                         ::testing::Values("hierarchical", "direct", "jacobi", "gauss-seidel",
                                           "shooting", "auto"),
                         [](const auto& param_info) {
                             std::string s = param_info.param;
                             for (char& c : s) {
                                 if (c == '-') c = '_';
                             }
                             return s;
                         });

// ---------------------------------------------------------------------------------------------
// Point luminaires in a black room: sensor illuminance is the direct term only.

const std::vector<Vec3> kFloorPoints{{2, 2, 0},     {0.5, 0.5, 0}, {3.5, 2, 0},   {1, 3, 0},
                                     {0.2, 3.8, 0}, {3.0, 1.0, 0}, {2.0, 0.25, 0}};

Scene black_room_with(const Luminaire& l) {
    Scene scene;
    scene.name = "black-room";
    scene.materials = {testing::gray("black", 0.0)};
    scene.surfaces = {testing::box_surface("room", "black", {0, 0, 0}, {4, 4, 3}, true)};
    scene.luminaires = {l};
    scene.sensors = {testing::sensor_points("floor", kFloorPoints)};
    return scene;
}

TEST(PointLuminaireDirect, IsotropicInverseSquareCosine) {
    const Vec3 pos{2, 2, 2};
    const Result r = solve_default(black_room_with(testing::luminaire("L", pos, 1000.0)));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    const auto* floor = find_sensor(r, "floor");
    ASSERT_NE(floor, nullptr);
    ASSERT_EQ(floor->illuminance.size(), kFloorPoints.size());
    const double intensity = 1000.0 / (4 * std::numbers::pi);
    for (std::size_t i = 0; i < kFloorPoints.size(); ++i) {
        const Vec3 d = pos - kFloorPoints[i];
        const double dist = length(d);
        const double exact = intensity * (d.z / dist) / (dist * dist);
        EXPECT_NEAR(floor->illuminance[i] / exact, 1.0, 0.005)
            << "point (" << kFloorPoints[i].x << ", " << kFloorPoints[i].y << "): got "
            << floor->illuminance[i] << " lx, exact " << exact << " lx";
    }
}

TEST(PointLuminaireDirect, LambertianAimedDown) {
    const Vec3 pos{2, 2, 2};
    const Result r = solve_default(
        black_room_with(testing::luminaire("L", pos, 1000.0, Distribution::lambertian)));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    const auto* floor = find_sensor(r, "floor");
    ASSERT_NE(floor, nullptr);
    ASSERT_EQ(floor->illuminance.size(), kFloorPoints.size());
    for (std::size_t i = 0; i < kFloorPoints.size(); ++i) {
        const Vec3 d = pos - kFloorPoints[i];
        const double dist = length(d);
        const double cos_theta = d.z / dist;  // emission angle from the aim and incidence angle
        const double exact = (1000.0 / std::numbers::pi) * cos_theta * cos_theta / (dist * dist);
        EXPECT_NEAR(floor->illuminance[i] / exact, 1.0, 0.005)
            << "point (" << kFloorPoints[i].x << ", " << kFloorPoints[i].y << "): got "
            << floor->illuminance[i] << " lx, exact " << exact << " lx";
    }
}

// ---------------------------------------------------------------------------------------------
// §5.8 a tiny, very bright emitter: 1 cm × 1 cm, L = 1e7 cd/m², 2 m above the floor of a black
// 4 × 4 × 3 m room. Floor illuminance from Lambert's formula (§1.5); nadir 249.998 lx.

// Lambert's point-to-polygon factor for a receiver at x with normal n (polygon in front of it).
double lambert_factor(const Vec3& x, const Vec3& n, const Polygon& poly) {
    double sum = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec3 a = poly[i] - x;
        const Vec3 b = poly[(i + 1) % poly.size()] - x;
        const Vec3 c = cross(a, b);
        const double gamma = std::atan2(length(c), dot(a, b));
        sum += gamma * dot(n, c) / length(c);
    }
    return std::abs(sum) / (2 * std::numbers::pi);
}

TEST(TinyBrightEmitter, FloorIlluminanceAndFlux) {
    const double luminance = 1e7;
    const double exitance = std::numbers::pi * luminance;
    Scene scene;
    scene.name = "tiny-led";
    scene.materials = {testing::gray("black", 0.0), testing::gray("led", 0.0, exitance)};
    const Polygon led = testing::ceiling_rect(1.995, 2.005, 1.995, 2.005, 2.0);
    scene.surfaces = {testing::box_surface("room", "black", {0, 0, 0}, {4, 4, 3}, true),
                      testing::polygon_surface("led", "led", led)};
    const std::vector<Vec3> points{{2, 2, 0}, {2.5, 2, 0}, {1, 1, 0}, {3.5, 0.5, 0}};
    scene.sensors = {testing::sensor_points("floor", points)};
    const Result r = solve_default(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    const auto* floor = find_sensor(r, "floor");
    ASSERT_NE(floor, nullptr);
    ASSERT_EQ(floor->illuminance.size(), points.size());
    EXPECT_NEAR(floor->illuminance[0] / 249.99791668489573, 1.0, 0.005)
        << "nadir " << floor->illuminance[0] << " lx, exact 249.998 lx";
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double exact = exitance * lambert_factor(points[i], {0, 0, 1}, led);
        EXPECT_NEAR(floor->illuminance[i] / exact, 1.0, 0.01)
            << "point " << i << ": " << floor->illuminance[i] << " lx, exact " << exact << " lx";
    }
    const double flux = exitance * 1e-4;  // π L A = 3141.59 lm
    EXPECT_NEAR(r.stats.emitted_flux_lm / flux, 1.0, 1e-9);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / flux, 1.0, 1e-3)
        << "absorbed " << r.stats.absorbed_flux_lm << " lm, emitted " << flux << " lm";
}

// ---------------------------------------------------------------------------------------------
// §5.5 a 1 × 1 m emitter exactly coplanar with (overlapping) a closed room's ceiling, against the
// same emitter 1 mm below it: face means within 0.5 %, and the closed-room energy balance.

Scene ceiling_with_overlay(double offset) {
    Scene scene;
    scene.name = "coplanar-panel";
    scene.materials = {testing::gray("wall", 0.5), testing::gray("panel", 0.5, 1000.0)};
    scene.surfaces = testing::closed_room(4, 4, 3, "wall");
    scene.surfaces.push_back(testing::polygon_surface(
        "panel", "panel", testing::ceiling_rect(1.5, 2.5, 1.5, 2.5, 3 - offset)));
    return scene;
}

TEST(CoplanarEmitter, MatchesOffsetEmitter) {
    const Result coplanar = solve_default(ceiling_with_overlay(0.0));
    const Result offset = solve_default(ceiling_with_overlay(0.001));
    ASSERT_EQ(coplanar.status, SolveStatus::converged) << describe(coplanar);
    ASSERT_EQ(offset.status, SolveStatus::converged) << describe(offset);
    ASSERT_EQ(coplanar.surfaces.size(), offset.surfaces.size());
    for (std::size_t i = 0; i < coplanar.surfaces.size(); ++i) {
        const auto& c = coplanar.surfaces[i];
        const auto& o = offset.surfaces[i];
        EXPECT_TRUE(std::isfinite(c.average_radiosity) && c.average_radiosity >= 0) << c.name;
        EXPECT_NEAR(c.average_radiosity / o.average_radiosity, 1.0, 0.005)
            << c.name << ": coplanar " << c.average_radiosity << ", 1 mm below "
            << o.average_radiosity;
    }
}

TEST(CoplanarEmitter, ClosedRoomEnergyBalance) {
    const Result r = solve_default(ceiling_with_overlay(0.0));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    const double ratio = r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm;
    std::ostringstream measured;
    measured << "absorbed " << r.stats.absorbed_flux_lm << " lm, emitted "
             << r.stats.emitted_flux_lm << " lm (ratio " << ratio << ", limit 1 ± 1e-3); ceiling B "
             << find_surface(r, "ceiling")->average_radiosity << ", area "
             << find_surface(r, "ceiling")->area_m2 << " m²; " << describe(r);
    EXPECT_NEAR(r.stats.emitted_flux_lm, 1000.0, 1e-6);
    EXPECT_NEAR(ratio, 1.0, 1e-3) << measured.str();
}

TEST(CoplanarEmitter, OffsetEmitterEnergyBalance) {
    const Result r = solve_default(ceiling_with_overlay(0.001));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    const double ratio = r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm;
    std::ostringstream measured;
    measured << "absorbed " << r.stats.absorbed_flux_lm << " lm, emitted "
             << r.stats.emitted_flux_lm << " lm (ratio " << ratio << ", limit 1 ± 1e-3); "
             << describe(r);
    EXPECT_NEAR(ratio, 1.0, 1e-3) << measured.str();
}

// ---------------------------------------------------------------------------------------------
// §5.4 light leaks: two 4 × 4 × 3 rooms sharing a wall; floor and ceiling polygons span both.

Scene two_rooms(double wall) {
    const double length = 8.0 + wall;
    Scene scene;
    scene.name = "two-rooms";
    Material wall_material = testing::gray("wall", 0.7);
    Material partition = testing::gray("partition", 0.7);
    partition.two_sided = true;
    Material panel = testing::gray("panel", 0.0);
    panel.emission = Emission{Emission::Kind::flux, 5000.0, std::nullopt, {}};
    scene.materials = {wall_material, partition, panel};
    scene.surfaces = {
        testing::box_surface("shell", "wall", {0, 0, 0}, {length, 4, 3}, true),
        testing::polygon_surface("panel", "panel", testing::ceiling_rect(1.5, 2.5, 1.5, 2.5, 2.99)),
    };
    if (wall > 0) {
        scene.surfaces.push_back(
            testing::box_surface("partition", "wall", {4, 0, 0}, {4 + wall, 4, 3}, false));
    } else {
        scene.surfaces.push_back(testing::polygon_surface(
            "partition", "partition", testing::rect({4, 0, 0}, {0, 0, 3}, {0, 4, 0})));
    }
    const double b0 = 4 + wall;
    scene.sensors = {
        testing::sensor_grid("room-a", {0.25, 0.25, 0.8}, {3.5, 0, 0}, {0, 3.5, 0}, 5, 5),
        testing::sensor_grid("room-b", {b0 + 0.25, 0.25, 0.8}, {3.5, 0, 0}, {0, 3.5, 0}, 5, 5),
        testing::sensor_points("room-b-floor-edge",
                               {{b0 + 0.002, 2.0, 0.0005}, {b0 + 0.002, 0.5, 0.0005}}),
    };
    return scene;
}

struct SealedCase {
    double wall;
    double degrees;
};

void PrintTo(const SealedCase& c, std::ostream* os) {
    *os << "wall " << c.wall << " m, " << c.degrees << " deg";
}

class SealedNeighbour : public ::testing::TestWithParam<SealedCase> {};

TEST_P(SealedNeighbour, NoLightInRoomB) {
    const auto [wall, degrees] = GetParam();
    const Result r = solve_default(maybe_rotated(two_rooms(wall), degrees));
    ASSERT_NE(r.status, SolveStatus::failed) << describe(r);
    const auto* a = find_sensor(r, "room-a");
    const auto* b = find_sensor(r, "room-b");
    const auto* edge = find_sensor(r, "room-b-floor-edge");
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    ASSERT_NE(edge, nullptr);
    ASSERT_GT(a->average, 0);
    std::ostringstream measured;
    measured << "wall " << wall << " m, rotated " << degrees << " deg: room-b max " << b->max
             << " lx, room-b-floor-edge max " << edge->max << " lx, room A mean " << a->average
             << " lx (ratios " << b->max / a->average << ", " << edge->max / a->average
             << ", limit 1e-6); absorbed/emitted "
             << r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm << "; " << describe(r)
             << ", rays " << r.stats.rays;
    EXPECT_EQ(r.status, SolveStatus::converged) << measured.str();
    EXPECT_LE(b->max, 1e-6 * a->average) << measured.str();
    EXPECT_LE(edge->max, 1e-6 * a->average) << measured.str();
}

INSTANTIATE_TEST_SUITE_P(Wall, SealedNeighbour,
                         ::testing::Values(SealedCase{0.2, 0}, SealedCase{0.01, 0},
                                           SealedCase{0, 0}, SealedCase{0.2, 30},
                                           SealedCase{0.01, 30}, SealedCase{0, 30}),
                         [](const auto& param_info) {
                             const auto& c = param_info.param;
                             std::string wall =
                                 c.wall == 0 ? std::string("two_sided_polygon")
                                             : "thickness_" +
                                                   std::to_string(std::lround(c.wall * 100)) + "cm";
                             return wall + "_" + angle_name(c.degrees);
                         });

// A window: a black 6 × 5 × 3 m room whose south wall has an open 2 × 0.6 m window, a 1.2 ×
// 0.6 m ceiling panel and, under its edge, a desk top that sees out through the window over
// 1.3 % of its hemisphere (cosine-weighted). The desk top's light is the panel's alone: E = M·F,
// Lambert's formula integrated over it. A patch that took the window for a wall would complete its
// factors to sum to 1 and so add that 1.3 % (+10 % on a classroom's desks before enclosure
// tests pooled a piece's rays).
Scene room_with_window(double reflectance = 0) {
    Scene scene;
    scene.name = "room-with-window";
    scene.materials = {testing::gray("wall", reflectance), testing::gray("panel", 0, 1000)};
    scene.surfaces = testing::room_without_ceiling(6, 5, 3, "wall");
    std::erase_if(scene.surfaces, [](const Surface& s) { return s.name == "wall-south"; });
    // The south wall (y = 0, facing +y) around the window x ∈ [2, 4], z ∈ [1.5, 2.1].
    auto south = [&](const std::string& name, double x0, double x1, double z0, double z1) {
        scene.surfaces.push_back(testing::polygon_surface(
            name, "wall", testing::rect({x0, 0, z0}, {0, 0, z1 - z0}, {x1 - x0, 0, 0})));
    };
    south("south-left", 0, 2, 0, 3);
    south("south-right", 4, 6, 0, 3);
    south("sill", 2, 4, 0, 1.5);
    south("lintel", 2, 4, 2.1, 3);
    scene.surfaces.push_back(
        testing::polygon_surface("ceiling", "wall", testing::ceiling_rect(0, 6, 0, 5, 3)));
    scene.surfaces.push_back(testing::polygon_surface(
        "panel", "panel", testing::ceiling_rect(2.4, 3.6, 3.1, 3.7, 2.99)));
    scene.surfaces.push_back(testing::polygon_surface(
        "desk-top", "wall", testing::rect({2.4, 2.5, 0.72}, {1.2, 0, 0}, {0, 0.6, 0})));
    return scene;
}

struct WindowCase {
    std::string method;
    double tolerance;
};

void PrintTo(const WindowCase& c, std::ostream* os) { *os << c.method << " at " << c.tolerance; }

class WindowedRoom : public ::testing::TestWithParam<WindowCase> {};

TEST_P(WindowedRoom, DeskTopGetsThePanelsLightAndNoMore) {
    const auto& [method, tolerance] = GetParam();
    Scene scene = room_with_window();
    scene.settings.method = method;
    scene.settings.tolerance = tolerance;
    const Result r = solve_default(scene);
    // At 0.003 the estimate stays a little above the tolerance (`stopped`); the light is right.
    ASSERT_NE(r.status, SolveStatus::failed) << describe(r);
    const Polygon panel = testing::ceiling_rect(2.4, 3.6, 3.1, 3.7, 2.99);
    constexpr int kPoints = 40;
    double sum = 0;
    for (int i = 0; i < kPoints; ++i) {
        for (int j = 0; j < kPoints; ++j) {
            const Vec3 x{2.4 + 1.2 * (i + 0.5) / kPoints, 2.5 + 0.6 * (j + 0.5) / kPoints, 0.72};
            sum += front_point_to_polygon_factor(x, {0, 0, 1}, panel, {0, 0, -1});
        }
    }
    const double exact = 1000 * sum / (kPoints * kPoints);
    const auto* desk = find_surface(r, "desk-top");
    ASSERT_NE(desk, nullptr);
    EXPECT_NEAR(desk->average_irradiance / exact, 1, 0.003)
        << desk->average_irradiance << " lx against " << exact << "; " << describe(r);
}

// With reflecting walls, light leaves only through the window, and the hierarchical solver must
// let as much out as the dense one. Its leaves that see the window have their factors completed
// to the share of their hemisphere that surfaces cover (from rays); left as sampled, they lost
// 2.3 % of the light here, and when the window went unnoticed (completed to 1), the dense
// solver kept 4 % that should have left.
TEST(WindowedRoomReflecting, HierarchicalLetsOutWhatDenseDoes) {
    Scene scene = room_with_window(0.7);
    scene.sensors = {
        testing::sensor_grid("workplane", {0.5, 0.5, 0.8}, {5, 0, 0}, {0, 4, 0}, 10, 8)};
    scene.settings.tolerance = 0.01;
    scene.settings.method = "direct";
    const Result dense = solve_default(scene);
    scene.settings.method = "hierarchical";
    const Result hierarchical = solve_default(scene);
    ASSERT_EQ(dense.status, SolveStatus::converged) << describe(dense);
    ASSERT_EQ(hierarchical.status, SolveStatus::converged) << describe(hierarchical);
    const auto* a = find_sensor(hierarchical, "workplane");
    const auto* b = find_sensor(dense, "workplane");
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_NEAR(hierarchical.stats.absorbed_flux_lm / dense.stats.absorbed_flux_lm, 1, 0.005)
        << describe(hierarchical);
    EXPECT_NEAR(a->average / b->average, 1, 0.005) << describe(hierarchical);
    EXPECT_LT(dense.stats.absorbed_flux_lm, 0.97 * dense.stats.emitted_flux_lm)
        << "light must leave through the window";
}

INSTANTIATE_TEST_SUITE_P(Solvers, WindowedRoom,
                         ::testing::Values(WindowCase{"hierarchical", 0.01},
                                           WindowCase{"hierarchical", 0.003},
                                           WindowCase{"direct", 0.01}),
                         [](const auto& param_info) {
                             const auto& c = param_info.param;
                             return c.method + "_" +
                                    std::to_string(std::lround(c.tolerance * 1000)) + "e_3";
                         });

// The zero-thickness partition as a user writes it: "two_sided" must reach the engine.
TEST(SealedNeighbourJson, TwoSidedPartitionParses) {
    const auto outcome = proto::parse_scene(R"({
      "format": "radiant-scene/1", "name": "two-sided", "units": "m",
      "materials": {"wall": {"reflectance": 0.7},
                    "partition": {"reflectance": 0.7, "two_sided": true},
                    "panel": {"reflectance": 0.0, "emission": {"flux": 5000.0}}},
      "surfaces": [
        {"name": "shell", "material": "wall", "box": {"min": [0,0,0], "max": [8,4,3], "facing": "in"}},
        {"name": "panel", "material": "panel",
         "polygon": [[1.5,1.5,2.99],[1.5,2.5,2.99],[2.5,2.5,2.99],[2.5,1.5,2.99]]},
        {"name": "partition", "material": "partition",
         "polygon": [[4,0,0],[4,0,3],[4,4,3],[4,4,0]]}],
      "sensors": [
        {"name": "room-a", "grid": {"origin": [0.25,0.25,0.8], "u": [3.5,0,0], "v": [0,3.5,0],
                                    "nu": 5, "nv": 5}, "normal": [0,0,1]},
        {"name": "room-b", "grid": {"origin": [4.25,0.25,0.8], "u": [3.5,0,0], "v": [0,3.5,0],
                                    "nu": 5, "nv": 5}, "normal": [0,0,1]}]
    })");
    for (const auto& p : outcome.problems) ADD_FAILURE() << p.pointer << ": " << p.message;
    ASSERT_TRUE(outcome.scene.has_value());
    ASSERT_EQ(outcome.scene->materials.size(), 3u);
    for (const auto& m : outcome.scene->materials) {
        EXPECT_EQ(m.two_sided, m.name == "partition") << m.name;
    }
    // Solving this scene is SealedNeighbour.NoLightInRoomB/two_sided_polygon.
    EXPECT_EQ(outcome.scene->surfaces.size(), 3u);
}

}  // namespace
}  // namespace radiant
