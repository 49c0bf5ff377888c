// Furnaces with occlusion (B = E/(1−ρ) exactly, any closed geometry): the L-shaped room and a
// free-floating block. Sampled visibility keeps row sums only to ~1e-3, which ρ/(1−ρ) would
// amplify to 10 % at ρ = 0.99; these cases check that enclosed rows are completed to 1.
#include <gtest/gtest.h>

#include <string>

#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant {
namespace {

Scene parse(const std::string& text) {
    auto outcome = proto::parse_scene(text);
    EXPECT_TRUE(outcome.ok());
    return outcome.scene.value_or(Scene{});
}

std::string materials(double rho) {
    return R"("materials": {"glow": {"reflectance": )" + std::to_string(rho) +
           R"(, "emission": {"exitance": 1}}})";
}

std::string l_room(double rho) {
    return R"({"format": "radiant-scene/1", "name": "l-room", )" + materials(rho) + R"(,
      "surfaces": [
        {"name": "floor", "material": "glow", "polygon": [[0,0,0],[4,0,0],[4,2,0],[2,2,0],[2,4,0],[0,4,0]]},
        {"name": "ceiling", "material": "glow", "polygon": [[0,0,3],[0,4,3],[2,4,3],[2,2,3],[4,2,3],[4,0,3]]},
        {"name": "w1", "material": "glow", "polygon": [[0,0,0],[0,0,3],[4,0,3],[4,0,0]]},
        {"name": "w2", "material": "glow", "polygon": [[4,0,0],[4,0,3],[4,2,3],[4,2,0]]},
        {"name": "w3", "material": "glow", "polygon": [[4,2,0],[4,2,3],[2,2,3],[2,2,0]]},
        {"name": "w4", "material": "glow", "polygon": [[2,2,0],[2,2,3],[2,4,3],[2,4,0]]},
        {"name": "w5", "material": "glow", "polygon": [[2,4,0],[2,4,3],[0,4,3],[0,4,0]]},
        {"name": "w6", "material": "glow", "polygon": [[0,4,0],[0,4,3],[0,0,3],[0,0,0]]}]})";
}

std::string floating_block(double rho) {
    return R"({"format": "radiant-scene/1", "name": "block", )" + materials(rho) + R"(,
      "surfaces": [
        {"name": "room", "material": "glow", "box": {"min": [0,0,0], "max": [4,4,3], "facing": "in"}},
        {"name": "block", "material": "glow", "box": {"min": [1,1,0.5], "max": [2,2.5,1.5], "facing": "out"}}]})";
}

struct Case {
    const char* name;
    std::string (*scene)(double);
    double rho;
    double tolerance;
};

class OccludedFurnace : public ::testing::TestWithParam<Case> {};

TEST_P(OccludedFurnace, EverySurfaceAtEOverOneMinusRho) {
    const Case c = GetParam();
    const Scene scene = parse(c.scene(c.rho));
    const Result r = solve(scene, options_from(scene.settings));
    ASSERT_EQ(r.status, SolveStatus::converged) << r.error;
    const double exact = 1.0 / (1.0 - c.rho);
    for (const auto& s : r.surfaces) {
        EXPECT_NEAR(s.average_radiosity / exact, 1.0, c.tolerance) << s.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, OccludedFurnace,
                         ::testing::Values(Case{"l_room_0_99", l_room, 0.99, 0.01},
                                           Case{"l_room_0_999", l_room, 0.999, 0.02},
                                           Case{"block_0_99", floating_block, 0.99, 0.01},
                                           Case{"block_0_999", floating_block, 0.999, 0.02}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace radiant
