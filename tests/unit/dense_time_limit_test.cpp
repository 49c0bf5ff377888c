// A dense solve at its time limit: form factors still being computed get a grace past the limit
// (a tenth of it, at least 0.5 s) to complete and be solved, and a mesh check the limit cut short
// leaves the mesh's error unmeasured, which the estimate must then say.
#include <gtest/gtest.h>

#include "scene_builder.h"
#include "solve_with.h"
#include "stopping_observers.h"

namespace radiant {
namespace {

using testing::describe;

constexpr double kTolerance = 0.1;
constexpr double kLimitSeconds = 1;

Scene panel_room() {
    Scene scene = testing::room_with_ceiling_panel(0.6, 1000);
    scene.sensors.push_back(
        testing::sensor_grid("work plane", {0.25, 0.25, 0.8}, {3.5, 0, 0}, {0, 3.5, 0}, 5, 5));
    return scene;
}

Result solve_held_at(const Scene& scene, const std::string& stage) {
    SolveOptions options;
    options.method = "direct";
    options.tolerance = kTolerance;
    options.max_seconds = kLimitSeconds;
    testing::WaitOutTheLimitAtStageReport waiting(kLimitSeconds + 0.05, stage, 1);
    Result r = solve(scene, options, &waiting);
    EXPECT_TRUE(waiting.reached()) << stage;
    return r;
}

// Held until the limit as its form factors begin, the solve still computes and solves them: the
// answer of the whole solve, not the first bounce.
TEST(DenseTimeLimit, FormFactorsTheLimitInterruptsCompleteInTheGrace) {
    const Scene scene = panel_room();
    const Result full = testing::solve_with(scene, "direct", kTolerance);
    ASSERT_EQ(full.status, SolveStatus::converged) << describe(full);
    const Result held = solve_held_at(scene, "form factors");
    ASSERT_EQ(held.status, SolveStatus::stopped) << describe(held);
    EXPECT_EQ(held.stats.patches, full.stats.patches);
    EXPECT_EQ(held.sensors.at(0).illuminance, full.sensors.at(0).illuminance);
}

// Held until the limit as the mesh check begins: the check is not made, and the estimate claims
// the mesh's error unmeasured (twice the tolerance), not the linear system's bound alone.
TEST(DenseTimeLimit, AMeshCheckTheLimitCutsShortLeavesTheMeshsErrorClaimed) {
    const Scene scene = panel_room();
    const Result held = solve_held_at(scene, "checking");
    ASSERT_EQ(held.status, SolveStatus::stopped) << describe(held);
    EXPECT_EQ(held.stats.error_parts.discretisation, 2 * kTolerance);
    EXPECT_GE(held.stats.error_estimate, 2 * kTolerance);
    EXPECT_GE(held.sensors.at(0).error_estimate, 2 * kTolerance);
}

}  // namespace
}  // namespace radiant
