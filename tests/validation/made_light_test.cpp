// Light the hierarchical solver's links made: no scene absorbs more than its sources emit, so an
// excess is error of the solve, which the estimate must count. In the generated furnished office
// the leaves of books, plants and shelves face much their links miss, and completing their factor
// sums fills it with the room's light (docs/accuracy.md, "Bookshelves"): 8 % more is absorbed
// than emitted. A result whose links made more light than the tolerance is `stopped`, saying so.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "radiant/solve.h"
#include "scene_files.h"
#include "solve_with.h"

namespace radiant {
namespace {

TEST(MadeLight, CountsInTheEstimateAndStopsTheClutteredOffice) {
    const Scene scene =
        testing::load_scene(std::filesystem::path(RADIANT_SOURCE_DIR) /
                            "proto/examples/furnished-office-clutter/furnished-office.json");
    SolveOptions options = options_from(scene.settings);
    options.method = "hierarchical";
    options.tolerance = 0.05;
    const Result result = solve(scene, options);
    ASSERT_GT(result.stats.emitted_flux_lm, 0);
    const double made = result.stats.absorbed_flux_lm / result.stats.emitted_flux_lm - 1;
    ASSERT_GT(made, options.tolerance) << testing::describe(result);
    EXPECT_GE(result.stats.error_estimate, made) << testing::describe(result);
    EXPECT_EQ(result.status, SolveStatus::stopped) << testing::describe(result);
    EXPECT_NE(result.stop_reason.find("more light than the sources emit"), std::string::npos)
        << result.stop_reason;
}

}  // namespace
}  // namespace radiant
