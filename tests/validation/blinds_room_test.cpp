// A room lit only through blinds: a glowing pane at the back of a 0.2 m window reveal, 24
// two-sided slats at 45° across the reveal, their ends on its sides. Each slat sees the pane
// 0.1 m away past the next slat, where the kernel is largest: visibility sampled by area made the
// slats' factors to the pane 16 % low, the pane handed on 8.5 % less light than it emitted, and
// the solve ended `stopped` at every tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "radiant/solve.h"
#include "scene_builder.h"
#include "solve_with.h"

namespace radiant {
namespace {

using testing::polygon_surface;
using testing::rect;

constexpr double kWidth = 5, kDepth = 4, kHeight = 3;
constexpr double kLeft = 1, kRight = 4, kSill = 0.9, kHead = 2.4, kReveal = 0.2;
constexpr int kSlats = 24;
constexpr double kSlatHalfRise = 0.0247;  // each slat rises 2 × this over as much depth

Scene blinds_room() {
    Scene scene;
    scene.name = "blinds-room";
    Material slat = testing::gray("slat", 0.7);
    slat.two_sided = true;
    scene.materials = {testing::gray("wall", 0.5), testing::gray("ceiling", 0.8), slat,
                       testing::gray("pane", 0, 10000)};
    const double w = kRight - kLeft, h = kHead - kSill;
    scene.surfaces = {
        polygon_surface("floor", "wall", rect({0, 0, 0}, {kWidth, 0, 0}, {0, kDepth, 0})),
        polygon_surface("ceiling", "ceiling",
                        rect({0, 0, kHeight}, {0, kDepth, 0}, {kWidth, 0, 0})),
        polygon_surface("north", "wall", rect({0, kDepth, 0}, {kWidth, 0, 0}, {0, 0, kHeight})),
        polygon_surface("west", "wall", rect({0, 0, 0}, {0, kDepth, 0}, {0, 0, kHeight})),
        polygon_surface("east", "wall", rect({kWidth, 0, 0}, {0, 0, kHeight}, {0, kDepth, 0})),
        // The south wall around the window.
        polygon_surface("south-left", "wall", rect({0, 0, 0}, {0, 0, kHeight}, {kLeft, 0, 0})),
        polygon_surface("south-right", "wall",
                        rect({kRight, 0, 0}, {0, 0, kHeight}, {kWidth - kRight, 0, 0})),
        polygon_surface("south-below", "wall", rect({kLeft, 0, 0}, {0, 0, kSill}, {w, 0, 0})),
        polygon_surface("south-above", "wall",
                        rect({kLeft, 0, kHead}, {0, 0, kHeight - kHead}, {w, 0, 0})),
        polygon_surface("reveal-left", "wall",
                        rect({kLeft, -kReveal, kSill}, {0, kReveal, 0}, {0, 0, h})),
        polygon_surface("reveal-right", "wall",
                        rect({kRight, -kReveal, kSill}, {0, 0, h}, {0, kReveal, 0})),
        polygon_surface("reveal-sill", "wall",
                        rect({kLeft, -kReveal, kSill}, {w, 0, 0}, {0, kReveal, 0})),
        polygon_surface("reveal-head", "wall",
                        rect({kLeft, -kReveal, kHead}, {0, kReveal, 0}, {w, 0, 0})),
        polygon_surface("pane", "pane", rect({kLeft, -kReveal, kSill}, {0, 0, h}, {w, 0, 0})),
    };
    for (int k = 0; k < kSlats; ++k) {
        const double z = kSill + (k + 0.5) * h / kSlats;
        const double d = kSlatHalfRise;
        scene.surfaces.push_back(polygon_surface(
            "slat" + std::to_string(k), "slat",
            rect({kLeft, -0.5 * kReveal - d, z - d}, {w, 0, 0}, {0, 2 * d, 2 * d})));
    }
    scene.sensors.push_back(testing::sensor_grid("work-plane", {0.25, 0.25, 0.8}, {4.5, 0, 0},
                                                 {0, 3.5, 0}, 10, 8, {0, 0, 1}));
    return scene;
}

TEST(BlindsRoom, HierarchicalConvergesAndKeepsTheLight) {
    const Result r = testing::solve_hierarchical(blinds_room(), 0.05);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    EXPECT_LE(r.stats.error_estimate, 0.05);
    ASSERT_GT(r.stats.emitted_flux_lm, 0);
    EXPECT_NEAR(r.stats.absorbed_flux_lm / r.stats.emitted_flux_lm, 1, 0.005);
    ASSERT_EQ(r.sensors.size(), 1u);
    for (const double lux : r.sensors[0].illuminance) EXPECT_GT(lux, 0);
}

}  // namespace
}  // namespace radiant
