// Progressive snapshots: published while solving, versioned, and the last one is the result.
#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "radiant/solve.h"
#include "scene_builder.h"

namespace radiant {
namespace {

class SnapshotRecorder : public SolveObserver {
public:
    void on_progress(const Progress&) override {}
    void on_snapshot(const Snapshot& snapshot) override {
        const std::lock_guard lock(mutex_);
        snapshots.push_back(snapshot);
    }
    std::vector<Snapshot> snapshots;

private:
    std::mutex mutex_;
};

TEST(Snapshots, VersionedWhileSolvingAndFinalEqualsResult) {
    Scene scene = testing::room_with_ceiling_panel(0.9, 1000.0);
    for (const std::string method : {"hierarchical", "shooting", "jacobi", "direct"}) {
        SolveOptions options = options_from(scene.settings);
        options.method = method;
        options.tolerance = 0.001;
        options.snapshot_interval_seconds = 0;  // every chance the solver gives
        options.want_mesh = true;
        SnapshotRecorder recorder;
        const Result r = solve(scene, options, &recorder);
        ASSERT_EQ(r.status, SolveStatus::converged) << method << " " << r.error;
        ASSERT_FALSE(recorder.snapshots.empty()) << method;
        if (method == "shooting" || method == "jacobi") {
            EXPECT_GE(recorder.snapshots.size(), 2u) << method;
        }
        for (std::size_t k = 0; k < recorder.snapshots.size(); ++k) {
            const Snapshot& s = recorder.snapshots[k];
            EXPECT_EQ(s.version, k + 1) << method;
            EXPECT_EQ(s.final, k + 1 == recorder.snapshots.size()) << method;
            ASSERT_TRUE(s.mesh) << method;
            EXPECT_EQ(s.mesh->triangles.size(), r.mesh->triangles.size()) << method;
            EXPECT_EQ(s.mesh_version, recorder.snapshots.front().mesh_version) << method;
        }
        const Snapshot& last = recorder.snapshots.back();
        EXPECT_EQ(last.mesh->triangle_radiosity, r.mesh->triangle_radiosity) << method;
        EXPECT_EQ(last.progress.error_estimate, r.stats.error_estimate) << method;
    }
}

TEST(Snapshots, NoneWithoutObserverInterest) {
    // An observer that only wants progress still works (on_snapshot has a default).
    class ProgressOnly : public SolveObserver {
    public:
        void on_progress(const Progress&) override { ++calls; }
        int calls = 0;
    } observer;
    const Scene scene = testing::room_with_ceiling_panel(0.5, 1000.0);
    const Result r = solve(scene, options_from(scene.settings), &observer);
    EXPECT_EQ(r.status, SolveStatus::converged) << r.error;
    EXPECT_GT(observer.calls, 0);
}

}  // namespace
}  // namespace radiant
