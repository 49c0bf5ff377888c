// Linking the element hierarchy: the links a receiver gets carry the light it sees, including
// from sources that only a part of it faces.
#include <gtest/gtest.h>

#include <vector>

#include "formfactor/point_polygon.h"
#include "hierarchy/link_refinement.h"
#include "linkable_scene.h"
#include "scene_builder.h"

namespace radiant {
namespace {

// A desk's side (1.4 × 0.75 m, facing −y) and an emitting chair side 0.1 m from the desk's end,
// standing across the desk side's view (facing −x, 0.1–0.55 m in front of it): only the strip of
// the desk side at x < 0.1 m sees it, and none of the desk side's quadrature points lies there.
Scene desk_beside_chair() {
    Scene scene;
    scene.name = "desk-beside-chair";
    scene.materials = {testing::gray("desk", 0.5), testing::gray("chair", 0.0, 1000.0)};
    scene.surfaces.push_back(testing::polygon_surface(
        "desk-side", "desk", testing::rect({0, 0, 0}, {1.4, 0, 0}, {0, 0, 0.75})));
    scene.surfaces.push_back(testing::polygon_surface(
        "chair-side", "chair", testing::rect({0.1, -0.55, 0}, {0, 0, 0.45}, {0, 0.45, 0})));
    return scene;
}

// A·F from the rectangle `receiver` to `source`, unoccluded, by the midpoint rule on an n × n
// grid (in the prepared scene's frame).
double exact_area_factor(const PatchGeometry& receiver, const std::vector<Vec3>& source,
                         const Vec3& source_normal, int n) {
    const Vec3 o = receiver.vertices[0];
    const Vec3 u = receiver.vertices[1] - o, v = receiver.vertices[3] - o;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Vec3 x = o + u * ((i + 0.5) / n) + v * ((j + 0.5) / n);
            sum += front_point_to_polygon_factor(x, receiver.normal, source, source_normal);
        }
    }
    return sum * receiver.area_m2 / (n * n);
}

TEST(LinkRefinement, ReceiverWhosePointsAllLieBehindTheSourceStillGetsItsLight) {
    const testing::LinkableScene linkable(desk_beside_chair(), 2.0, 0.05);
    ASSERT_EQ(linkable.roots.size(), 2u);
    const PatchGeometry& desk = linkable.roots.patch(0);
    const PatchGeometry& chair = linkable.roots.patch(1);
    ASSERT_EQ(desk.vertices.size(), 4u);
    ASSERT_EQ(desk.surface, 0);
    ASSERT_EQ(chair.surface, 1);
    ElementTree& tree = *linkable.tree;
    tree.light_from(0);
    tree.estimate_from(0, 0, 1);

    RefinementCriteria criteria;
    criteria.power_epsilon_lm = 0.01;  // of the chair's 200 lm
    const RefinementOutcome linked = refine_links(tree, *linkable.visibility, criteria);
    double linked_area_factor = 0;
    for (const Link& l : linked.links) {
        const Element& r = tree[static_cast<std::size_t>(l.receiver)];
        if (!r.cluster && r.patch == 0) linked_area_factor += r.area_m2 * l.factor;
    }
    const double exact = exact_area_factor(desk, chair.vertices, chair.normal, 400);
    ASSERT_GT(exact, 0.002);
    EXPECT_NEAR(linked_area_factor, exact, 0.05 * exact);
}

}  // namespace
}  // namespace radiant
