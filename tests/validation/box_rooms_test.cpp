// The box rooms of tests/data/box_rooms (converged references computed outside the solver by
// radiant-box-reference, validation README §2.7): the dense solver's error estimate, which
// includes the mesh's error, must bound its true error against them (the RMS of the faces'
// relative errors, as radiant-bench measures it), and so must the hierarchical solver's, which
// must also balance their light as the engine core's bar asks of every closed room, and Monte
// Carlo's, which measures the surfaces' noise.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "expected_checks.h"
#include "scene_files.h"
#include "solve_with.h"

namespace radiant {
namespace {

using testing::data_path;

nlohmann::json expected() { return testing::read_json(data_path("box_rooms/expected.json")); }

class BoxRoom : public ::testing::TestWithParam<std::string> {};

Result solve_room(const std::string& name, const std::string& method) {
    return testing::solve_with(testing::load_scene(data_path("box_rooms/" + name + ".json")),
                               method);
}

TEST_P(BoxRoom, DirectEstimateBoundsTheError) {
    const std::string name = GetParam();
    const Result result = solve_room(name, "direct");
    // A result whose estimate misses the tolerance at the dense patch budget is `stopped`.
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    const double error = testing::rms_relative_error(result, expected()[name]);
    EXPECT_GT(error, 0) << name;
    EXPECT_GE(result.stats.error_estimate, error) << name;
    // Tightly too (issue 27: at most 4× an error above 0.1 %); 1.3–1.7× at 0.01.
    if (error > 1e-3) {
        EXPECT_LE(result.stats.error_estimate, 4 * error) << name;
    }
}

// Closed rooms lit by a panel, by a point source and from one end of a corridor: the linked
// operator loses or makes 0.15–0.2 % of the light unless it is made to conserve it. Its estimate
// bounds its error as the dense solver's does, and as tightly: 1.2–3.7 times at 0.01.
TEST_P(BoxRoom, HierarchicalAbsorbsWhatItEmitsAndBoundsItsError) {
    const std::string name = GetParam();
    const Result result = solve_room(name, "hierarchical");
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    EXPECT_NEAR(result.stats.absorbed_flux_lm / result.stats.emitted_flux_lm, 1.0, 1e-3) << name;
    const double error = testing::rms_relative_error(result, expected()[name]);
    EXPECT_GE(result.stats.error_estimate, error) << name;
    if (error > 1e-3) {
        EXPECT_LE(result.stats.error_estimate, 4 * error) << name;
    }
}

// Without sensors Monte Carlo states its error on the surfaces' means, from its photon batches'
// spread. Its error is one draw of that noise, so the estimate is judged over seeds: the
// errors' RMS within it and not 4 times under it, and at most one run of six above its own
// estimate (its margin is at least a 99 % quantile: seed 1 of the corridor draws its dark end
// wall 3.2 standard deviations low, its estimate 0.87 times its error; in 20 seeds of each room it
// is the only one).
TEST_P(BoxRoom, MonteCarloBoundsItsSurfaceError) {
    const std::string name = GetParam();
    const Scene scene = testing::load_scene(data_path("box_rooms/" + name + ".json"));
    constexpr int kSeeds = 6;
    double squares = 0, estimates = 0;
    int under = 0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        SolveOptions options = options_from(scene.settings);
        options.method = "monte-carlo";
        options.seed = static_cast<std::uint64_t>(seed);
        const Result result = solve(scene, options);
        ASSERT_EQ(result.status, SolveStatus::converged) << testing::describe(result);
        const double error = testing::rms_relative_error(result, expected()[name]);
        squares += error * error / kSeeds;
        estimates += result.stats.error_estimate / kSeeds;
        under += result.stats.error_estimate < error ? 1 : 0;
    }
    const double error = std::sqrt(squares);
    EXPECT_LE(under, 1) << name;
    EXPECT_GE(estimates, error) << name;
    EXPECT_LE(estimates, 4 * error) << name;
}

INSTANTIATE_TEST_SUITE_P(Reference, BoxRoom, ::testing::ValuesIn(testing::scene_names(expected())),
                         [](const auto& param_info) {
                             return testing::test_name(param_info.param);
                         });

}  // namespace
}  // namespace radiant
