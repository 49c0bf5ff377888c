// The hierarchical solver's phases: progressive shooting first (a scene without reflection is
// solved once its emitters have shot, with no sweep), then sweeps; and in closed rooms the
// linked operator is made to conserve light without disturbing furnaces.
#include <gtest/gtest.h>

#include <string>

#include "expected_checks.h"
#include "scene_builder.h"
#include "scene_files.h"
#include "solve_with.h"

namespace radiant {
namespace {

using testing::describe;
using testing::solve_hierarchical;

// Two black parallel squares 1 m apart, one emitting: the exact answer after one shot.
TEST(HierarchicalPhases, WithoutReflectionShootingAloneSolvesTheScene) {
    const std::string name = "parallel-squares-d1";
    const Scene scene = testing::load_scene(testing::data_path("scenes/" + name + ".json"));
    const Result r = solve_hierarchical(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_EQ(r.stats.iterations, 1u) << "one shooting pass, no sweep; " << describe(r);
    const auto expected = testing::read_json(testing::data_path("scenes/expected.json"));
    testing::expect_checks(r, expected[name], name);
}

// A black closed room with a ceiling panel: one shooting pass, and every lumen absorbed.
TEST(HierarchicalPhases, BlackClosedRoomBalancesAfterOnePass) {
    const Result r = solve_hierarchical(testing::room_with_ceiling_panel(0.0, 1000.0));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_EQ(r.stats.iterations, 1u) << describe(r);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm, 1.0, 1e-3) << describe(r);
}

// Coloured walls: each channel is corrected on its own, and the room still balances.
TEST(HierarchicalPhases, ColouredClosedRoomBalances) {
    Scene scene = testing::room_with_ceiling_panel(0.5, 1000.0);
    scene.materials[0].reflectance = {0.7, 0.5, 0.2};
    scene.materials[0].rgb_reflectance = true;
    const Result r = solve_hierarchical(scene);
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm, 1.0, 1e-3) << describe(r);
}

// The conservation step must leave a furnace alone: every leaf's defect is light it fails to
// hand on, but a uniform radiosity loses none in total.
TEST(HierarchicalPhases, ConservationKeepsAFurnaceExact) {
    const Result r = solve_hierarchical(testing::furnace_cube(0.9));
    ASSERT_EQ(r.status, SolveStatus::converged) << describe(r);
    for (const auto& s : r.surfaces)
        EXPECT_NEAR(s.average_radiosity * (1 - 0.9), 1.0, 1e-3) << s.name << "; " << describe(r);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm, 1.0, 1e-3) << describe(r);
}

}  // namespace
}  // namespace radiant
