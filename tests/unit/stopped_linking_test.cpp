// A hierarchical solve stopped while it links (cancelled, or at its time limit) answers with the
// links it made: its leaves' factor sums are then short, and its error estimate must still cover
// the light the missing links would have carried, whenever the stop comes.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

#include "reference_csv.h"
#include "scene_files.h"

namespace radiant {
namespace {

// Cancels the solve as it reports its `round`-th round of linking.
class CancelAtLinkingRound : public SolveObserver {
public:
    CancelAtLinkingRound(CancellationToken& token, int round) : token_(token), round_(round) {}
    void on_progress(const Progress& p) override {
        if (p.stage == "form factors" && ++rounds_ == round_) token_.cancel();
    }

private:
    CancellationToken& token_;
    int round_;
    std::atomic<int> rounds_{0};
};

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
// them: each answer is short of light (without the estimate covering it, a cut-short solve claimed 0.4 % for an error
// of 19 %, or made 4.5 times the light its sources emit), and each estimate bounds its error.
TEST(StoppedLinking, TheEstimateCoversTheLightOfTheLinksNotMade) {
    const RoomS2 room;
    const Result full = solve(room.scene, room.options());
    ASSERT_EQ(full.status, SolveStatus::converged) << full.error;
    ASSERT_EQ(full.sensors.size(), 1u);
    for (const int round : {1, 12, 15, 20, 25, 30}) {
        SCOPED_TRACE("cancelled at round " + std::to_string(round));
        CancellationToken token;
        CancelAtLinkingRound observer(token, round);
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

// Holds the solve at its `round`-th round of linking until its time limit (`seconds` after the
// solve began, which is before the first report) has passed.
class WaitOutTheLimitAtLinkingRound : public SolveObserver {
public:
    WaitOutTheLimitAtLinkingRound(double seconds, int round) : seconds_(seconds), round_(round) {}
    void on_progress(const Progress& p) override {
        const auto now = std::chrono::steady_clock::now();
        if (!first_) first_ = now;
        if (p.stage == "form factors" && ++rounds_ == round_)
            std::this_thread::sleep_until(*first_ + std::chrono::duration<double>(seconds_));
    }

private:
    double seconds_;
    int round_;
    std::optional<std::chrono::steady_clock::time_point> first_;
    int rounds_ = 0;
};

// At a time limit, unlike at a cancel, the links made are still swept (for a tenth of the
// limit): the answer is the links' own, not their first shot's.
TEST(StoppedLinking, AtTheTimeLimitTheLinksMadeAreStillSwept) {
    const RoomS2 room;
    constexpr int kRound = 20;
    CancellationToken token;
    CancelAtLinkingRound cancelling(token, kRound);
    const Result cancelled = solve(room.scene, room.options(), &cancelling, &token);
    ASSERT_EQ(cancelled.status, SolveStatus::stopped) << cancelled.error;

    SolveOptions options = room.options();
    options.max_seconds = 1;
    WaitOutTheLimitAtLinkingRound waiting(1.05, kRound);
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
