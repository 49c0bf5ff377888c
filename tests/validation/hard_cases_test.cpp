// Hard cases for the hierarchical solver (issue 3, item 7), each solved with
// `method: hierarchical` explicitly (`auto` would solve most of these small scenes densely) and
// checked against physics: exact answers, energy balance, equality across equivalent inputs,
// and finite values everywhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "analytic_form_factors.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"
#include "scene_builder.h"
#include "scene_files.h"
#include "solve_with.h"

namespace radiant {
namespace {

using testing::describe;
using testing::find_sensor;
using testing::find_surface;
using testing::solve_hierarchical;
using testing::solve_with;

// Every number a result reports is finite, and light is never negative.
void expect_finite(const Result& r) {
    for (const double v : {r.stats.error_estimate, r.stats.emitted_flux_lm,
                           r.stats.absorbed_flux_lm, r.stats.unshot_fraction}) {
        EXPECT_TRUE(std::isfinite(v)) << "a statistic is " << v;
    }
    for (const auto& s : r.surfaces) {
        EXPECT_TRUE(std::isfinite(s.average_radiosity) && s.average_radiosity >= 0) << s.name;
        EXPECT_TRUE(std::isfinite(s.average_irradiance) && s.average_irradiance >= 0) << s.name;
    }
    for (const auto& set : r.sensors) {
        for (const double v : set.illuminance) {
            EXPECT_TRUE(std::isfinite(v) && v >= 0) << set.name << ": " << v;
        }
    }
}

double absorbed_over_emitted(const Result& r) {
    return r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm;
}

// ---------------------------------------------------------------------------------------------
// Reflectance 0.99 and 0.999: a closed room with a closed block inside, every surface emitting
// E = 1: B = E / (1 − ρ) everywhere (100 and 1000), reached to 2 %. How fast is measured by
// radiant-bench (furnace-rho0.99, furnace-rho0.999), not here: a timed test fails on a busy
// machine.

class HighReflectanceFurnace : public ::testing::TestWithParam<double> {};

TEST_P(HighReflectanceFurnace, EverySurfaceAtEOverOneMinusRho) {
    const double rho = GetParam();
    Scene scene;
    scene.name = "furnace-high-rho";
    scene.materials = {testing::gray("glow", rho, 1.0)};
    scene.surfaces = {
        testing::box_surface("room", "glow", {0, 0, 0}, {4, 4, 3}, true),
        testing::box_surface("block", "glow", {1.5, 1.5, 0.5}, {2.5, 2.5, 1.5}, false)};
    const Result r = solve_hierarchical(scene, 0.02);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    const double exact = 1.0 / (1.0 - rho);
    for (const auto& s : r.surfaces) {
        EXPECT_NEAR(s.average_radiosity / exact, 1.0, 0.02)
            << s.name << ": B " << s.average_radiosity << ", exact " << exact << "; "
            << describe(r);
    }
}

INSTANTIATE_TEST_SUITE_P(Rho, HighReflectanceFurnace, ::testing::Values(0.99, 0.999),
                         [](const auto& param_info) {
                             return "rho" + std::to_string(std::lround(param_info.param * 1000));
                         });

// ---------------------------------------------------------------------------------------------
// Adjacent perpendicular patches sharing an edge: an emitter (E = 1, black) and a black
// receiver; the receiver's mean irradiance is E · F(emitter → receiver) · A_e / A_r (§1.2).

struct PerpendicularCase {
    double edge, emitter_width, receiver_height;
};

void PrintTo(const PerpendicularCase& c, std::ostream* os) {
    *os << "edge " << c.edge << " m, emitter width " << c.emitter_width << " m, receiver height "
        << c.receiver_height << " m";
}

class AdjacentPerpendicular : public ::testing::TestWithParam<PerpendicularCase> {};

TEST_P(AdjacentPerpendicular, ReceiverIrradianceIsTheFormFactor) {
    const auto [l, w, h] = GetParam();
    Scene scene;
    scene.name = "adjacent-perpendicular";
    scene.materials = {testing::gray("emitter", 0.0, 1.0), testing::gray("black", 0.0)};
    // Emitter in z = 0 over [0, l] × [0, w], facing up; receiver in y = 0 over [0, l] × [0, h],
    // facing +y; they share the edge along x.
    scene.surfaces = {testing::polygon_surface("emitter", "emitter",
                                               testing::rect({0, 0, 0}, {l, 0, 0}, {0, w, 0})),
                      testing::polygon_surface("receiver", "black",
                                               testing::rect({0, 0, 0}, {0, 0, h}, {l, 0, 0}))};
    const Result r = solve_hierarchical(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    const auto* receiver = find_surface(r, "receiver");
    ASSERT_NE(receiver, nullptr);
    const double exact = analytic::perpendicular_common_edge(l, w, h) * w / h;
    EXPECT_NEAR(receiver->average_irradiance / exact, 1.0, 0.01)
        << "irradiance " << receiver->average_irradiance << ", exact " << exact << "; "
        << describe(r);
    // Open scene, black receiver: what it absorbs is exactly what reaches it.
    EXPECT_NEAR(r.stats.absorbed_flux_lm / (exact * l * h), 1.0, 0.01) << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Shapes, AdjacentPerpendicular,
                         ::testing::Values(PerpendicularCase{1, 1, 1}, PerpendicularCase{1, 2, 0.5},
                                           PerpendicularCase{2, 0.2, 1}),
                         [](const auto& param_info) {
                             const auto& c = param_info.param;
                             auto cm = [](double v) {
                                 return std::to_string(std::lround(v * 100));
                             };
                             return "l" + cm(c.edge) + "_w" + cm(c.emitter_width) + "_h" +
                                    cm(c.receiver_height) + "_cm";
                         });

// ---------------------------------------------------------------------------------------------
// A tiny, very bright emitter: 1 cm², L = 1e7 cd/m² (Φ = π L A = 3141.6 lm) at the ceiling of
// a 4 × 4 × 3 m room. In a black room a sensor at distance d gets the far-field
// Φ cosθ_e cosθ_r / (π d²); in a grey closed room absorbed = emitted, to the solve's
// tolerance (links may carry that much uncertain power; the dense solvers' exact row sums
// do better).

Scene room_with_tiny_emitter(double reflectance) {
    Scene scene;
    scene.name = "tiny-emitter";
    scene.materials = {testing::gray("room", reflectance),
                       testing::gray("led", 0.0, std::numbers::pi * 1e7)};
    scene.surfaces = {testing::box_surface("room", "room", {0, 0, 0}, {4, 4, 3}, true),
                      testing::polygon_surface(
                          "led", "led", testing::ceiling_rect(1.995, 2.005, 1.995, 2.005, 2.999))};
    return scene;
}

TEST(TinyBrightEmitter, FarFieldInverseSquareInABlackRoom) {
    Scene scene = room_with_tiny_emitter(0.0);
    const Vec3 source{2, 2, 2.999};
    const std::vector<Vec3> points{{2, 2, 0}, {3, 2, 0.5}, {0.5, 1, 0}, {3.5, 3.5, 1}};
    scene.sensors = {testing::sensor_points("floor", points)};
    const Result r = solve_hierarchical(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    const double flux = std::numbers::pi * 1e7 * 1e-4;
    EXPECT_NEAR(r.stats.emitted_flux_lm / flux, 1.0, 1e-9);
    const auto* floor = find_sensor(r, "floor");
    ASSERT_NE(floor, nullptr);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 d = source - points[i];
        const double dist = length(d), cos_theta = d.z / dist;  // both normals are vertical
        const double exact = flux * cos_theta * cos_theta / (std::numbers::pi * dist * dist);
        // The emitter's size (1 cm at ≥ 2 m) changes the far-field value by < 1e-5.
        EXPECT_NEAR(floor->illuminance[i] / exact, 1.0, 0.005)
            << "point " << i << ": " << floor->illuminance[i] << " lx, far field " << exact;
    }
}

// In a grey room and in a black one alike: black walls carry no light, so their links stay
// coarse, yet their factors must not let the emitter's exact light be scaled up when a
// receiver's factor sum is completed to 1.
class TinyEmitterEnergyBalance : public ::testing::TestWithParam<double> {};

TEST_P(TinyEmitterEnergyBalance, AbsorbedEqualsEmitted) {
    const double tolerance = 0.01;
    const Result r = solve_hierarchical(room_with_tiny_emitter(GetParam()), tolerance);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    EXPECT_NEAR(absorbed_over_emitted(r), 1.0, 1e-3)
        << "absorbed " << r.stats.absorbed_flux_lm << ", emitted " << r.stats.emitted_flux_lm
        << "; " << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Walls, TinyEmitterEnergyBalance, ::testing::Values(0.0, 0.7),
                         [](const ::testing::TestParamInfo<double>& param_info) {
                             return param_info.param == 0 ? std::string("black")
                                                          : std::string("grey");
                         });

// ---------------------------------------------------------------------------------------------
// Sliver and degenerate triangles. A zero-area face is refused with its JSON pointer; needle
// faces (aspect ratio up to 4·10⁶) are solved without NaN and give the same light as the same
// floor as one polygon.

TEST(DegenerateTriangles, ZeroAreaFaceIsRefusedWithItsPointer) {
    const char* text = R"({
      "format": "radiant-scene/1", "name": "degenerate",
      "materials": { "m": { "reflectance": 0.5, "emission": { "exitance": 10 } } },
      "surfaces": [ { "name": "floor", "material": "m", "mesh": {
        "vertices": [[0,0,0], [1,0,0], [1,1,0], [2,2,0]],
        "faces": [[0,1,2], [0,2,3]] } } ] })";
    const auto outcome = proto::parse_scene(text);
    ASSERT_FALSE(outcome.ok());
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/surfaces/0/mesh/faces/1");
    EXPECT_NE(outcome.problems[0].message.find("zero area"), std::string::npos)
        << outcome.problems[0].message;
}

Scene room_with_floor(Surface floor) {
    Scene scene;
    scene.name = "needle-floor";
    scene.materials = {testing::gray("wall", 0.5), testing::gray("panel", 0.5, 1000.0)};
    scene.surfaces = testing::room_without_ceiling(4, 4, 3, "wall");
    scene.surfaces[0] = std::move(floor);
    scene.surfaces.push_back(
        testing::polygon_surface("ceiling", "panel", testing::ceiling_rect(0, 4, 0, 4, 3)));
    scene.sensors = {testing::sensor_grid("workplane", {0, 0, 0.8}, {4, 0, 0}, {0, 4, 0}, 4, 4)};
    return scene;
}

TEST(DegenerateTriangles, NeedleFacesMatchThePlainFloor) {
    // A fan from (0, 0) over the floor; the top-edge points crowd together near x = 2, so
    // three faces are needles 4 m long and 1 mm, 1 µm and 1 µm wide.
    MeshGeometry mesh;
    mesh.vertices = {{0, 0, 0},        {4, 0, 0},        {4, 4, 0}, {3, 4, 0}, {2 + 1e-3, 4, 0},
                     {2 + 2e-6, 4, 0}, {2 + 1e-6, 4, 0}, {2, 4, 0}, {1, 4, 0}, {0, 4, 0}};
    for (int k = 1; k + 1 < static_cast<int>(mesh.vertices.size()); ++k)
        mesh.faces.push_back({0, k, k + 1});
    Surface needles;
    needles.name = "floor";
    needles.material = "wall";
    needles.geometry = mesh;
    const Scene plain_scene = room_with_floor(
        testing::polygon_surface("floor", "wall", testing::rect({0, 0, 0}, {4, 0, 0}, {0, 4, 0})));
    const Scene needle_scene = room_with_floor(needles);
    ASSERT_TRUE(check_scene(needle_scene).empty()) << "needles are valid input";
    const Result plain = solve_hierarchical(plain_scene);
    const Result needle = solve_hierarchical(needle_scene);
    ASSERT_EQ(plain.status, SolveStatus::converged) << describe(plain);
    ASSERT_EQ(needle.status, SolveStatus::converged) << describe(needle);
    expect_finite(needle);
    ASSERT_EQ(plain.surfaces.size(), needle.surfaces.size());
    for (std::size_t i = 0; i < plain.surfaces.size(); ++i) {
        EXPECT_NEAR(needle.surfaces[i].average_radiosity / plain.surfaces[i].average_radiosity, 1.0,
                    0.01)
            << plain.surfaces[i].name;
    }
    const auto& a = plain.sensors.at(0).illuminance;
    const auto& b = needle.sensors.at(0).illuminance;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(b[i] / a[i], 1.0, 0.01) << "point " << i;
    // Closed room: absorbed = emitted within the engine core's 0.1 % (see TinyBrightEmitter).
    EXPECT_NEAR(absorbed_over_emitted(needle), 1.0, 1e-3) << describe(needle);
}

// ---------------------------------------------------------------------------------------------
// A 100 × 20 × 8 m hall with a 2 mm thick shelf board (closed box) over part of the work plane:
// as is, moved 10 km away, and in millimetres. The three give the same sensor values.

Scene hall(double scale, Vec3 offset, LengthUnit units) {
    auto at = [&](Vec3 p) { return p * scale + offset; };
    Scene scene;
    scene.name = "hall";
    scene.units = units;
    scene.materials = {testing::gray("wall", 0.5), testing::gray("shelf", 0.6)};
    Surface room = testing::box_surface("hall", "wall", at({0, 0, 0}), at({100, 20, 8}), true);
    Surface board =
        testing::box_surface("shelf", "shelf", at({49, 9, 1.2}), at({51, 11, 1.202}), false);
    scene.surfaces = {room, board};
    for (int k = 0; k < 5; ++k) {
        scene.luminaires.push_back(
            testing::luminaire("lamp-" + std::to_string(k), at({10.0 + 20 * k, 10, 7}), 20000));
    }
    std::vector<Vec3> points{
        {50, 10, 0.8}, {49.5, 9.5, 1.0}, {50, 10, 1.21}, {30, 10, 0.8}, {90, 3, 0.8}};
    for (auto& p : points) p = at(p);
    scene.sensors = {testing::sensor_points("probes", points)};
    return scene;
}

TEST(HallWithThinShelf, SameValuesFarAwayAndInMillimetres) {
    // What is compared is the three placements, not the answer's accuracy: a coarse tolerance
    // meshes and links them alike as well as a fine one does, in a fraction of the time.
    constexpr double kTolerance = 0.05;
    const Result base = solve_hierarchical(hall(1, {0, 0, 0}, LengthUnit::m), kTolerance);
    const Result far = solve_hierarchical(hall(1, {1e4, 1e4, 0}, LengthUnit::m), kTolerance);
    const Result mm = solve_hierarchical(hall(1000, {0, 0, 0}, LengthUnit::mm), kTolerance);
    for (const Result* r : {&base, &far, &mm}) {
        ASSERT_EQ(r->status, SolveStatus::converged) << describe(*r);
        expect_finite(*r);
    }
    const auto& want = base.sensors.at(0).illuminance;
    // Under the board the light is reflected only, above it direct: the board must cast its
    // shadow (less than a third of the open work plane), and no variant may leak through it.
    EXPECT_LT(want[0], want[3] / 3) << "under the shelf " << want[0] << ", open " << want[3];
    for (const Result* r : {&far, &mm}) {
        const auto& got = r->sensors.at(0).illuminance;
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i) {
            EXPECT_NEAR(got[i] / want[i], 1.0, 1e-3)
                << (r == &far ? "10 km away" : "millimetres") << ", probe " << i << ": " << got[i]
                << " lx, as is " << want[i] << " lx";
        }
        EXPECT_NEAR(r->stats.absorbed_flux_lm / base.stats.absorbed_flux_lm, 1.0, 1e-3);
    }
}

