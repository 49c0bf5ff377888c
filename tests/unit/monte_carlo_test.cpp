// The Monte Carlo method: its elements, its light sources, and solves whose answer is known
// exactly or from another method — each within the error the solve itself estimates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <variant>

#include "formfactor/point_polygon.h"
#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "montecarlo/monte_carlo_error.h"
#include "montecarlo/photon_field.h"
#include "montecarlo/sensor_gather.h"
#include "scene/prepared_scene.h"
#include "scene_builder.h"
#include "solve_with.h"

namespace radiant {
namespace {

using testing::describe;

Scene panel_room_with_sensors() {
    Scene scene = testing::room_with_ceiling_panel(0.6, 1000);
    scene.sensors.push_back(
        testing::sensor_grid("work plane", {0.25, 0.25, 0.8}, {3.5, 0, 0}, {0, 3.5, 0}, 7, 7));
    return scene;
}

// What a gather needs: a scene's mesh of edge `edge`, its ray tracer, its sources, a photon field
// of `photons` and the direct-light cache.
struct GatherSetup {
    GatherSetup(const Scene& scene, double edge, std::size_t photons)
        : prepared(prepare_scene(scene)),
          mesh(prepared, {edge}),
          visibility(make_embree_visibility(mesh.triangles())),
          sources(prepared, visibility->epsilon()),
          field(prepared, mesh, 5),
          cache(prepared, mesh, sources, *visibility, 7) {
        field.trace(photons, sources, *visibility, [] { return false; });
    }
    SensorGather gather() const { return {prepared, mesh, sources, cache, *visibility, 7}; }

    PreparedScene prepared;
    ElementMesh mesh;
    std::unique_ptr<Visibility> visibility;
    LightSources sources;
    PhotonField field;
    SideDirectCache cache;
};

// The scene's first sensor point, gathered with `sets` ray sets over `photons` photons on
// elements of edge `edge` (m).
GatheredPoint first_point(const Scene& scene, double edge, std::size_t photons, int sets) {
    const GatherSetup setup(scene, edge, photons);
    SensorGather gather = setup.gather();
    gather.gather(sets, [] { return false; });
    return gather.evaluate(setup.field).at(0);
}

double rms_relative_error(const std::vector<double>& values, const std::vector<double>& exact) {
    double sum = 0, mean = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        sum += (values[i] - exact[i]) * (values[i] - exact[i]);
        mean += exact[i];
    }
    mean /= static_cast<double>(exact.size());
    return std::sqrt(sum / static_cast<double>(exact.size())) / mean;
}

TEST(ElementMesh, CutsPiecesToTheEdgeAndKeepsTheirArea) {
    const PreparedScene scene = prepare_scene(panel_room_with_sensors());
    const double edge = 0.3;
    const ElementMesh mesh(scene, {edge});
    std::vector<double> area(scene.pieces.size(), 0.0);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const MeshElement& e = mesh[i];
        for (const auto& [p, q] : {std::pair{e.triangle.a, e.triangle.b},
                                   {e.triangle.b, e.triangle.c},
                                   {e.triangle.c, e.triangle.a}}) {
            EXPECT_LE(length(q - p), edge * (1 + 1e-12));
        }
        EXPECT_GT(dot(cross(e.triangle.b - e.triangle.a, e.triangle.c - e.triangle.a), e.normal),
                  0);
        area[static_cast<std::size_t>(e.piece)] += e.area_m2;
        if (e.sibling >= 0) {
            const MeshElement& s = mesh[static_cast<std::size_t>(e.sibling)];
            EXPECT_EQ(s.sibling, static_cast<int>(i));
            EXPECT_EQ(s.piece, e.piece);
        }
        EXPECT_EQ(e.back, -1);  // gray one-sided walls
    }
    for (std::size_t p = 0; p < scene.pieces.size(); ++p)
        EXPECT_NEAR(area[p], scene.pieces[p].area_m2, 1e-9 * scene.pieces[p].area_m2);
}

// Near a luminaire elements shrink with their distance from it (a lamp's light varies over
// that distance), down to an eighth of the edge; beyond its reach they keep the edge. Pieces
// keep their area, and count() says what the mesh holds.
TEST(ElementMesh, ElementsNearALuminaireShrinkWithTheDistance) {
    Scene scene = panel_room_with_sensors();
    scene.luminaires.push_back(testing::luminaire("lamp", {1, 1, 0.5}, 800));
    const PreparedScene prepared = prepare_scene(scene);
    const Vec3 lamp = prepared.luminaires.at(0).position;
    const ElementSizing sizing{0.4, 1.2};
    const ElementMesh mesh(prepared, sizing);
    std::vector<double> area(prepared.pieces.size(), 0.0);
    double finest = sizing.max_edge_m;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Triangle& t = mesh[i].triangle;
        const double longest = std::max({length(t.b - t.a), length(t.c - t.b), length(t.a - t.c)});
        const double apart = length((t.a + t.b + t.c) / 3.0 - lamp);
        EXPECT_LE(longest, sizing.max_edge_m * (1 + 1e-12));
        EXPECT_LE(longest, sizing.max_edge_m *
                               std::max(apart / sizing.light_reach_m, ElementSizing::kFinest) *
                               (1 + 1e-12));
        if (apart > sizing.light_reach_m + sizing.max_edge_m) {
            EXPECT_GT(longest, sizing.max_edge_m / 4) << "element " << i;
        }
        finest = std::min(finest, longest);
        area[static_cast<std::size_t>(mesh[i].piece)] += mesh[i].area_m2;
    }
    EXPECT_LT(finest, sizing.max_edge_m / 2);
    EXPECT_GT(mesh.size(), ElementMesh(prepared, {sizing.max_edge_m}).size());
    for (std::size_t p = 0; p < prepared.pieces.size(); ++p)
        EXPECT_NEAR(area[p], prepared.pieces[p].area_m2, 1e-9 * prepared.pieces[p].area_m2);
    const ElementCount counted = ElementMesh::count(prepared, sizing);
    EXPECT_EQ(counted.elements, mesh.size());
    EXPECT_EQ(counted.sides, mesh.sides().size());
}

