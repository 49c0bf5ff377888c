// The cross-check of a radiosity answer in a cluttered room (Pipeline::cross_check). The
// hierarchical solver's links miss much of what the leaves of books, plants and shelves face,
// and completing their factor sums fills it with the room's light (docs/accuracy.md,
// "Bookshelves"): the generated furnished office absorbs 8 % more than it emits. The solver's
// own estimate counts that excess, but among such clutter its estimate had also been under its
// error; a Monte Carlo solve of the same scene now bounds it, and the status follows that bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "radiant/solve.h"
#include "reference_csv.h"
#include "scene_files.h"
#include "solve_with.h"

namespace radiant {
namespace {

namespace fs = std::filesystem;

TEST(CrossCheck, BoundsAHierarchicalSolveOfTheClutteredOfficeAgainstRadiance) {
    const fs::path dir = fs::path(RADIANT_SOURCE_DIR) / "proto/examples/furnished-office-clutter";
    const Scene scene = testing::load_scene(dir / "furnished-office.json");
    const testing::ReferencePoints reference =
        testing::read_reference_csv(dir / "furnished-office.reference.csv");
    SolveOptions options = options_from(scene.settings);
    options.method = "hierarchical";
    options.tolerance = 0.05;
    const Result result = solve(scene, options);
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    ASSERT_GT(result.stats.emitted_flux_lm, 0);
    // The solver's own estimate counts the light its links made.
    const double made = result.stats.absorbed_flux_lm / result.stats.emitted_flux_lm - 1;
    ASSERT_GT(made, options.tolerance) << testing::describe(result);
    EXPECT_GE(result.stats.error_parts.completion, made) << testing::describe(result);
    // The cross-check's bound is the estimate, and it bounds the work plane's error.
    const double cross = result.stats.error_parts.cross_check;
    ASSERT_GT(cross, 0) << testing::describe(result);
    EXPECT_DOUBLE_EQ(result.stats.error_estimate, std::max(cross, 0.04 * options.tolerance));
    ASSERT_FALSE(result.sensors.empty());
    const SensorResult& plane = result.sensors.front();
    ASSERT_EQ(plane.points.size(), reference.points.size());
    const double error = testing::normalised_rms(
        plane.initial ? plane.initial->illuminance : plane.illuminance, reference.illuminance);
    EXPECT_GE(result.stats.error_estimate, error);
    EXPECT_LE(result.stats.error_estimate, 4 * std::max(error, 1e-3)) << "error " << error;
    // Converged exactly when that bound meets the tolerance; a stop says why.
    EXPECT_EQ(result.status == SolveStatus::converged,
              result.stats.error_estimate <= options.tolerance)
        << testing::describe(result);
    if (result.status == SolveStatus::stopped) {
        EXPECT_NE(result.stop_reason.find("Monte Carlo"), std::string::npos) << result.stop_reason;
    }
}

}  // namespace
}  // namespace radiant