// ---------------------------------------------------------------------------------------------
// Coplanar coincident surfaces: an emitting panel flush in (on top of) the ceiling polygon and
// a rug lying on the floor polygon, against the same room with ceiling and floor cut around
// them. The overlay hides what is under it: no light leaks, nothing is counted twice.

Scene room_with_overlays(bool cut) {
    Scene scene = testing::room_with_ceiling_panel(0.5, 2000);
    scene.name = cut ? "cut-room" : "overlay-room";
    scene.materials.push_back(testing::gray("rug", 0.1));
    const Polygon rug = testing::rect({1, 1, 0}, {2, 0, 0}, {0, 1.5, 0});
    if (!cut) {
        // One ceiling polygon under the panel, one floor polygon under the rug.
        std::erase_if(scene.surfaces,
                      [](const Surface& s) { return s.name.rfind("ceiling-", 0) == 0; });
        scene.surfaces.push_back(
            testing::polygon_surface("ceiling", "wall", testing::ceiling_rect(0, 4, 0, 4, 3)));
    } else {
        // The floor as four rectangles around the rug.
        std::erase_if(scene.surfaces, [](const Surface& s) { return s.name == "floor"; });
        scene.surfaces.push_back(testing::polygon_surface(
            "floor-1", "wall", testing::rect({0, 0, 0}, {4, 0, 0}, {0, 1, 0})));
        scene.surfaces.push_back(testing::polygon_surface(
            "floor-2", "wall", testing::rect({0, 2.5, 0}, {4, 0, 0}, {0, 1.5, 0})));
        scene.surfaces.push_back(testing::polygon_surface(
            "floor-3", "wall", testing::rect({0, 1, 0}, {1, 0, 0}, {0, 1.5, 0})));
        scene.surfaces.push_back(testing::polygon_surface(
            "floor-4", "wall", testing::rect({3, 1, 0}, {1, 0, 0}, {0, 1.5, 0})));
    }
    scene.surfaces.push_back(testing::polygon_surface("rug", "rug", rug));
    scene.sensors = {testing::sensor_grid("workplane", {0, 0, 0.8}, {4, 0, 0}, {0, 4, 0}, 5, 5)};
    return scene;
}

