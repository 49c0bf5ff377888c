// A hierarchical solve stopped while it links (cancelled, or at its time limit) answers with the
// links it made: its leaves' factor sums are then short, and its error estimate must still cover
// the light the missing links would have carried, whenever the stop comes.
#include <gtest/gtest.h>

#include <string>

#include "reference_csv.h"
#include "scene_files.h"
#include "solution/result_difference.h"
#include "stopping_observers.h"

namespace radiant {
namespace {

struct RoomS2 {
    Scene scene = testing::load_scene(testing::data_path("radiance/room-s2.json"));
    testing::ReferencePoints reference =
        testing::read_reference_csv(testing::data_path("radiance/room-s2.reference.csv"));

    SolveOptions options() const {
        SolveOptions o = options_from(scene.settings);
        o.method = "hierarchical";
        o.tolerance = 0.05;
        return o;
    }
    double error_of(const Result& r) const {
        return testing::normalised_rms(r.sensors.front().illuminance, reference.illuminance);
    }
};

// Stopped before a link was made (round 1), with a few (12), most (25) or nearly all (30) of
// them: each answer is short of light (without the estimate covering it, a cut-short solve claimed
// 0.4 % for an error of 19 %, or made 4.5 times the light its sources emit), and each estimate
// bounds its error.
TEST(StoppedLinking, TheEstimateCoversTheLightOfTheLinksNotMade) {
    const RoomS2 room;
    const Result full = solve(room.scene, room.options());
    ASSERT_EQ(full.status, SolveStatus::converged) << full.error;
    ASSERT_EQ(full.sensors.size(), 1u);
    for (const int round : {1, 12, 15, 20, 25, 30}) {
        SCOPED_TRACE("cancelled at round " + std::to_string(round));
        CancellationToken token;
        testing::CancelAtStageReport observer(token, "form factors", round);
        const Result r = solve(room.scene, room.options(), &observer, &token);
        ASSERT_EQ(r.status, SolveStatus::stopped) << r.error;
        EXPECT_EQ(r.stop_reason, "cancelled");
        ASSERT_EQ(r.sensors.size(), 1u);
        EXPECT_LT(r.stats.links, full.stats.links);
        EXPECT_LE(r.stats.absorbed_flux_lm, r.stats.emitted_flux_lm * (1 + 1e-9));
        const double error = room.error_of(r);
        EXPECT_GT(error, 0.05) << "the stop came too late to test anything";
        EXPECT_GE(r.stats.error_estimate, error);
        EXPECT_GT(r.stats.error_parts.discretisation, 0);
    }
}

// Without sensors the estimate is the surfaces' measure: a black receiver whose only link was
// never made is dark, and measured against itself that showed nothing (0.04 %).
TEST(StoppedLinking, ADarkReceiverWithoutSensorsIsMeasuredAgainstTheLightItMisses) {
    const Scene scene = testing::load_scene(testing::data_path("scenes/parallel-squares-d1.json"));
    SolveOptions options = options_from(scene.settings);
    options.method = "hierarchical";
    const Result full = solve(scene, options);
    ASSERT_EQ(full.status, SolveStatus::converged) << full.error;
    CancellationToken token;
    testing::CancelAtStageReport observer(token, "form factors", 1);
    const Result r = solve(scene, options, &observer, &token);
    ASSERT_EQ(r.status, SolveStatus::stopped) << r.error;
    EXPECT_EQ(r.stats.links, 0u);
    const double error = relative_rms_difference(full, r);
    EXPECT_GT(error, 0.1);
    EXPECT_GE(r.stats.error_estimate, error);
}

// At a time limit, unlike at a cancel, the links made are still swept (for a tenth of the
// limit): the answer is the links' own, not their first shot's.
TEST(StoppedLinking, AtTheTimeLimitTheLinksMadeAreStillSwept) {
    const RoomS2 room;
    constexpr int kRound = 20;
    CancellationToken token;
    testing::CancelAtStageReport cancelling(token, "form factors", kRound);
    const Result cancelled = solve(room.scene, room.options(), &cancelling, &token);
    ASSERT_EQ(cancelled.status, SolveStatus::stopped) << cancelled.error;

    SolveOptions options = room.options();
    options.max_seconds = 1;
    testing::WaitOutTheLimitAtStageReport waiting(1.05, "form factors", kRound);
    const Result timed = solve(room.scene, options, &waiting);
    ASSERT_EQ(timed.status, SolveStatus::stopped) << timed.error;
    EXPECT_EQ(timed.stop_reason, "the time limit of 1 s");
    EXPECT_EQ(timed.stats.links, cancelled.stats.links);
    EXPECT_GT(timed.stats.iterations, cancelled.stats.iterations);
    EXPECT_LT(timed.stats.error_parts.residual, cancelled.stats.error_parts.residual);
    EXPECT_GE(timed.stats.error_estimate, room.error_of(timed));
}

}  // namespace
}  // namespace radiant