// The panel room with a strip 3 cm wide from `a` along x to `x1`, facing down, emitting
// `exitance`; its elements, and the offset of their frame from the scene's.
std::pair<ElementMesh, Vec3> mesh_with_strip(const Vec3& a, double x1, double exitance,
                                             const ElementSizing& sizing) {
    Scene scene = panel_room_with_sensors();
    scene.materials.push_back(testing::gray("strip", 0.5, exitance));
    scene.surfaces.push_back(testing::polygon_surface(
        "strip", "strip", testing::ceiling_rect(a.x, x1, a.y, a.y + 0.03, a.z)));
    const PreparedScene prepared = prepare_scene(scene);
    return {ElementMesh(prepared, sizing), prepared.world_origin};
}

// A strip light (1.2 m by 3 cm, facing down 1 m over the floor) is no compact light, but the
// light under it varies across it over its distance from it as a lamp's does: elements in front
// of it are cut by their distance from its length, as near its ends as near its middle. The same
// strip emitting nothing leaves the mesh as without it.
TEST(ElementMesh, ElementsNearAStripLightShrinkWithTheirDistanceFromIt) {
    const ElementSizing sizing{0.4, 1.2};
    const Vec3 a{0.5, 0.5, 1}, b{1.7, 0.5, 1};
    const auto [dark, dark_origin] = mesh_with_strip(a, b.x, 0, sizing);
    const auto [lit, origin] = mesh_with_strip(a, b.x, 50000, sizing);
    EXPECT_GT(lit.size(), dark.size() + 50);
    std::size_t near_an_end = 0;
    for (const MeshElement& e : lit.elements()) {
        const Triangle& t = e.triangle;
        const Vec3 centre = (t.a + t.b + t.c) / 3.0 + origin;
        const double along = std::clamp(dot(centre - a, b - a) / length_squared(b - a), 0.0, 1.0);
        const double apart = length(centre - (a + (b - a) * along));
        const double longest = std::max({length(t.b - t.a), length(t.c - t.b), length(t.a - t.c)});
        if (centre.z >= a.z) continue;  // behind the strip: it lights nothing there
        EXPECT_LE(longest,
                  sizing.max_edge_m *
                      std::clamp(apart / sizing.light_reach_m, ElementSizing::kFinest, 1.0) *
                      (1 + 1e-12));
        // Under the strip's first 10 cm, over 0.5 m from its middle, on the floor.
        if (centre.z < 0.01 && centre.x > a.x && centre.x < a.x + 0.1 &&
            std::abs(centre.y - a.y) < 0.1)
            near_an_end += longest < 0.9 * sizing.max_edge_m ? 1 : 0;
    }
    EXPECT_GT(near_an_end, 0u);
}

// A strip 20 km long through the room would be a chain of 66 667 lights at this reach, more than
// the chains may hold in all (a hostile scene's strips would make billions): it grades nothing.
TEST(ElementMesh, AStripTooLongForTheChainsGradesNothing) {
    const ElementSizing sizing{0.4, 1.2};
    const Vec3 a{-10000, 0.5, 1};
    EXPECT_EQ(mesh_with_strip(a, 10000, 50000, sizing).first.size(),
              mesh_with_strip(a, 10000, 0, sizing).first.size());
    // A tenth as long, through the room as well, it does.
    const Vec3 a_tenth{-1000, 0.5, 1};
    EXPECT_GT(mesh_with_strip(a_tenth, 1000, 50000, sizing).first.size(),
              mesh_with_strip(a_tenth, 1000, 0, sizing).first.size());
}

// Elements of the scene's ceiling (its surfaces named ceiling-…) and of the others.
std::pair<std::size_t, std::size_t> ceiling_and_rest(const PreparedScene& prepared,
                                                     const ElementMesh& mesh) {
    std::size_t ceiling = 0;
    for (const MeshElement& e : mesh.elements())
        ceiling +=
            prepared.surface_names.at(static_cast<std::size_t>(e.surface)).rfind("ceiling", 0) == 0
                ? 1
                : 0;
    return {ceiling, mesh.size() - ceiling};
}

// A light 2 cm under the ceiling that sends nothing upward (a lambertian downlight, an IES table
// dark above the horizontal, a small emitting disc facing down) leaves the ceiling round it cut
// as far from any light; the walls beside it are cut finer. A bulb shining all round cuts both.
TEST(ElementMesh, LightsDarkAboveLeaveTheCeilingBehindThemUncut) {
    const ElementSizing sizing{0.4, 1.2};
    const Vec3 spot{0.5, 0.5, 2.98};
    const auto mesh_with = [&](const std::function<void(Scene&)>& add) {
        Scene scene = panel_room_with_sensors();
        add(scene);
        const PreparedScene prepared = prepare_scene(scene);
        return ceiling_and_rest(prepared, ElementMesh(prepared, sizing));
    };
    const auto [bare_ceiling, bare_rest] = mesh_with([](Scene&) {});
    const auto downlight = [&](Distribution d, std::optional<PhotometricTable> table) {
        return mesh_with([&](Scene& scene) {
            scene.luminaires.push_back(testing::luminaire("downlight", spot, 800, d));
            scene.luminaires.back().photometry = std::move(table);
        });
    };
    const std::vector<std::pair<std::size_t, std::size_t>> dark_above = {
        downlight(Distribution::lambertian, std::nullopt),
        downlight(Distribution::photometric,
                  PhotometricTable{{0, 45, 90}, {0}, {1000, 500, 0}, {}}),
        mesh_with([&](Scene& scene) {
            scene.materials.push_back(testing::gray("disc", 0.5, 20000));
            scene.surfaces.push_back(testing::polygon_surface(
                "disc", "disc", testing::ceiling_rect(0.45, 0.55, 0.45, 0.55, spot.z)));
        })};
    for (const auto& [ceiling, rest] : dark_above) {
        EXPECT_EQ(ceiling, bare_ceiling);
        EXPECT_GT(rest, bare_rest + 10);
    }
    // A table with light up to 135° reaches the ceiling: cut like a bulb's.
    const auto wide = downlight(Distribution::photometric,
                                PhotometricTable{{0, 90, 135, 180}, {0}, {1000, 500, 100, 0}, {}});
    const auto bulb = downlight(Distribution::isotropic, std::nullopt);
    EXPECT_GT(wide.first, bare_ceiling + 10);
    EXPECT_GT(bulb.first, bare_ceiling + 10);
}