TEST(CoplanarOverlays, EmitterInCeilingAndRugOnFloorMatchCutSurfaces) {
    const Result overlay = solve_hierarchical(room_with_overlays(false));
    const Result cut = solve_hierarchical(room_with_overlays(true));
    ASSERT_EQ(overlay.status, SolveStatus::converged) << describe(overlay);
    ASSERT_EQ(cut.status, SolveStatus::converged) << describe(cut);
    expect_finite(overlay);
    // The panel emits 2000 lm/m² over its 1 m², counted once.
    EXPECT_NEAR(overlay.stats.emitted_flux_lm, 2000.0, 1e-6);
    // Closed rooms balance within the engine core's 0.1 % (the solver conserves light there);
    // an overlay that leaked or counted light twice would move its balance away from the cut
    // room's, whose links are the same but for the hidden patches.
    EXPECT_NEAR(absorbed_over_emitted(overlay), 1.0, 1e-3) << describe(overlay);
    EXPECT_NEAR(absorbed_over_emitted(cut), 1.0, 1e-3) << describe(cut);
    EXPECT_NEAR(absorbed_over_emitted(overlay), absorbed_over_emitted(cut), 1e-3)
        << describe(overlay) << " / " << describe(cut);
    for (const char* name : {"panel", "rug"}) {
        const auto* a = find_surface(overlay, name);
        const auto* b = find_surface(cut, name);
        ASSERT_TRUE(a && b) << name;
        EXPECT_NEAR(a->average_radiosity / b->average_radiosity, 1.0, 0.01) << name;
        EXPECT_NEAR(a->average_irradiance / b->average_irradiance, 1.0, 0.01) << name;
    }
    const auto& want = cut.sensors.at(0).illuminance;
    const auto& got = overlay.sensors.at(0).illuminance;
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_NEAR(got[i] / want[i], 1.0, 0.01) << "point " << i;
    }
}

