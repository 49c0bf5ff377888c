// The error estimate in progress reports (issue 29: a stream read 0 → 26 → 0.0007 → 0.012): none
// until the solve has an estimate of its answer, never a linear solve's residual, and the last
// report carries the result's own estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "radiant/solve.h"
#include "scene_builder.h"

namespace radiant {
namespace {

class ProgressRecorder : public SolveObserver {
public:
    void on_progress(const Progress& p) override {
        const std::lock_guard lock(mutex_);
        reports.push_back(p);
    }
    std::vector<Progress> reports;

private:
    std::mutex mutex_;
};

/// A lit room with a work plane: every solver has sensors to estimate from.
Scene lit_room() {
    Scene scene = testing::room_with_ceiling_panel(0.5, 1000.0);
    scene.sensors.push_back(
        testing::sensor_grid("workplane", {0.5, 0.5, 0.8}, {3, 0, 0}, {0, 3, 0}, 6, 6));
    return scene;
}

TEST(ProgressEstimate, AbsentUntilTheSolveHasOneThenItsAnswersEstimate) {
    const Scene scene = lit_room();
    for (const std::string method :
         {"monte-carlo", "hierarchical", "direct", "jacobi", "gauss-seidel", "shooting"}) {
        SolveOptions options = options_from(scene.settings);
        options.method = method;
        options.tolerance = 0.05;
        options.seed = 7;
        ProgressRecorder recorder;
        const Result result = solve(scene, options, &recorder);
        ASSERT_NE(result.status, SolveStatus::failed) << method << " " << result.error;
        ASSERT_FALSE(recorder.reports.empty()) << method;
        // Meshing comes before any answer, so before any estimate of one.
        EXPECT_FALSE(recorder.reports.front().error_estimate) << method;
        for (const Progress& p : recorder.reports) {
            if (p.stage == "solving") {
                // A linear solve's residual is not the answer's error.
                EXPECT_FALSE(p.error_estimate) << method << " " << *p.error_estimate;
            }
            if (!p.error_estimate) continue;
            // A relative error: positive, finite, and no larger than the answer itself.
            EXPECT_TRUE(std::isfinite(*p.error_estimate)) << method << " " << p.stage;
            EXPECT_GT(*p.error_estimate, 0.0) << method << " " << p.stage;
            EXPECT_LE(*p.error_estimate, 1.0) << method << " " << p.stage;
        }
        const Progress& last = recorder.reports.back();
        ASSERT_TRUE(last.error_estimate) << method << " " << last.stage;
        EXPECT_EQ(*last.error_estimate, result.stats.error_estimate) << method;
    }
}

}  // namespace
}  // namespace radiant
