// Every scene of the shared validation set against its expected answer (tests/data/scenes,
// copied from shared/validation so that a clone is self-contained), with default settings —
// and with `method: hierarchical` forced, since every accuracy bar must hold with it too; and
// whether the estimate bounds the error at a coarse tolerance, and stays within 4× of it there.
// The error is the RMS of the checks' relative errors, as radiant-bench measures it (issue 27).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "expected_checks.h"
#include "scene_files.h"

namespace radiant {
namespace {

using testing::data_path;

// Issue 27: where the true error is above kReadableError, the estimate is at most kTightFactor
// times it.
constexpr double kReadableError = 1e-3;
constexpr double kTightFactor = 4;

nlohmann::json expected() { return testing::read_json(data_path("scenes/expected.json")); }

class ValidationScene : public ::testing::TestWithParam<std::string> {};

void expect_matches(const std::string& name, const std::string& method) {
    const Scene scene = testing::load_scene(data_path("scenes/" + name + ".json"));
    SolveOptions options = options_from(scene.settings);
    options.method = method;
    const Result result = solve(scene, options);
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    EXPECT_LE(result.stats.error_estimate, scene.settings.tolerance);
    const nlohmann::json all = expected();
    ASSERT_TRUE(all.contains(name));
    testing::expect_checks(result, all[name], name + " " + method);
    // The estimate includes the mesh's error (and the hierarchy's, its completion's), so it
    // bounds the true one.
    EXPECT_GE(result.stats.error_estimate, testing::rms_relative_error(result, all[name]))
        << name << " " << method;
}

TEST_P(ValidationScene, MatchesExpected) { expect_matches(GetParam(), "auto"); }

// At coarse tolerances too, where the solvers' errors are far below them (parallel squares:
// 4e-6 at 0.1) and the two solutions of the mesh check agree closer still.
TEST_P(ValidationScene, EstimateBoundsTheErrorAtACoarseTolerance) {
    const std::string name = GetParam();
    const Scene scene = testing::load_scene(data_path("scenes/" + name + ".json"));
    for (const double tolerance : {0.3, 0.1}) {
        SolveOptions options = options_from(scene.settings);
        options.tolerance = tolerance;
        const Result result = solve(scene, options);
        ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
        const double error = testing::rms_relative_error(result, expected()[name]);
        EXPECT_GE(result.stats.error_estimate, error) << name << " at " << tolerance;
        // A tight bound where the error is large enough to read (issue 27: at most 4× where it
        // is above 0.1 %). The cube's dense estimate was 17× its error at 0.1 when it counted
        // the largest difference over surfaces three times over; the sphere's hierarchical one
        // 4.5× at 0.3 when its check was at 0.5, too near to measure by.
        if (error > kReadableError) {
            EXPECT_LE(result.stats.error_estimate, kTightFactor * error)
                << name << " at " << tolerance << ": " << result.stats.patches
                << " patches, discretisation part " << result.stats.error_parts.discretisation;
        }
    }
}

TEST_P(ValidationScene, MatchesExpectedHierarchical) { expect_matches(GetParam(), "hierarchical"); }

INSTANTIATE_TEST_SUITE_P(Shared, ValidationScene,
                         ::testing::ValuesIn(testing::scene_names(expected())),
                         [](const auto& param_info) {
                             return testing::test_name(param_info.param);
                         });

}  // namespace
}  // namespace radiant