// ---------------------------------------------------------------------------------------------
// An emitter 1 mm above a receiver: a 1 × 1 m emitter (M = 1000 lm/m², facing down) over a
// black 1 × 1 m receiver. The kernel is near-singular over the whole footprint; the receiver's
// mean irradiance is M · F12, F12 = 0.998006 (§1.1), the same in millimetres and 10 km from the
// origin. Over the black floor of a closed black room all the light is absorbed, nearly all of
// it by the floor (what leaves the gap lands within a few mm of the footprint). Both with a
// bounded number of elements: the gap must not shrink the mesh of the whole scene to 1 mm.

constexpr double kGap = 0.001;
constexpr double kEmitterExitance = 1000;
// Elements a few 1 m² surfaces may take, refined until the estimate meets the tolerance, with
// room to spare (the bug took 1.9 million).
constexpr std::size_t kNearElementLimit = 100000;

struct NearCase {
    const char* method;
    const char* variant;  // "m", "mm" or "far"
};

void PrintTo(const NearCase& c, std::ostream* os) { *os << c.method << ", " << c.variant; }

Scene emitter_over_receiver(const std::string& variant) {
    const double scale = variant == "mm" ? 1000 : 1;
    const Vec3 offset = variant == "far" ? Vec3{1e4, 1e4, 0} : Vec3{0, 0, 0};
    auto at = [&](Vec3 p) { return p * scale + offset; };
    Scene scene;
    scene.name = "emitter-1mm-above-receiver";
    scene.units = variant == "mm" ? LengthUnit::mm : LengthUnit::m;
    scene.materials = {testing::gray("emitter", 0.0, kEmitterExitance),
                       testing::gray("black", 0.0)};
    // Emitter at z = 1 mm facing −z; receiver at z = 0 facing +z; both [0, 1] × [0, 1].
    scene.surfaces = {
        testing::polygon_surface(
            "emitter", "emitter",
            {at({0, 0, kGap}), at({0, 1, kGap}), at({1, 1, kGap}), at({1, 0, kGap})}),
        testing::polygon_surface("receiver", "black",
                                 {at({0, 0, 0}), at({1, 0, 0}), at({1, 1, 0}), at({0, 1, 0})})};
    return scene;
}

