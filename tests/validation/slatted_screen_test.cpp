// Sensors behind a slatted screen: a glowing pane seen through 25 black strips, the sensors'
// illuminance against an integral over the pane with the strips' shadows found exactly. Many
// views of pane elements are partly blocked, so sampled visibility is most of the error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "radiant/solve.h"
#include "scene_builder.h"
#include "solve_with.h"

namespace radiant {
namespace {

constexpr double kExitance = 8000;
constexpr double kPaneWidth = 2.0;   // along x
constexpr double kPaneHeight = 1.8;  // along z from kSill, pane in the plane y = 0 facing +y
constexpr double kSill = 0.9;
constexpr double kScreenY = 0.1;
constexpr int kStrips = 25;
constexpr double kFirstStrip = 0.03;
constexpr double kPitch = 0.072;
constexpr double kStripHeight = 0.036;

Scene slatted_screen(const std::vector<Vec3>& sensors) {
    Scene scene;
    scene.name = "slatted-screen";
    scene.materials = {testing::gray("pane", 0, kExitance), testing::gray("black", 0)};
    scene.surfaces.push_back(testing::polygon_surface(
        "pane", "pane", testing::rect({0, 0, kSill}, {0, 0, kPaneHeight}, {kPaneWidth, 0, 0})));
    for (int k = 0; k < kStrips; ++k) {
        const double z = kSill + kFirstStrip + k * kPitch;
        scene.surfaces.push_back(testing::polygon_surface(
            "strip" + std::to_string(k), "black",
            testing::rect({0, kScreenY, z}, {0, 0, kStripHeight}, {kPaneWidth, 0, 0})));
    }
    scene.sensors.push_back(testing::sensor_points("work-plane", sensors, {0, 0, 1}));
    return scene;
}

// A ray from the pane point (x, 0, z) to the sensor p crosses the screen at x(1 − t) + p.x·t,
// z(1 − t) + p.z·t, t = screen distance / p.y: so, column by column, each strip shades one
// interval of the pane's z, and Lambert's kernel p.y·(z − p.z) / r⁴ integrates in closed form
// over what is left (a regular grid over the pane aliases with the strips' period instead).
double exact_illuminance(const Vec3& p) {
    const double t = kScreenY / p.y;
    constexpr int nx = 4000;  // midpoint rule across the smooth x direction
    const double dx = kPaneWidth / nx;
    const double top = kSill + kPaneHeight;
    double sum = 0;
    for (int i = 0; i < nx; ++i) {
        const double x = (i + 0.5) * dx;
        const double a2 = (x - p.x) * (x - p.x) + p.y * p.y;
        auto antiderivative = [&](double z) { return -0.5 / (a2 + (z - p.z) * (z - p.z)); };
        double column = antiderivative(top) - antiderivative(kSill);
        const double cx = x * (1 - t) + p.x * t;
        if (cx >= 0 && cx <= kPaneWidth) {
            for (int k = 0; k < kStrips; ++k) {
                const double z0 = kSill + kFirstStrip + k * kPitch;
                const double lo = std::max(kSill, (z0 - p.z * t) / (1 - t));
                const double hi = std::min(top, (z0 + kStripHeight - p.z * t) / (1 - t));
                if (hi > lo) column -= antiderivative(hi) - antiderivative(lo);
            }
        }
        sum += p.y * column * dx;
    }
    return kExitance / std::numbers::pi * sum;
}

class SlattedScreen : public ::testing::TestWithParam<std::string> {};

TEST_P(SlattedScreen, SensorsWithinTheirShareOfTheTolerance) {
    // On a work plane under the sill, from 0.3 m to 2 m into the room, and beside the pane.
    const std::vector<Vec3> sensors{{1.0, 0.3, 0.8}, {0.5, 0.5, 0.8}, {1.5, 0.8, 0.8},
                                    {1.0, 1.2, 0.8}, {0.2, 0.4, 0.8}, {2.5, 1.0, 0.8}};
    const Result r = testing::solve_with(slatted_screen(sensors), GetParam(), 0.01);
    ASSERT_NE(r.status, SolveStatus::failed) << testing::describe(r);
    ASSERT_EQ(r.sensors.size(), 1u);
    for (std::size_t i = 0; i < sensors.size(); ++i) {
        const double exact = exact_illuminance(sensors[i]);
        // Sampled visibility is held to a standard deviation of a quarter of the tolerance; with
        // 16 rays per view and no more, the dense solve's sensors were up to 0.52 % off.
        EXPECT_NEAR(r.sensors[0].illuminance[i] / exact, 1.0, 0.004)
            << "sensor " << i << ": " << r.sensors[0].illuminance[i] << " lx, exact " << exact
            << " lx; " << testing::describe(r);
    }
}

INSTANTIATE_TEST_SUITE_P(Solvers, SlattedScreen, ::testing::Values("hierarchical", "direct"));

}  // namespace
}  // namespace radiant
