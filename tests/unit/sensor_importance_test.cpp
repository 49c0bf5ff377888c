// Importance from the sensors: surfaces no sensor can see, directly or by reflection, get the
// least refinement weight, so the hierarchical solver leaves them coarse — and what the sensors
// read does not change.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hierarchy/sensor_importance.h"
#include "linkable_scene.h"
#include "parallel/fork_join.h"
#include "scene_builder.h"
#include "solve_with.h"

namespace radiant {
namespace {

using testing::describe;

// Two 4 × 4 × 3 m rooms sealed from each other by a 0.2 m partition (the floor, the ceiling and
// the long walls run through both), each lit by a 1 m² ceiling panel. Sensors: a work plane in
// room A, and in room B too when `sensors_in_b`.
Scene two_sealed_rooms(bool sensors_in_b) {
    Scene scene;
    scene.name = "two-sealed-rooms";
    scene.materials = {testing::gray("wall", 0.7), testing::gray("panel", 0.0, 5000.0)};
    scene.surfaces = testing::closed_room(8.2, 4, 3, "wall");
    scene.surfaces.push_back(
        testing::box_surface("partition", "wall", {4, 0, 0}, {4.2, 4, 3}, false));
    scene.surfaces.push_back(testing::polygon_surface(
        "panel-a", "panel", testing::ceiling_rect(1.5, 2.5, 1.5, 2.5, 2.99)));
    scene.surfaces.push_back(testing::polygon_surface(
        "panel-b", "panel", testing::ceiling_rect(5.7, 6.7, 1.5, 2.5, 2.99)));
    scene.sensors.push_back(
        testing::sensor_grid("room-a", {0.25, 0.25, 0.8}, {3.5, 0, 0}, {0, 3.5, 0}, 5, 5));
    if (sensors_in_b) {
        scene.sensors.push_back(
            testing::sensor_grid("room-b", {4.45, 0.25, 0.8}, {3.5, 0, 0}, {0, 3.5, 0}, 5, 5));
    }
    return scene;
}

// The scene as the hierarchical pipeline links it, and its sensors' importance.
struct Linkable : testing::LinkableScene {
    using LinkableScene::LinkableScene;
    ImportanceEstimate importance() const {
        return estimate_sensor_importance(scene, roots, *tree, *visibility, triangle_piece, 1);
    }
};

TEST(SensorImportance, WithoutSensorsEverySurfaceGetsFullWeight) {
    Scene scene = two_sealed_rooms(false);
    scene.sensors.clear();
    const Linkable linkable(scene);
    const ImportanceEstimate w = linkable.importance();
    EXPECT_EQ(w.rays, 0u);
    ASSERT_EQ(w.refinement_weight.size(), linkable.roots.size());
    for (const double x : w.refinement_weight) EXPECT_EQ(x, 1.0);
}

TEST(SensorImportance, SealedRoomWithoutSensorsGetsTheLeastWeight) {
    const Linkable linkable(two_sealed_rooms(false));
    const ImportanceEstimate w = linkable.importance();
    EXPECT_GT(w.rays, 0u);
    std::size_t in_a = 0, full_in_a = 0, in_b = 0;
    for (std::size_t i = 0; i < linkable.roots.size(); ++i) {
        const PatchGeometry& p = linkable.roots.patch(i);
        if (p.hidden) continue;
        const Vec3 at = p.centroid + linkable.scene.world_origin;  // local frame → metres
        const double x = at.x;
        if (x > 4.2) {
            ++in_b;
            EXPECT_EQ(w.per_area[i], 0.0) << "patch " << i;
            EXPECT_EQ(w.refinement_weight[i], kMinRefinementWeight) << "patch " << i;
        } else if (x < 4) {
            // The ceiling behind panel A is seen only through the 1 cm gap above the panel.
            if (at.z > 2.99 && at.x > 1.5 && at.x < 2.5 && at.y > 1.5 && at.y < 2.5) continue;
            ++in_a;
            if (w.refinement_weight[i] == 1.0) ++full_in_a;
        }
    }
    ASSERT_GT(in_b, 10u);
    ASSERT_GT(in_a, 10u);
    // The rest of room A is seen directly or through one reflection (ρ 0.7).
    EXPECT_EQ(full_in_a, in_a);
}

TEST(SensorImportance, StopsWhenAsked) {
    const Linkable linkable(two_sealed_rooms(false));
    const ImportanceEstimate w = estimate_sensor_importance(
        linkable.scene, linkable.roots, *linkable.tree, *linkable.visibility,
        linkable.triangle_piece, 1, [] { return true; });
    EXPECT_EQ(w.rays, 0u);
}

TEST(SensorImportance, SameForAnyThreadCount) {
    const Linkable linkable(two_sealed_rooms(false));
    ImportanceEstimate one;
    run_with_threads(1, [&] { one = linkable.importance(); });
    ImportanceEstimate two;
    run_with_threads(2, [&] { two = linkable.importance(); });
    EXPECT_EQ(one.rays, two.rays);
    EXPECT_EQ(one.per_area, two.per_area);
    EXPECT_EQ(one.refinement_weight, two.refinement_weight);
}

// Triangles of the solved mesh whose centroid lies east of the partition (room B).
std::size_t triangles_in_room_b(const SolvedMesh& mesh) {
    std::size_t n = 0;
    for (const auto& t : mesh.triangles) {
        double x = 0;
        for (const int v : t) x += mesh.vertices[static_cast<std::size_t>(v)].x;
        if (x / 3 > 4.2) ++n;
    }
    return n;
}

TEST(SensorImportance, UnseenRoomStaysCoarseAndTheSensorsReadTheSame) {
    const double tolerance = 0.01;
    auto solve_scene = [&](bool sensors_in_b) {
        SolveOptions options;
        options.method = "hierarchical";
        options.tolerance = tolerance;
        options.want_mesh = true;
        return solve(two_sealed_rooms(sensors_in_b), options);
    };
    const Result seen = solve_scene(true);
    const Result unseen = solve_scene(false);
    ASSERT_EQ(seen.status, SolveStatus::converged) << describe(seen) << ": " << seen.stop_reason;
    ASSERT_EQ(unseen.status, SolveStatus::converged) << describe(unseen);
    ASSERT_TRUE(seen.mesh && unseen.mesh);
    EXPECT_LT(triangles_in_room_b(*unseen.mesh), triangles_in_room_b(*seen.mesh) / 2)
        << describe(unseen) << " against " << describe(seen);
    EXPECT_LT(unseen.stats.links, seen.stats.links);
    std::cerr << describe(unseen) << " against " << describe(seen) << "\n";
    // Room A's work plane does not notice: each reading within a tenth of the tolerance.
    const std::vector<double>& a = unseen.sensors[0].illuminance;
    const std::vector<double>& b = seen.sensors[0].illuminance;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 0.1 * tolerance * b[i]) << i;
    // Room B's surfaces, now coarse, still get their light within the tolerance.
    for (std::size_t s = 0; s < seen.surfaces.size(); ++s) {
        const double want = seen.surfaces[s].average_irradiance;
        EXPECT_NEAR(unseen.surfaces[s].average_irradiance, want, tolerance * want)
            << seen.surfaces[s].name;
    }
}

}  // namespace
}  // namespace radiant