class EmitterOneMillimetreAbove : public ::testing::TestWithParam<NearCase> {};

TEST_P(EmitterOneMillimetreAbove, ReceiverGetsTheFormFactor) {
    const auto [method, variant] = GetParam();
    const Result r = solve_with(emitter_over_receiver(variant), method);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    const auto* receiver = find_surface(r, "receiver");
    ASSERT_NE(receiver, nullptr);
    const double f12 = analytic::parallel_coaxial_rectangles(1, 1, kGap);
    ASSERT_NEAR(f12, 0.998006, 1e-6);
    EXPECT_NEAR(receiver->average_irradiance / (f12 * kEmitterExitance), 1.0, 0.01)
        << "irradiance " << receiver->average_irradiance << " lx; " << describe(r);
    EXPECT_LT(r.stats.elements, kNearElementLimit) << describe(r);
}

std::string near_case_name(const ::testing::TestParamInfo<NearCase>& param_info) {
    return std::string(param_info.param.method) + "_" + param_info.param.variant;
}

INSTANTIATE_TEST_SUITE_P(Variants, EmitterOneMillimetreAbove,
                         ::testing::Values(NearCase{"hierarchical", "m"},
                                           NearCase{"hierarchical", "mm"},
                                           NearCase{"hierarchical", "far"}, NearCase{"auto", "m"},
                                           NearCase{"auto", "mm"}, NearCase{"auto", "far"}),
                         near_case_name);

