// The solve's memory budget: the ledger itself, and every solver under a shrinking budget — it
// converges with room to spare, stops refining (`stopped`, saying it was the memory budget) when
// a finer step would not fit, and fails at once, saying so, when its first steps do not fit.
#include "solver/memory_budget.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "radiant/solve.h"
#include "scene_builder.h"

namespace radiant {
namespace {

TEST(MemoryBudget, HoldsWhatFitsAndGivesItBack) {
    MemoryBudget budget(1000);
    EXPECT_TRUE(budget.fits(1000));
    EXPECT_FALSE(budget.fits(1001));
    {
        MemoryHold a(budget, 600);
        EXPECT_EQ(budget.held_bytes(), 600u);
        EXPECT_TRUE(budget.fits(400));
        EXPECT_FALSE(budget.fits(401));
        EXPECT_EQ(budget.available_bytes(), 400u);
        MemoryHold b = std::move(a);
        EXPECT_EQ(budget.held_bytes(), 600u);
        b.resize(100);
        EXPECT_EQ(budget.held_bytes(), 100u);
    }
    EXPECT_EQ(budget.held_bytes(), 0u);
    const MemoryBudget unlimited(0);
    EXPECT_TRUE(unlimited.fits(std::size_t{1} << 60));
}

// A stage's memory is the most the budget held while it ran, above what it held before.
TEST(MemoryBudget, PeakSinceARestart) {
    MemoryBudget budget(0);
    MemoryHold before(budget, 100);
    EXPECT_EQ(budget.restart_peak(), 100u);
    {
        MemoryHold a(budget, 300);
        a.resize(50);
        MemoryHold b(budget, 200);
    }
    EXPECT_EQ(budget.held_bytes(), 100u);
    EXPECT_EQ(budget.peak_bytes(), 400u);  // 100 + 300, more than 100 + 50 + 200
    EXPECT_EQ(budget.restart_peak(), 100u);
    EXPECT_EQ(budget.peak_bytes(), 100u);
}

// An 8 × 6 × 3 m office with ceiling panels, desks (boxes) and a grid of sensors on the floor.
Scene office() {
    Scene scene;
    scene.name = "office";
    scene.materials = {testing::gray("wall", 0.6), testing::gray("desk", 0.4),
                       testing::gray("panel", 0.0, 20000.0)};
    scene.surfaces = testing::closed_room(8, 6, 3, "wall");
    for (int i = 0; i < 4; ++i) {
        const double x = 1.5 + 1.7 * i;
        const std::string n = std::to_string(i);
        scene.surfaces.push_back(testing::polygon_surface(
            "panel-" + n, "panel", testing::ceiling_rect(x - 0.3, x + 0.3, 2.7, 3.3, 2.99)));
        scene.surfaces.push_back(testing::box_surface("desk-" + n, "desk", {x - 0.6, 1.0, 0.7},
                                                      {x + 0.6, 2.0, 0.74}, false));
    }
    scene.sensors.push_back(
        testing::sensor_grid("floor", {0.5, 0.5, 0.8}, {7, 0, 0}, {0, 5, 0}, 14, 10));
    return scene;
}

enum class Outcome { converged, stopped_for_memory, failed_for_memory };

Outcome outcome_of(const Result& r) {
    if (r.status == SolveStatus::converged) return Outcome::converged;
    if (r.status == SolveStatus::stopped) {
        EXPECT_EQ(r.stop_reason.rfind("memory budget: ", 0), 0u) << r.stop_reason;
        return Outcome::stopped_for_memory;
    }
    EXPECT_EQ(r.error.rfind("memory budget: ", 0), 0u) << r.error;
    return Outcome::failed_for_memory;
}

class EverySolver : public ::testing::TestWithParam<const char*> {};

TEST_P(EverySolver, ShrinkingBudgetStopsRefiningThenRefusesUpFront) {
    const Scene scene = office();
    SolveOptions options;
    options.method = GetParam();
    options.tolerance = 0.05;
    options.max_memory_bytes = std::size_t{64} << 20;
    Outcome last = outcome_of(solve(scene, options));
    EXPECT_EQ(last, Outcome::converged);
    // Each budget half the last, down to where even the first steps do not fit; every outcome
    // on the way is an answer or a refusal that names the memory budget (outcome_of checks).
    for (int step = 0; step < 24 && last != Outcome::failed_for_memory; ++step) {
        options.max_memory_bytes /= 2;
        const Outcome now = outcome_of(solve(scene, options));
        // A smaller budget never gives a better outcome.
        EXPECT_GE(static_cast<int>(now), static_cast<int>(last))
            << options.max_memory_bytes << " bytes";
        last = now;
    }
    EXPECT_EQ(last, Outcome::failed_for_memory);
}

INSTANTIATE_TEST_SUITE_P(Methods, EverySolver,
                         ::testing::Values("monte-carlo", "hierarchical", "direct", "gauss-seidel",
                                           "shooting"));

// Between the two, refinement stops at the budget: an answer, not a failure. The dense path at
// 0.4, which no coarser solve can check, refines (124 patches in 1 MiB, then 174 that need 2;
// at 0.02 its estimate meets the tolerance on the first mesh); the hierarchical solver's
// elements at 0.05 need about 20 MiB.
TEST(MemoryBudget, RefinementThatWouldNotFitStopsWithTheBestAnswerSoFar) {
    const Scene scene = office();
    for (const char* method : {"direct", "hierarchical"}) {
        SCOPED_TRACE(method);
        const bool dense = method == std::string("direct");
        SolveOptions options;
        options.method = method;
        options.tolerance = dense ? 0.4 : 0.05;
        options.max_memory_bytes = dense ? std::size_t{1} << 20 : std::size_t{16} << 20;
        const Result r = solve(scene, options);
        EXPECT_EQ(outcome_of(r), Outcome::stopped_for_memory) << r.error;
        EXPECT_FALSE(r.sensors.empty());
        for (const SensorResult& s : r.sensors)
            for (const double e : s.illuminance) EXPECT_TRUE(e > 0) << s.name;
    }
}

// Triangles that cross each other cut each other's patches along every crossing: a few hundred
// in a small ball would be cut into millions of slivers (and a mesh instanced on itself pairs
// every triangle with every other). Planning the patches stops once its polygons and pairs
// would exceed the budget, and the solve fails saying so, instead of holding gigabytes first.
TEST(MemoryBudget, PiecesThatWouldCutEachOtherIntoSliversAreRefusedWhileBeingPlanned) {
    Scene scene = office();
    for (Surface& shard : testing::crossing_shards(600, {4, 3, 1.5}, 0.3, "desk"))
        scene.surfaces.push_back(std::move(shard));
    for (const char* method : {"hierarchical", "shooting"}) {
        SCOPED_TRACE(method);
        SolveOptions options;
        options.method = method;
        options.tolerance = 0.1;
        options.max_memory_bytes = std::size_t{48} << 20;
        const Result r = solve(scene, options);
        EXPECT_EQ(r.status, SolveStatus::failed);
        EXPECT_EQ(r.error.rfind("memory budget: ", 0), 0u) << r.error;
        EXPECT_NE(r.error.find("planning"), std::string::npos) << r.error;
    }
}

// A cancel (or the time limit) while they are being cut drops the cuts (patch_plan_test): the
// pieces' subdivision alone, and the solve stops with it instead of cutting on for seconds. Within
// 3 GiB the whole plan would fit, and its 1.65 million root patches would not.
TEST(MemoryBudget, ACancelWhileCrossingPiecesAreCutStopsCuttingThem) {
    Scene scene = office();
    for (Surface& shard : testing::crossing_shards(600, {4, 3, 1.5}, 0.3, "desk"))
        scene.surfaces.push_back(std::move(shard));
    SolveOptions options;
    options.method = "hierarchical";
    options.tolerance = 0.1;
    options.max_memory_bytes = std::size_t{3} << 30;
    CancellationToken cancelled;
    cancelled.cancel();
    const Result r = solve(scene, options, nullptr, &cancelled);
    EXPECT_EQ(r.status, SolveStatus::stopped) << r.error;
    EXPECT_EQ(r.stop_reason, "cancelled");
    EXPECT_LT(r.stats.patches, std::size_t{100000});
}

// A cylindrical sensor point keeps every emitting piece (no one tangent plane cuts the light
// tree): 10,000 such points under a luminous ceiling of 1,600 tiles hold 128 MB of source lists,
// which the budget must count before the gather is made, not find out after.
TEST(MemoryBudget, CylindricalPointsUnderManyEmittersAreCountedBeforeTheGather) {
    Scene scene = office();
    for (Surface& tile : testing::ceiling_tiles("tile", "panel", 40, 40, 2, 1, 0.1, 0.09, 2.98))
        scene.surfaces.push_back(std::move(tile));
    SensorSet faces =
        testing::sensor_grid("faces", {0.5, 0.5, 1.2}, {7, 0, 0}, {0, 5, 0}, 100, 100);
    faces.kind = SensorKind::cylindrical;
    scene.sensors.push_back(faces);
    SolveOptions options;
    options.tolerance = 0.3;
    options.max_memory_bytes = std::size_t{64} << 20;
    const Result r = solve(scene, options);
    EXPECT_EQ(outcome_of(r), Outcome::failed_for_memory) << to_string(r.status);
}

}  // namespace
}  // namespace radiant