// Forty lamps, more than a triangle weighs before its list is narrowed to those within reach
// of it as it is cut: every element still keeps to its nearest lamp's distance.
TEST(ElementMesh, ManyLuminairesNarrowedAsPiecesAreCutStillSizeEveryElement) {
    Scene scene = panel_room_with_sensors();
    for (int i = 0; i < 40; ++i) {
        scene.luminaires.push_back(testing::luminaire(
            "lamp " + std::to_string(i), {0.3 + 0.45 * (i % 8), 0.4 + 0.8 * (i / 8), 2.7}, 100));
    }
    const PreparedScene prepared = prepare_scene(scene);
    const ElementSizing sizing{0.4, 1.2};
    const ElementMesh mesh(prepared, sizing);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Triangle& t = mesh[i].triangle;
        const Vec3 centre = (t.a + t.b + t.c) / 3.0;
        double apart = sizing.light_reach_m;
        for (const PreparedLuminaire& l : prepared.luminaires)
            apart = std::min(apart, length(centre - l.position));
        const double longest = std::max({length(t.b - t.a), length(t.c - t.b), length(t.a - t.c)});
        EXPECT_LE(longest, sizing.max_edge_m *
                               std::max(apart / sizing.light_reach_m, ElementSizing::kFinest) *
                               (1 + 1e-12))
            << "element " << i;
    }
    EXPECT_EQ(ElementMesh::count(prepared, sizing).elements, mesh.size());
}

// A stop (a time limit, a cancel) cuts meshing short, with no elements: a million triangles take
// seconds to cut, which a short time limit was overrun by.
TEST(ElementMesh, AStopCutsMeshingShortWithNoElements) {
    const PreparedScene prepared = prepare_scene(panel_room_with_sensors());
    const ElementSizing sizing{0.1};
    const ElementMesh whole(prepared, sizing, [] { return false; });
    EXPECT_GT(whole.size(), 1000u);
    EXPECT_EQ(whole.size(), ElementMesh(prepared, sizing).size());
    const ElementMesh stopped(prepared, sizing, [] { return true; });
    EXPECT_EQ(stopped.size(), 0u);
    EXPECT_TRUE(stopped.sides().empty());
}

// A rack's beam (24.3 m by 12 cm) and a long thin triangle are cut into a strip of cells whose
// two triangles are each other's coarser half, four elements per edge length along them (cells
// half an edge long), not the 1 458 that bisecting the beam's triangles made; count() says what
// the mesh holds.
TEST(ElementMesh, CutsLongStripsIntoAsFewElementsAsTheirLength) {
    Scene scene;
    scene.materials = {testing::gray("steel", 0.5)};
    scene.surfaces.push_back(testing::polygon_surface(
        "beam", "steel", testing::rect({0, 0, 1}, {24.3, 0, 0}, {0, 0.12, 0})));
    scene.surfaces.push_back(
        testing::polygon_surface("blade", "steel", {{0, 2, 1}, {12, 2.05, 1}, {0, 2.1, 1}}));
    const PreparedScene prepared = prepare_scene(scene);
    const double edge = 0.71;
    const ElementMesh mesh(prepared, {edge});
    std::map<int, std::size_t> per_piece;
    std::map<int, double> area;
    std::size_t paired = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        ++per_piece[mesh[i].piece];
        area[mesh[i].piece] += mesh[i].area_m2;
        if (mesh[i].sibling >= 0) ++paired;
        for (const auto& [p, q] : {std::pair{mesh[i].triangle.a, mesh[i].triangle.b},
                                   {mesh[i].triangle.b, mesh[i].triangle.c},
                                   {mesh[i].triangle.c, mesh[i].triangle.a}}) {
            EXPECT_LE(length(q - p), edge * (1 + 1e-12));
        }
    }
    ASSERT_EQ(per_piece.size(), 2u);
    for (const auto& [piece, sum] : area) {
        const double whole = prepared.pieces[static_cast<std::size_t>(piece)].area_m2;
        EXPECT_NEAR(sum, whole, 1e-9 * whole) << "piece " << piece;
    }
    EXPECT_LE(per_piece[0], 2 * static_cast<std::size_t>(std::ceil(2 * 24.3 / edge)) + 2);
    EXPECT_LE(per_piece[1], 2 * static_cast<std::size_t>(std::ceil(2 * 12 / edge)) + 2);
    EXPECT_GE(paired, mesh.size() * 9 / 10);  // the strip's cells, all but a few at the tips
    const ElementCount counted = ElementMesh::count(prepared, {edge});
    EXPECT_EQ(counted.elements, mesh.size());
    EXPECT_EQ(counted.sides, mesh.sides().size());
}

// A panel hung 1 cm under the ceiling hides the ceiling behind it: light reaches none of it, so
// the photons' flux must be spread over the rest of those elements (the classroom's work plane
// read 0.09 % dark without). What lies farther away hides nothing: the floor under a desk, or
// under a board seen from its black back (wound the wrong way), keeps its whole area.
TEST(ElementMesh, OpenAreasLeaveOutWhatASurfaceRightInFrontHides) {
    Scene scene;
    scene.materials = {testing::gray("wall", 0.5), testing::gray("panel", 0, 1000)};
    scene.surfaces = testing::closed_room(4, 4, 3, "wall");
    scene.surfaces.push_back(testing::polygon_surface(
        "panel", "panel", testing::ceiling_rect(1.5, 2.5, 1.5, 2.5, 2.99)));
    scene.surfaces.push_back(testing::box_surface("desk", "wall", {0.5, 0.5, 0}, {1.5, 1, 0.75},
                                                  /*facing_in=*/false));
    // A board wound the wrong way: the floor under it sees its black back.
    Polygon board = testing::ceiling_rect(2.5, 3.5, 2.5, 3.5, 2);
    std::reverse(board.begin(), board.end());
    scene.surfaces.push_back(testing::polygon_surface("board", "wall", board));
    const PreparedScene prepared = prepare_scene(scene);
    ElementMesh mesh(prepared, {0.1});
    const std::unique_ptr<Visibility> visibility = make_embree_visibility(mesh.triangles());
    std::uint64_t rays = 0;
    mesh.measure_open_areas(*visibility, 0.02, rays);
    EXPECT_EQ(rays, 4 * mesh.sides().size());
    std::map<std::string, std::pair<double, double>> open_and_whole;  // by surface name
    for (const ElementSide& side : mesh.sides()) {
        const MeshElement& e = mesh[static_cast<std::size_t>(side.element)];
        auto& [open, whole] =
            open_and_whole[prepared.surface_names[static_cast<std::size_t>(e.surface)]];
        EXPECT_GE(side.open_area_m2, 0.0);
        EXPECT_LE(side.open_area_m2, e.area_m2 * (1 + 1e-12));
        open += side.open_area_m2;
        whole += e.area_m2;
    }
    // The panel hides 1 m² of the ceiling (4 points per element of at most 0.1 m: its outline is
    // known to about an element's width all round).
    EXPECT_NEAR(open_and_whole.at("ceiling").first, 16 - 1, 4 * 0.1);
    for (const char* name : {"panel", "floor", "wall-west", "desk", "board"}) {
        EXPECT_DOUBLE_EQ(open_and_whole.at(name).first, open_and_whole.at(name).second) << name;
    }
}

