// A coarser tolerance must never cost the hierarchical solver more, and a memory budget holds. Its
// root patches grow with the tolerance; parallel surfaces within a gap that grew with them cut
// every root along their outlines, and in a furnished office a solve at 0.3 took more time and
// memory than at 0.03.
#include <gtest/gtest.h>

#include <string>

#include "radiant/solve.h"
#include "scene_builder.h"

namespace radiant {
namespace {

// A 12 × 12 × 3 m office: ceiling panels over a grid of tables (boxes) with horizontal tops.
Scene small_office() {
    Scene scene;
    scene.name = "small-office";
    scene.materials = {testing::gray("wall", 0.5), testing::gray("table", 0.45),
                       testing::gray("panel", 0.0, 30000.0)};
    scene.surfaces = testing::closed_room(12, 12, 3, "wall");
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            const double x = 2 + 4 * i, y = 2 + 4 * j;
            const std::string n = std::to_string(3 * j + i);
            scene.surfaces.push_back(testing::polygon_surface(
                "panel-" + n, "panel",
                testing::ceiling_rect(x - 0.3, x + 0.3, y - 0.3, y + 0.3, 2.99)));
            scene.surfaces.push_back(testing::box_surface(
                "table-" + n, "table", {x - 0.9, y - 0.5, 0.7}, {x + 0.7, y + 0.3, 0.73}, false));
        }
    }
    return scene;
}

Result solve_at(const Scene& scene, double tolerance, std::size_t max_memory_bytes = 0) {
    SolveOptions options;
    options.method = "hierarchical";
    options.tolerance = tolerance;
    options.max_memory_bytes = max_memory_bytes;
    return solve(scene, options);
}

TEST(HierarchicalCost, CoarserToleranceIsNotDearer) {
    const Scene scene = small_office();
    const Result coarse = solve_at(scene, 0.3);
    const Result fine = solve_at(scene, 0.03);
    ASSERT_EQ(coarse.status, SolveStatus::converged) << coarse.error;
    ASSERT_EQ(fine.status, SolveStatus::converged) << fine.error;
    EXPECT_LE(coarse.stats.patches, fine.stats.patches);
    EXPECT_LE(coarse.stats.elements, fine.stats.elements);
    EXPECT_LE(coarse.stats.links, fine.stats.links);
}

// Past its memory budget the solver links pairs where they stand: a coarser, honest answer
// marked `stopped`, never a crash or the whole machine's memory.
TEST(HierarchicalCost, MemoryBudgetStopsRefinementNotTheSolve) {
    const Scene scene = small_office();
    const Result free = solve_at(scene, 0.01);
    ASSERT_EQ(free.status, SolveStatus::converged) << free.error;
    const std::size_t budget = 4u << 20;
    const Result tight = solve_at(scene, 0.01, budget);
    ASSERT_EQ(tight.status, SolveStatus::stopped) << tight.error;
    EXPECT_LT(tight.stats.elements, free.stats.elements / 2);
    // An element with its polygon and quadrature points holds several hundred bytes.
    EXPECT_LT(tight.stats.elements * 300, budget);
    ASSERT_EQ(tight.surfaces.size(), free.surfaces.size());
    for (std::size_t i = 0; i < free.surfaces.size(); ++i) {
        const double want = free.surfaces[i].average_irradiance;
        EXPECT_NEAR(tight.surfaces[i].average_irradiance, want, 0.1 * want + 1e-9)
            << free.surfaces[i].name;
    }
}

}  // namespace
}  // namespace radiant
