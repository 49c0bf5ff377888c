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

Pair solve_box_room(const std::string& name, const std::string& method) {
    const Scene scene = testing::load_scene(data_path("box_rooms/" + name + ".json"));
    SolveOptions options = options_from(scene.settings);
    options.method = method;
    options.tolerance = 0.01;
    PipelineLimits once;
    once.max_refinement = 1;
    return {Pipeline(scene, options, nullptr, nullptr, once).run(),
            Pipeline(scene, options, nullptr, nullptr).run()};
}

class Refinement : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(Refinement, MeetsTheToleranceAndNearsTheReference) {
    const auto [name, method] = GetParam();
    const auto [unrefined, refined] = solve_box_room(name, method);
    // Without refinement the mesh check finds the mesh too coarse; the result stays converged,
    // as where no finer mesh can be tried.
    ASSERT_EQ(unrefined.status, SolveStatus::converged) << describe(unrefined);
    ASSERT_GT(unrefined.stats.error_estimate, 0.01) << describe(unrefined);

    ASSERT_EQ(refined.status, SolveStatus::converged) << describe(refined);
    EXPECT_LE(refined.stats.error_estimate, 0.01) << describe(refined);
    EXPECT_GT(refined.stats.elements, unrefined.stats.elements) << describe(refined);

    const nlohmann::json expected =
        testing::read_json(data_path("box_rooms/expected.json"))[std::string(name)];
    const double before = testing::largest_relative_error(unrefined, expected);
    const double after = testing::largest_relative_error(refined, expected);
    EXPECT_LT(after, before) << describe(refined);
    EXPECT_GE(refined.stats.error_estimate, after) << describe(refined);
}

INSTANTIATE_TEST_SUITE_P(BoxRooms, Refinement,
                         ::testing::Values(std::pair{"box-room-panel", "hierarchical"},
                                           std::pair{"box-corridor-panel", "hierarchical"},
                                           std::pair{"box-cube-rho0.2", "direct"}),
                         [](const auto& param_info) {
                             return testing::test_name(std::string(param_info.param.first) + "_" +
                                                       param_info.param.second);
                         });

}  // namespace
}  // namespace radiant