TEST(LightSources, PhotonsCarryTheEmittedFluxOnAverage) {
    Scene scene = panel_room_with_sensors();
    scene.luminaires.push_back(
        testing::luminaire("lamp", {1, 1, 2.5}, 2000, Distribution::lambertian, {0, 0, -1}));
    const PreparedScene prepared = prepare_scene(scene);
    const LightSources sources(prepared, 1e-6);
    const double emitted = 2000 + 1000 * 1.0;  // the lamp, and the 1 m² panel
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        SampleStream rng(3, 0, static_cast<std::uint64_t>(i));
        sum += sources.emit(rng).flux[0];
    }
    EXPECT_NEAR(sum / n, emitted, 1e-9 * emitted);  // weights are exact for these sources
}

TEST(MonteCarlo, FurnaceSensorsSeeTheExactRadiosityWithinTheEstimate) {
    for (const double rho : {0.5, 0.9}) {
        Scene scene = testing::furnace_cube(rho);
        scene.sensors.push_back(testing::sensor_points(
            "inside", {{0.5, 0.5, 0.5}, {0.2, 0.7, 0.3}, {0.8, 0.1, 0.9}, {0.5, 0.5, 0.05}}));
        const Result r = testing::solve_with(scene, "monte-carlo", 0.01);
        ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
        const double exact = 1 / (1 - rho);
        const std::vector<double> expected(4, exact);
        const double error = rms_relative_error(r.sensors.at(0).illuminance, expected);
        EXPECT_LE(error, r.stats.error_estimate) << "rho " << rho << ": " << describe(r);
        EXPECT_LE(r.stats.error_estimate, 0.01);
    }
}

TEST(MonteCarlo, AgreesWithTheDenseSolverWithinBothEstimates) {
    const Scene scene = panel_room_with_sensors();
    const Result mc = testing::solve_with(scene, "monte-carlo", 0.01);
    const Result h = testing::solve_with(scene, "direct", 0.01);
    ASSERT_EQ(mc.status, SolveStatus::converged) << describe(mc);
    ASSERT_NE(h.status, SolveStatus::failed) << describe(h);
    const double difference =
        rms_relative_error(mc.sensors.at(0).illuminance, h.sensors.at(0).illuminance);
    EXPECT_LE(difference, mc.stats.error_estimate + h.stats.error_estimate) << describe(mc);
    // Tolerance means error: no solve 20× more accurate than asked.
    EXPECT_GE(mc.stats.error_estimate, 0.05 * 0.01);
    EXPECT_GT(mc.stats.error_parts.gather_noise, 0);
    EXPECT_GT(mc.stats.error_parts.photon_noise, 0);
}

// At a time limit the first round still completes (for a tenth of the limit, at least 0.5 s,
// past it): its samples are what any estimate is made of. Stopped in it, the furnished office
// answered 0 lx everywhere with an estimate of 0.04 %.
TEST(MonteCarlo, AtATimeLimitTheFirstRoundStillCompletes) {
    Scene scene = testing::furnace_cube(0.5);
    scene.sensors.push_back(testing::sensor_points("inside", {{0.5, 0.5, 0.5}, {0.2, 0.7, 0.3}}));
    SolveOptions options;
    options.method = "monte-carlo";
    options.tolerance = 0.001;
    options.max_seconds = 1e-3;
    const Result r = solve(scene, options);
    ASSERT_EQ(r.status, SolveStatus::stopped) << describe(r);
    EXPECT_EQ(r.stats.iterations, 1u) << describe(r);
    const double error = rms_relative_error(r.sensors.at(0).illuminance, {2, 2});
    EXPECT_LT(error, 0.1) << describe(r);
    EXPECT_GE(r.stats.error_estimate, error) << describe(r);
    EXPECT_GE(r.sensors.at(0).error_estimate, error) << describe(r);
}

// A cancel ends even the first round: an answer whose samples measure nothing claims twice its
// own size, overall and for each sensor set (its error is its size where it is dark).
TEST(MonteCarlo, AnAnswerWithoutOneCompleteRoundClaimsTwiceItsSize) {
    Scene scene = testing::furnace_cube(0.5);
    scene.sensors.push_back(testing::sensor_points("inside", {{0.5, 0.5, 0.5}, {0.2, 0.7, 0.3}}));
    SolveOptions options;
    options.method = "monte-carlo";
    CancellationToken cancelled;
    cancelled.cancel();
    const Result r = solve(scene, options, nullptr, &cancelled);
    ASSERT_EQ(r.status, SolveStatus::stopped) << describe(r);
    EXPECT_GE(r.stats.error_estimate, 2) << describe(r);
    EXPECT_GE(r.sensors.at(0).error_estimate, 2) << describe(r);
    EXPECT_GE(r.stats.error_estimate, rms_relative_error(r.sensors.at(0).illuminance, {2, 2}));
}