// The issue's scene: the emitter 1 mm above the middle of an open, black 10 × 10 m floor. The
// floor gets all the light but what escapes the gap sideways and misses it (< 0.2 %), with
// elements bounded (the mean free path across the gap once made 1.9 million root patches).
Scene emitter_over_large_floor(const std::string& variant) {
    const double scale = variant == "mm" ? 1000 : 1;
    const Vec3 offset = variant == "far" ? Vec3{1e4, 1e4, 0} : Vec3{0, 0, 0};
    auto at = [&](Vec3 p) { return p * scale + offset; };
    Scene scene;
    scene.name = "emitter-1mm-above-large-floor";
    scene.units = variant == "mm" ? LengthUnit::mm : LengthUnit::m;
    scene.materials = {testing::gray("emitter", 0.0, kEmitterExitance),
                       testing::gray("black", 0.0)};
    scene.surfaces = {
        testing::polygon_surface("emitter", "emitter",
                                 {at({4.5, 4.5, kGap}), at({4.5, 5.5, kGap}), at({5.5, 5.5, kGap}),
                                  at({5.5, 4.5, kGap})}),
        testing::polygon_surface("floor", "black",
                                 {at({0, 0, 0}), at({10, 0, 0}), at({10, 10, 0}), at({0, 10, 0})})};
    return scene;
}

