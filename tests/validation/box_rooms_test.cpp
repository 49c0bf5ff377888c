// The box rooms of tests/data/box_rooms (converged references computed outside the solver by
// radiant-box-reference, validation README §2.7): the dense solver's error estimate, which
// includes the mesh's error, must bound its true error against them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "expected_checks.h"
#include "scene_files.h"

namespace radiant {
namespace {

using testing::data_path;

nlohmann::json expected() { return testing::read_json(data_path("box_rooms/expected.json")); }

class BoxRoom : public ::testing::TestWithParam<std::string> {};

TEST_P(BoxRoom, DirectEstimateBoundsTheError) {
    const std::string name = GetParam();
    const Scene scene = testing::load_scene(data_path("box_rooms/" + name + ".json"));
    SolveOptions options = options_from(scene.settings);
    options.method = "direct";
    options.tolerance = 0.01;
    const Result result = solve(scene, options);
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    const double largest = testing::largest_relative_error(result, expected()[name]);
    EXPECT_GT(largest, 0) << name;
    EXPECT_GE(result.stats.error_estimate, largest) << name;
}

INSTANTIATE_TEST_SUITE_P(Reference, BoxRoom, ::testing::ValuesIn(testing::scene_names(expected())),
                         [](const auto& param_info) {
                             return testing::test_name(param_info.param);
                         });

}  // namespace
}  // namespace radiant