// Tolerance means error: at a loose tolerance the first round is cut to it, so that the answer
// is not ten times more accurate than asked (its estimate is about twice its error).
TEST(MonteCarlo, ALooseToleranceIsNotMetTenTimesOver) {
    const Scene scene = panel_room_with_sensors();
    const double tolerance = 0.1;
    const Result loose = testing::solve_with(scene, "monte-carlo", tolerance);
    const Result reference = testing::solve_with(scene, "monte-carlo", 0.002);
    ASSERT_EQ(loose.status, SolveStatus::converged) << describe(loose);
    ASSERT_EQ(reference.status, SolveStatus::converged) << describe(reference);
    const double error =
        rms_relative_error(loose.sensors.at(0).illuminance, reference.sensors.at(0).illuminance);
    EXPECT_GE(error, tolerance / 10) << describe(loose);
    EXPECT_LE(error + reference.stats.error_estimate, loose.stats.error_estimate)
        << describe(loose);
}

TEST(MonteCarlo, AMirrorImageAgreesWithinBothEstimates) {
    const Scene scene = panel_room_with_sensors();
    Scene mirrored = scene;  // x → 4 − x; polygons reversed to keep their fronts
    for (auto& s : mirrored.surfaces) {
        auto& poly = std::get<Polygon>(s.geometry);
        for (auto& v : poly) v.x = 4 - v.x;
        std::reverse(poly.begin(), poly.end());
    }
    for (auto& v : mirrored.sensors.at(0).points) v.x = 4 - v.x;
    const Result a = testing::solve_with(scene, "monte-carlo", 0.01);
    const Result b = testing::solve_with(mirrored, "monte-carlo", 0.01);
    ASSERT_EQ(b.status, SolveStatus::converged) << describe(b);
    const double difference =
        rms_relative_error(b.sensors.at(0).illuminance, a.sensors.at(0).illuminance);
    EXPECT_GT(difference, 0);  // other samples
    EXPECT_LE(difference, a.stats.error_estimate + b.stats.error_estimate);
}

// With sensors, and without them (the estimate then read from the surfaces' batch tallies).
TEST(MonteCarlo, SameAnswerForAnyNumberOfThreads) {
    Scene scene = panel_room_with_sensors();
    scene.luminaires.push_back(testing::luminaire("lamp", {3, 3, 2.5}, 1500));
    for (const bool sensors : {true, false}) {
        if (!sensors) scene.sensors.clear();
        SolveOptions options;
        options.method = "monte-carlo";
        options.threads = 1;
        const Result one = solve(scene, options);
        options.threads = 2;
        const Result two = solve(scene, options);
        ASSERT_EQ(one.status, SolveStatus::converged) << describe(one);
        ASSERT_EQ(one.sensors.size(), two.sensors.size());
        if (sensors) {
            EXPECT_EQ(one.sensors.at(0).illuminance, two.sensors.at(0).illuminance);
        }
        ASSERT_EQ(one.surfaces.size(), two.surfaces.size());
        for (std::size_t i = 0; i < one.surfaces.size(); ++i) {
            EXPECT_EQ(one.surfaces[i].average_irradiance, two.surfaces[i].average_irradiance);
            EXPECT_EQ(one.surfaces[i].average_radiosity, two.surfaces[i].average_radiosity);
        }
        EXPECT_EQ(one.stats.rays, two.stats.rays) << sensors;
        EXPECT_EQ(one.stats.error_estimate, two.stats.error_estimate) << sensors;
    }
}

// A 1.2 × 0.6 m panel 2 m above three points, and 3.5 cm above them a black bar 5 mm wide (a
// monitor's edge seen from below) whose shadow is a band across the panel: the points see the
// panel's two ends beside the band, whose exact factors give their light. A shadow ray aimed
// at a uniform point of each small part of the panel weighted visibility by area within the
// part and read them 0.15 % bright, twice the estimate at 0.001.
TEST(MonteCarlo, PointsInAPenumbraGetThePanelsExactLight) {
    const double height = 2, bar = 0.035, y0 = -0.004, y1 = 0.001, exitance = 1000;
    Scene scene;
    scene.materials = {testing::gray("black", 0), testing::gray("panel", 0, exitance)};
    scene.surfaces = {
        testing::polygon_surface("panel", "panel",
                                 testing::ceiling_rect(-0.6, 0.6, -0.3, 0.3, height)),
        testing::box_surface("bar", "black", {-3, y0, bar}, {3, y1, bar + 0.0005}, false)};
    const std::vector<Vec3> points{{0, 0, 0}, {0.2, 0, 0}, {-0.3, 0, 0}};
    scene.sensors.push_back(testing::sensor_points("under the bar", points));
    // The bar's underside casts the band: y from y0 to y1 scaled by height / bar on the panel.
    const double band0 = y0 * height / bar, band1 = y1 * height / bar;
    std::vector<double> exact;
    for (const Vec3& x : points) {
        const Polygon near_end = testing::ceiling_rect(-0.6, 0.6, -0.3, band0, height);
        const Polygon far_end = testing::ceiling_rect(-0.6, 0.6, band1, 0.3, height);
        exact.push_back(exitance * (point_to_polygon_factor(x, {0, 0, 1}, near_end) +
                                    point_to_polygon_factor(x, {0, 0, 1}, far_end)));
    }
    const Result r = testing::solve_with(scene, "monte-carlo", 0.001);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_LE(rms_relative_error(r.sensors.at(0).illuminance, exact), r.stats.error_estimate)
        << describe(r);
}

