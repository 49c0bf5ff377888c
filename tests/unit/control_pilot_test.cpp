// Cheap rays go to ray sets only where the pilot shows they pay: where the control takes most
// of a set's spread, and more of them the dearer the exact rays.
#include <gtest/gtest.h>

#include "montecarlo/control_pilot.h"

namespace radiant {
namespace {

ControlPilot pilot(double plain, double residual, double control, double rays_per_set) {
    return {.plain = plain,
            .residual = residual,
            .control = control,
            .sets = 8,
            .rays = 8 * rays_per_set};
}

TEST(ControlPilot, AControlThatTakesMostOfTheSpreadGetsCheapRays) {
    // The cove lobby's pilot: F − G holds 3.6 % of F's variance, 582 rays per set.
    EXPECT_EQ(cheap_rays_per_set(pilot(61240, 2195, 60670, 582), 64), 1024);
}

TEST(ControlPilot, AControlThatTakesLittleGetsNone) {
    // A boutique's: the residual is all of the spread.
    EXPECT_EQ(cheap_rays_per_set(pilot(721, 722, 724, 267), 64), 0);
}

TEST(ControlPilot, CheapExactRaysGetFewerCheapOnes) {
    const int dear = cheap_rays_per_set(pilot(1000, 50, 950, 800), 64);
    const int cheap = cheap_rays_per_set(pilot(1000, 50, 950, 300), 64);
    EXPECT_GT(cheap, 0);
    EXPECT_LT(cheap, dear);
}

TEST(ControlPilot, NoSpreadOrNoSetsGetNone) {
    EXPECT_EQ(cheap_rays_per_set(pilot(0, 0, 0, 582), 64), 0);
    EXPECT_EQ(cheap_rays_per_set(ControlPilot{.plain = 1000, .residual = 10, .control = 990}, 64),
              0);
}

}  // namespace
}  // namespace radiant
