// Lazy linking: links from the emitting patches are made first, the rest when they are ready; the
// two stages make the links one stage makes, and the emitters' shot between them is their light.
#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

#include "analytic_form_factors.h"
#include "hierarchy/emitter_shot.h"
#include "hierarchy/link_refinement.h"
#include "linkable_scene.h"
#include "scene_builder.h"

namespace radiant {
namespace {

constexpr double kExitance = 1000;

// A closed 4 × 4 × 3 m room, its 1 × 1 m ceiling panel flush (nothing can occlude: no rays).
struct PanelRoom {
    PanelRoom() : linkable(testing::room_with_ceiling_panel(0.5, kExitance), 1.0, 0.1) {
        linkable.tree->light_from(0);
        linkable.tree->estimate_from(0, 0, 1);
        criteria.power_epsilon_lm = 1e-4 * kExitance;
        criteria.unoccluded = true;
        for (std::size_t p = 0; p < linkable.roots.size(); ++p) {
            const PatchGeometry& patch = linkable.roots.patch(p);
            emitting.push_back(
                !patch.hidden && !patch.back_side &&
                linkable.scene.materials[static_cast<std::size_t>(patch.material)].emits());
        }
    }

    int patch_of(int element) const {
        return (*linkable.tree)[static_cast<std::size_t>(element)].patch;
    }

    // Σ A·K per pair of root patches.
    std::map<std::pair<int, int>, double> exchange(const std::vector<Link>& links) const {
        std::map<std::pair<int, int>, double> out;
        for (const Link& l : links) {
            const Element& r = (*linkable.tree)[static_cast<std::size_t>(l.receiver)];
            out[{r.patch, patch_of(l.source)}] += r.area_m2 * l.factor;
        }
        return out;
    }

    testing::LinkableScene linkable;
    RefinementCriteria criteria;
    std::vector<char> emitting;
};

TEST(LazyLinking, EmittersFirstThenTheRestMakeTheLinksOfOneStage) {
    PanelRoom staged;
    staged.criteria.ready_source = staged.emitting;
    RefinementOutcome linked =
        refine_links(*staged.linkable.tree, *staged.linkable.visibility, staged.criteria);
    ASSERT_FALSE(linked.links.empty());
    ASSERT_FALSE(linked.deferred.empty());
    for (const Link& l : linked.links)
        EXPECT_TRUE(staged.emitting[static_cast<std::size_t>(staged.patch_of(l.source))]);
    staged.criteria.ready_source = {};
    resume_links(linked, *staged.linkable.tree, *staged.linkable.visibility, staged.criteria);
    EXPECT_TRUE(linked.deferred.empty());
    EXPECT_FALSE(linked.stopped);
    for (std::size_t k = 1; k < linked.links.size(); ++k) {
        const Link &a = linked.links[k - 1], &b = linked.links[k];
        ASSERT_TRUE(a.receiver < b.receiver || (a.receiver == b.receiver && a.source < b.source));
    }

    PanelRoom at_once;
    const RefinementOutcome direct =
        refine_links(*at_once.linkable.tree, *at_once.linkable.visibility, at_once.criteria);
    EXPECT_EQ(linked.links.size(), direct.links.size());
    const auto want = at_once.exchange(direct.links);
    const auto got = staged.exchange(linked.links);
    ASSERT_EQ(got.size(), want.size());
    for (const auto& [pair, value] : want) {
        const auto it = got.find(pair);
        ASSERT_NE(it, got.end());
        EXPECT_NEAR(it->second, value, 1e-6 * value);
    }
}

TEST(LazyLinking, EmitterShotIsTheEmittersDirectLight) {
    PanelRoom room;
    room.criteria.ready_source = room.emitting;
    const RefinementOutcome linked =
        refine_links(*room.linkable.tree, *room.linkable.visibility, room.criteria);
    const ElementTree& tree = *room.linkable.tree;
    const std::vector<Rgb> shot = emitter_shot(tree, linked.links);
    // The floor's leaves: their area-weighted light against E·F(floor → panel).
    double light = 0, area = 0;
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || !x.leaf()) continue;
        const PatchGeometry& p = room.linkable.roots.patch(static_cast<std::size_t>(x.patch));
        if (p.surface != 0) continue;  // the floor
        light += x.area_m2 * shot[e][0];
        area += x.area_m2;
    }
    ASSERT_NEAR(area, 16, 1e-9);
    const double exact =
        kExitance * analytic::parallel_rectangles(0, 4, 0, 4, 1.5, 2.5, 1.5, 2.5, 3);
    EXPECT_NEAR(light / area, exact, 0.005 * exact);
}

}  // namespace
}  // namespace radiant