// A bulb modelled as a sphere of 96 faces in a black room: its direct light at points below is
// the exact sum of its facing faces' factors (RADIANCE reads such a bulb 2–9 % dark, see
// tests/bench/results/living-room.md). Its pieces are more than a sensor's cut holds one by one,
// so most of them are drawn from clusters whose fronts face every way.
TEST(MonteCarlo, ABulbOfManyFacesGivesTheExactSumOfTheirLight) {
    const double exitance = 50000;
    Scene scene;
    scene.materials = {testing::gray("black", 0), testing::gray("bulb", 0, exitance)};
    scene.surfaces = testing::closed_room(4, 4, 3, "black");
    scene.surfaces.push_back(testing::sphere_surface("bulb", "bulb", {2, 2, 1.7}, 0.05, 8, 12));
    const std::vector<Vec3> points{{2.3, 1.6, 0.75}, {2, 2, 0.75}, {1.1, 2.4, 0.75}};
    scene.sensors.push_back(testing::sensor_points("table", points));
    const PreparedScene prepared = prepare_scene(scene);
    std::vector<double> exact;
    for (const Vec3& p : points) {
        const Vec3 x = p - prepared.world_origin;
        double sum = 0;
        for (const Piece& piece : prepared.pieces) {
            if (prepared.surface_names[static_cast<std::size_t>(piece.surface)] == "bulb")
                sum += exitance *
                       front_point_to_polygon_factor(x, {0, 0, 1}, piece.vertices, piece.normal);
        }
        exact.push_back(sum);
    }
    const Result r = testing::solve_with(scene, "monte-carlo", 0.002);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_LE(rms_relative_error(r.sensors.at(0).illuminance, exact), r.stats.error_estimate)
        << describe(r);
}

// Without sensors the error is stated on the surfaces' means, which have no discretisation part
// (photons reflect from where they land) and no ray sets: only the photons' noise. A furnace's
// six faces each receive E / (1 − ρ).
TEST(MonteCarlo, MeasuresTheSurfacesWithoutSensors) {
    constexpr double kRho = 0.5;
    const Result r =
        testing::solve_with(testing::boxes_as_polygons(testing::furnace_cube(kRho)), "monte-carlo");
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    ASSERT_EQ(r.surfaces.size(), 6u);
    double squares = 0;
    for (const SurfaceResult& s : r.surfaces) {
        const double irradiance = s.average_irradiance / (1 / (1 - kRho)) - 1;
        const double radiosity = s.average_radiosity / (1 / (1 - kRho)) - 1;
        squares += (irradiance * irradiance + radiosity * radiosity) / 12;
    }
    const double error = std::sqrt(squares);
    EXPECT_GT(error, 0);
    EXPECT_GE(r.stats.error_estimate, error);
    EXPECT_LE(r.stats.error_estimate, 0.01);
    EXPECT_EQ(r.stats.error_parts.photon_noise, r.stats.error_estimate);
    EXPECT_EQ(r.stats.error_parts.gather_noise, 0);
    EXPECT_EQ(r.stats.error_parts.discretisation, 0);
}

// A row of books 1 cm apart under a lamp, in a room of `room` reflectance: the faces between
// them are nearer their neighbours than the open-area test looks (2 % of the mean free path).
Scene books_under_a_lamp(double room, double books) {
    Scene scene;
    scene.materials = {testing::gray("room", room), testing::gray("book", books)};
    scene.surfaces = testing::closed_room(4, 4, 3, "room");
    for (int i = 0; i < 20; ++i) {
        const double x = 1.4 + 0.03 * i;
        scene.surfaces.push_back(testing::box_surface("book " + std::to_string(i), "book",
                                                      {x, 1.85, 0}, {x + 0.02, 2.15, 0.3},
                                                      /*facing_in=*/false));
    }
    scene.luminaires.push_back(
        testing::luminaire("lamp", {1.7, 2, 0.8}, 1000, Distribution::isotropic, {0, 0, -1}));
    return scene;
}

// Light that enters such a gap lands on sides counted as hidden; it is absorbed there all the
// same. With black surfaces every photon is absorbed where it first lands, so the surfaces
// absorb exactly what the lamp emits.
TEST(MonteCarlo, LightInAHiddenGapIsAbsorbedThere) {
    const Result r = testing::solve_with(books_under_a_lamp(0, 0), "monte-carlo", 0.05);
    ASSERT_NE(r.status, SolveStatus::failed) << describe(r);
    EXPECT_NEAR(r.stats.absorbed_flux_lm, r.stats.emitted_flux_lm, 1e-9 * 1000) << describe(r);
}

// A gather ray that finds its way into the gap reads the light that entered it, over the
// sides' whole area (they have no open area to spread it over), not darkness.
TEST(PhotonField, AHiddenSideIsLitByWhatEntersItsGap) {
    const PreparedScene prepared = prepare_scene(books_under_a_lamp(0.5, 0.5));
    ElementMesh mesh(prepared, {0.05});
    const std::unique_ptr<Visibility> visibility = make_embree_visibility(mesh.triangles());
    std::uint64_t rays = 0;
    mesh.measure_open_areas(*visibility, 0.02, rays);
    const LightSources sources(prepared, visibility->epsilon());
    PhotonField field(prepared, mesh, 5);
    field.trace(200000, sources, *visibility, [] { return false; });
    int hidden = 0, lit = 0;
    for (std::size_t s = 0; s < mesh.sides().size(); ++s) {
        const MeshElement& e = mesh[static_cast<std::size_t>(mesh.sides()[s].element)];
        const std::string& name = prepared.surface_names[static_cast<std::size_t>(e.surface)];
        // The books' sides with no open area: the faces between them.
        if (mesh.sides()[s].open_area_m2 > 0 || name.rfind("book", 0) != 0) continue;
        ++hidden;
        if (field.indirect(static_cast<int>(s))[0] > 0) ++lit;
    }
    ASSERT_GT(hidden, 100);
    // Light enters the 30 cm deep gaps at their top and ends only: 19 % of their sides are lit
    // by these photons (none before they were read over their whole area).
    EXPECT_GT(lit, hidden / 10) << lit << " of " << hidden << " hidden sides lit";
}

TEST(MonteCarlo, ReportsItsStages) {
    const Result r = testing::solve_with(panel_room_with_sensors(), "monte-carlo");
    std::vector<std::string> names;
    for (const StageStats& s : r.stats.stages) names.push_back(s.name);
    EXPECT_EQ(names, (std::vector<std::string>{"prepare", "checks", "meshing", "photons", "gather",
                                               "estimate"}));
    std::uint64_t rays = 0;
    for (const StageStats& s : r.stats.stages) rays += s.rays;
    EXPECT_EQ(rays, r.stats.rays);
}

