// Refinement to the tolerance (Pipeline::refine_to_tolerance): a result whose mesh check says the
// mesh is too coarse for the tolerance is solved again finer, so that `converged` carries an
// estimate at or under the tolerance, and the finer answer is nearer the converged reference.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "expected_checks.h"
#include "scene_files.h"
#include "solve_with.h"
#include "solver/pipeline.h"

namespace radiant {
namespace {

using testing::data_path;
using testing::describe;

struct Pair {
    Result unrefined;  // solved at the tolerance only
    Result refined;    // as solve() does
};

struct Case {
    const char* name;
    const char* method;
    double tolerance;
};

Pair solve_box_room(const Case& c) {
    const Scene scene =
        testing::load_scene(data_path(std::string("box_rooms/") + c.name + ".json"));
    SolveOptions options = options_from(scene.settings);
    options.method = c.method;
    options.tolerance = c.tolerance;
    PipelineLimits once;
    once.max_refinement = 1;
    return {Pipeline(scene, options, nullptr, nullptr, once).run(),
            Pipeline(scene, options, nullptr, nullptr).run()};
}

class Refinement : public ::testing::TestWithParam<Case> {};

TEST_P(Refinement, MeetsTheToleranceAndNearsTheReference) {
    const Case c = GetParam();
    const auto [unrefined, refined] = solve_box_room(c);
    // Without refinement the mesh check finds the mesh too coarse; the result is `stopped`, as
    // where no finer mesh can be tried.
    ASSERT_EQ(unrefined.status, SolveStatus::stopped) << describe(unrefined);
    ASSERT_GT(unrefined.stats.error_estimate, c.tolerance) << describe(unrefined);

    ASSERT_EQ(refined.status, SolveStatus::converged) << describe(refined);
    EXPECT_LE(refined.stats.error_estimate, c.tolerance) << describe(refined);
    EXPECT_GT(refined.stats.elements, unrefined.stats.elements) << describe(refined);

    const nlohmann::json expected =
        testing::read_json(data_path("box_rooms/expected.json"))[std::string(c.name)];
    const double before = testing::rms_relative_error(unrefined, expected);
    const double after = testing::rms_relative_error(refined, expected);
    EXPECT_LT(after, before) << describe(refined);
    EXPECT_GE(refined.stats.error_estimate, after) << describe(refined);
}

// The hierarchical solver's first solve of the panel room at 0.01 no longer needs refining since
// links share their sources by the factor (see Link), nor the cubes' at 0.005 since leaves are
// completed through their inherited links first (see leaf_completion.h), nor the corridor's at
// 0.01 since its estimate measures the RMS difference its error is stated in, not the largest
// (RMS error 0.35 %, estimate 0.43 %; it used to refine to an error of 0.065 %). The dense
// path's estimate (issue 27) no longer asks for it where its mesh follows the tolerance (the
// ρ 0.2 cube at 0.01: 600 patches, estimate 0.0017 for an RMS error of 0.0012); it does where
// the tolerance gives a mesh too coarse to check — the scene's coarsest, as at 0.3 for the ρ 0.2
// cube and at 0.4 for the mixed cube's 24 patches (RMS error 2.0 %), which claim twice the
// tolerance.
INSTANTIATE_TEST_SUITE_P(BoxRooms, Refinement,
                         ::testing::Values(Case{"box-cube-rho0.2", "direct", 0.3},
                                           Case{"box-cube-mixed", "direct", 0.4}),
                         [](const auto& param_info) {
                             return testing::test_name(std::string(param_info.param.name) + "_" +
                                                       param_info.param.method);
                         });

}  // namespace
}  // namespace radiant