class EmitterOneMillimetreAboveLargeFloor : public ::testing::TestWithParam<NearCase> {};

TEST_P(EmitterOneMillimetreAboveLargeFloor, FloorGetsTheLight) {
    const auto [method, variant] = GetParam();
    const Result r = solve_with(emitter_over_large_floor(variant), method);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    const auto* floor = find_surface(r, "floor");
    ASSERT_NE(floor, nullptr);
    EXPECT_NEAR(floor->average_irradiance * 100 / kEmitterExitance, 1.0, 0.01)
        << "floor " << floor->average_irradiance << " lx; " << describe(r);
    EXPECT_LT(r.stats.elements, kNearElementLimit) << describe(r);
}

INSTANTIATE_TEST_SUITE_P(Variants, EmitterOneMillimetreAboveLargeFloor,
                         ::testing::Values(NearCase{"hierarchical", "m"},
                                           NearCase{"hierarchical", "mm"},
                                           NearCase{"hierarchical", "far"}, NearCase{"auto", "m"}),
                         near_case_name);

// The 1 × 1 m emitter 1 mm above the floor of a closed 4 × 4 × 3 m room: black everywhere, or
// with a grey floor (ρ 0.5) that sends half of it back to the emitter and the room.
Scene emitter_over_floor(double floor_reflectance) {
    Scene scene;
    scene.name = "emitter-1mm-above-floor";
    scene.materials = {testing::gray("emitter", 0.0, kEmitterExitance), testing::gray("black", 0.0),
                       testing::gray("floor", floor_reflectance)};
    scene.surfaces = testing::closed_room(4, 4, 3, "black");
    scene.surfaces[0].material = "floor";
    scene.surfaces.push_back(testing::polygon_surface(
        "emitter", "emitter", testing::ceiling_rect(1.5, 2.5, 1.5, 2.5, kGap)));
    return scene;
}

struct NearFloorCase {
    const char* method;
    double floor_reflectance;
};

void PrintTo(const NearFloorCase& c, std::ostream* os) {
    *os << c.method << ", floor reflectance " << c.floor_reflectance;
}

class EmitterOneMillimetreAboveFloor : public ::testing::TestWithParam<NearFloorCase> {};

TEST_P(EmitterOneMillimetreAboveFloor, ClosedRoomAbsorbsWhatItEmits) {
    const auto [method, rho] = GetParam();
    const Result r = solve_with(emitter_over_floor(rho), method);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    expect_finite(r);
    EXPECT_NEAR(r.stats.emitted_flux_lm, kEmitterExitance, 1e-6);
    EXPECT_NEAR(absorbed_over_emitted(r), 1.0, 0.01)
        << "absorbed " << r.stats.absorbed_flux_lm << "; " << describe(r);
    EXPECT_LT(r.stats.elements, kNearElementLimit) << describe(r);
    if (rho == 0) {
        // All but what escapes the gap lands on the floor, and most of that lands beside it.
        const auto* floor = find_surface(r, "floor");
        ASSERT_NE(floor, nullptr);
        EXPECT_NEAR(floor->average_irradiance * 16 / kEmitterExitance, 1.0, 0.01)
            << "floor " << floor->average_irradiance << " lx; " << describe(r);
    }
}

INSTANTIATE_TEST_SUITE_P(Floors, EmitterOneMillimetreAboveFloor,
                         ::testing::Values(NearFloorCase{"hierarchical", 0.0},
                                           NearFloorCase{"hierarchical", 0.5},
                                           NearFloorCase{"auto", 0.0}, NearFloorCase{"auto", 0.5}),
                         [](const auto& param_info) {
                             return std::string(param_info.param.method) + "_floor_rho" +
                                    std::to_string(
                                        std::lround(param_info.param.floor_reflectance * 10));
                         });

}  // namespace
}  // namespace radiant