// A point 3 mm beside the foot of a 1 m board that a white floor strip lights from below: the
// board's foot reflects about 1.7 times its average light, and the point sees mostly its foot.
// Read with elements as large as the board, it gets what it gets with elements of 5 cm, but for
// what the one further bounce reads as an average (the strip is brighter beside the board: 0.4 %
// here); an element's average light at every hit (the old gather) read 4.4 % less.
TEST(SensorGather, APointBesideASurfaceReadsTheLightOfThatSpot) {
    Scene scene;
    scene.materials = {testing::gray("board", 0.5), testing::gray("white", 0.9),
                       testing::gray("panel", 0, 1000)};
    scene.surfaces = {
        testing::polygon_surface("board", "board",
                                 testing::rect({0, -0.5, 0}, {0, 1, 0}, {0, 0, 1})),
        testing::polygon_surface("strip", "white",
                                 testing::rect({0, -0.5, 0}, {1, 0, 0}, {0, 1, 0})),
        testing::polygon_surface("panel", "panel", testing::ceiling_rect(0, 1, -0.5, 0.5, 2))};
    scene.sensors.push_back(testing::sensor_points("beside", {{0.003, 0, 0.05}}));
    const GatheredPoint coarse = first_point(scene, 1.5, 1 << 22, 256);
    const GatheredPoint fine = first_point(scene, 0.05, 1 << 22, 256);
    const double spread = std::sqrt(coarse.gather_variance + coarse.photon_variance +
                                    fine.gather_variance + fine.photon_variance);
    EXPECT_LT(spread, 0.01 * fine.illuminance);
    EXPECT_NEAR(coarse.illuminance, fine.illuminance, 4 * spread + 0.01 * fine.illuminance);
}

// A point 0.5 m in front of a 1 m board whose lower half hides 2 cm behind a box: the point
// sees the board's open upper half, which is brighter than the board's average. Read with
// elements as large as the board, the average understates what the point sees; the depth check
// (each far hit's average against one bounce further) measures that, and with 5 cm elements it
// finds next to nothing.
TEST(SensorGather, TheDepthCheckMeasuresWhatAnElementAverageMisses) {
    Scene scene;
    scene.materials = {testing::gray("wall", 0.5), testing::gray("panel", 0, 1000)};
    scene.surfaces = {
        testing::polygon_surface("board", "wall", testing::rect({0, 0, 0}, {0, 0, 1}, {1, 0, 0})),
        testing::box_surface("box", "wall", {0, 0.02, 0}, {1, 0.3, 0.5}, false),
        testing::polygon_surface("floor", "wall", testing::rect({0, 0, 0}, {1, 0, 0}, {0, 2, 0})),
        testing::polygon_surface("panel", "panel", testing::ceiling_rect(0, 1, 0.5, 1.5, 2))};
    scene.sensors.push_back(testing::sensor_points("front", {{0.5, 0.8, 0.75}}, {0, -1, 0}));
    const GatheredPoint coarse = first_point(scene, 1.5, 1 << 23, 1024);
    const GatheredPoint fine = first_point(scene, 0.05, 1 << 23, 1024);
    // Read whole, the board is 1.9 % darker than with 5 cm elements; the check finds about 70 %
    // of that, well beyond its noise, and nothing beyond its noise with 5 cm elements.
    const double gap = std::abs(fine.illuminance - coarse.illuminance);
    const double noise =
        std::sqrt(coarse.gather_variance + coarse.photon_variance + fine.gather_variance +
                  fine.photon_variance + coarse.depth_difference_variance);
    EXPECT_GT(gap, 4 * noise);
    EXPECT_GT(coarse.depth_difference_squared, 9 * coarse.depth_difference_variance);
    EXPECT_NEAR(std::sqrt(coarse.depth_difference_squared), gap, 3 * noise);
    EXPECT_LT(fine.depth_difference_squared, 9 * fine.depth_difference_variance);
}

// A lamp in an open shade (a cone of 0.25 m down to 0.05 m, white on both sides, its bulb a
// point) 0.9 m above a point on a dark floor: the point sees the shade's bright inside in a few
// rays of a set or none. Rays aimed at the bright sides give the same light, its variance over
// ray sets a twentieth of what cosine rays alone leave.
TEST(SensorGather, RaysAimedAtBrightSidesKeepTheMeanAndCutTheSpread) {
    Scene scene;
    Material shade = testing::gray("shade", 0.8);
    shade.two_sided = true;
    scene.materials = {testing::gray("floor", 0.1), shade};
    scene.surfaces = {testing::polygon_surface("floor", "floor",
                                               testing::rect({-2, -2, 0}, {4, 0, 0}, {0, 4, 0}))};
    MeshGeometry cone;
    const int segments = 16;
    for (int k = 0; k < segments; ++k) {
        const double a = 2 * std::numbers::pi * k / segments;
        cone.vertices.push_back({0.25 * std::cos(a), 0.25 * std::sin(a), 1.6});
        cone.vertices.push_back({0.05 * std::cos(a), 0.05 * std::sin(a), 1.85});
        const int j = (k + 1) % segments;
        cone.faces.push_back({2 * k, 2 * j, 2 * j + 1, 2 * k + 1});
    }
    Surface cone_surface;
    cone_surface.name = "shade";
    cone_surface.material = "shade";
    cone_surface.geometry = std::move(cone);
    scene.surfaces.push_back(std::move(cone_surface));
    scene.luminaires.push_back(
        testing::luminaire("bulb", {0, 0, 1.7}, 1000, Distribution::isotropic));
    scene.sensors.push_back(testing::sensor_points("below", {{0.2, 0.1, 0.75}}));
    const GatherSetup setup(scene, 0.05, 1 << 20);
    SensorGather cosine = setup.gather(), aimed = setup.gather();
    aimed.aim_at_bright_sides(setup.field, std::size_t{1} << 30);
    const auto never = [] { return false; };
    cosine.gather(2000, never);
    aimed.gather(2000, never);
    const GatheredPoint a = aimed.evaluate(setup.field).at(0);
    const GatheredPoint c = cosine.evaluate(setup.field).at(0);
    EXPECT_NEAR(a.illuminance, c.illuminance, 4 * std::sqrt(a.gather_variance + c.gather_variance));
    EXPECT_LT(a.gather_variance, c.gather_variance / 10);
}

