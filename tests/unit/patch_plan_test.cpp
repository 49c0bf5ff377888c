// Planning a radiosity mesh: where pieces touch or cross, their patches are cut along the
// contacts; a stop (a time limit, a cancel) while they are being cut leaves the pieces'
// subdivision alone, so that the rest of a stopping solve is not linear in millions of slivers.
#include <gtest/gtest.h>

#include <atomic>

#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"
#include "scene_builder.h"

namespace radiant {
namespace {

TEST(PatchPlan, AStopWhileThePiecesAreCutDropsTheirCutsSoFar) {
    Scene scene = testing::room_with_ceiling_panel(0.5, 1000);
    for (Surface& shard : testing::crossing_shards(150, {2, 2, 1}, 0.3, "wall"))
        scene.surfaces.push_back(std::move(shard));
    const PreparedScene prepared = prepare_scene(scene);
    MeshingOptions options{0.5, 1'000'000, 0.01};
    const PatchPlan whole(prepared, options);
    options.should_stop = [] { return true; };
    const PatchPlan uncut(prepared, options);
    ASSERT_GT(whole.count(), 10 * uncut.count()) << "the shards must cut each other";
    // Stopped after some pieces were cut: the same plan as stopped at once.
    std::atomic<int> polls{0};
    options.should_stop = [&polls] { return ++polls > 50; };
    const PatchPlan midway(prepared, options);
    EXPECT_GT(polls.load(), 50);
    EXPECT_EQ(midway.count(), uncut.count());
    EXPECT_FALSE(midway.exceeded());
}

}  // namespace
}  // namespace radiant