// A point under a table in a room lit by a ceiling panel sees no lamp: its light is what the
// floor and walls around the table reflect, and its ray sets spread by which of them their rays
// land on. After a pilot gather, the sets take cheap rays reading their elements' direct light
// (SideDirectCache): the same light, at a fraction of the spread of sets without them.
TEST(SensorGather, CheapRaysKeepTheMeanAndCutTheSpreadUnderATable) {
    Scene scene = testing::room_with_ceiling_panel(0.7, 1000);
    scene.surfaces.push_back(
        testing::box_surface("table", "wall", {1.4, 1.4, 0.7}, {2.6, 2.6, 0.75}, false));
    // Two points, so that their threads read the cache at once (the test runs under TSan).
    scene.sensors.push_back(testing::sensor_points("under", {{2, 2, 0.3}, {2.2, 2, 0.3}}));
    const GatherSetup setup(scene, 0.25, 1 << 20);
    SensorGather plain = setup.gather(), cheap = setup.gather(), tight = setup.gather();
    const auto never = [] { return false; };
    plain.gather(256, never);
    cheap.gather(8, never);
    EXPECT_GT(cheap.take_cheap_rays(never, std::size_t{1} << 30), 0u);
    // Cheap rays only save rays: where the pilot's sets would not hold theirs, none are taken.
    tight.gather(8, never);
    EXPECT_EQ(tight.take_cheap_rays(never, 1024), 0u);
    cheap.gather(256, never);
    const GatheredPoint p = plain.evaluate(setup.field).at(0);
    const GatheredPoint c = cheap.evaluate(setup.field).at(0);
    EXPECT_EQ(c.sets, 256);
    EXPECT_NEAR(c.illuminance, p.illuminance, 4 * std::sqrt(p.gather_variance + c.gather_variance));
    EXPECT_LT(c.gather_variance, p.gather_variance / 10);
}

// Two sets of 50 points with the same photon variance per point: in one each point's batches
// scatter on their own, in the other all points move together batch by batch. The shared
// scatter does not average over the set's points, so it gets the larger margin (2 against 1.5).
TEST(MonteCarloError, PhotonNoiseTheSetSharesGetsTheLargerMargin) {
    constexpr int kPoints = 50;
    std::vector<GatheredPoint> own(kPoints), shared(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        for (int q = 0; q < PhotonField::kBatches; ++q) {
            const double sign = q % 2 ? 1.0 : -1.0;  // ±1 lx about 100 lx
            own[static_cast<std::size_t>(i)].photon_batches[static_cast<std::size_t>(q)] =
                100 + (((q + i) % 2) ? 1.0 : -1.0);
            shared[static_cast<std::size_t>(i)].photon_batches[static_cast<std::size_t>(q)] =
                100 + sign;
        }
    }
    // The variance of a mean of 16 values of ±1: 16 / (16 · 15).
    for (auto* set : {&own, &shared}) {
        for (GatheredPoint& p : *set) {
            p.illuminance = 100;
            p.photon_variance = 1.0 / 15;
        }
    }
    const std::vector<std::size_t> sizes{kPoints};
    const double sigma = std::sqrt(1.0 / 15) / 100;
    const double apart = worst_error(set_errors(own, sizes)).parts.photon_noise;
    const double together = worst_error(set_errors(shared, sizes)).parts.photon_noise;
    EXPECT_NEAR(apart, 1.5 * sigma, 1e-12);
    EXPECT_NEAR(together, 2 * sigma, 1e-12);
}

// Fifty points with the same gather noise in all: their set's RMS error averages fifty draws,
// and the margin is 1.5. One point with all of it (a point beside a lamp): the set's error is
// one draw, and the margin is the square root of χ²₁'s upper 1 % quantile (6.63), 2.57.
TEST(MonteCarloError, NoiseHeldByOnePointGetsTheMarginOfOneDraw) {
    constexpr int kPoints = 50;
    std::vector<GatheredPoint> even(kPoints), one(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        for (auto* set : {&even, &one}) {
            GatheredPoint& p = (*set)[static_cast<std::size_t>(i)];
            p.illuminance = 100;
            p.sets = 8;
        }
        even[static_cast<std::size_t>(i)].gather_variance = 1;
    }
    one[0].gather_variance = kPoints;
    const std::vector<std::size_t> sizes{kPoints};
    const double sigma = std::sqrt(1.0) / 100;  // √(Σ var / n) over the mean, in both sets
    EXPECT_NEAR(worst_error(set_errors(even, sizes)).parts.gather_noise, 1.5 * sigma, 1e-12);
    EXPECT_NEAR(worst_error(set_errors(one, sizes)).parts.gather_noise, 2.57 * sigma, 0.01 * sigma);
}

// The coarser level's difference counts in the estimate either way, but calls for a finer mesh
// only when it stands out of its noise: 50 points whose squared differences exceed their
// variance by 1 lx², a sum of 50 lx², with a variance of 2 lx² each (noise alone spreads that sum
// by 20 lx², so 50 is within three deviations) or of 0.01 lx² (by 0.1 lx²).
TEST(MonteCarloError, ABiasCallsForAFinerMeshOnlyAboveItsNoise) {
    constexpr int kPoints = 50;
    auto set_with_variance = [](double variance) {
        std::vector<GatheredPoint> points(kPoints);
        for (GatheredPoint& p : points) {
            p.illuminance = 100;
            p.coarse_difference_variance = variance;
            p.coarse_difference_squared = variance + 1;
        }
        return worst_error(set_errors(points, {kPoints}));
    };
    const MonteCarloError noisy = set_with_variance(2);
    const MonteCarloError clear = set_with_variance(0.01);
    // The levels differ by 1 % beyond their noise; the coarser elements are √2 times the size,
    // so a first-order bias of the fine level is that difference over √2 − 1.
    const double bias = 0.01 / (std::sqrt(2.0) - 1);
    EXPECT_NEAR(noisy.parts.discretisation, bias, 1e-12);
    EXPECT_NEAR(clear.parts.discretisation, bias, 1e-12);
    EXPECT_FALSE(noisy.discretisation_significant);
    EXPECT_TRUE(clear.discretisation_significant);
}

}  // namespace
}  // namespace radiant
