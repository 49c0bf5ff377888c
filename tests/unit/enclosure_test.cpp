// Which root patches look into a closed enclosure, and how much of each one's view ends on a
// surface's front: closed rooms, an opening, the rays counted, and a stop that leaves the rest
// of the patches unsurveyed (taken as open, their shares unmeasured) at once.
#include "formfactor/enclosure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "linkable_scene.h"
#include "scene_builder.h"

namespace radiant {
namespace {

// A 4 × 4 × 3 m room, closed or without its ceiling (nothing in it: a panel hung under the
// ceiling would show the patches above it its back, which makes them open).
Scene room(bool closed) {
    Scene scene;
    scene.name = closed ? "closed" : "open";
    scene.materials = {testing::gray("wall", 0.6)};
    scene.surfaces = closed ? testing::closed_room(4, 4, 3, "wall")
                            : testing::room_without_ceiling(4, 4, 3, "wall");
    return scene;
}

TEST(Enclosure, EveryPatchOfAClosedRoomIsEnclosedAndSeesOnlyFronts) {
    const testing::LinkableScene s(room(true));
    std::uint64_t rays = 0;
    const std::vector<char> enclosed =
        enclosed_patches(s.scene, s.roots, *s.visibility, s.triangle_piece, 1, rays);
    EXPECT_TRUE(std::all_of(enclosed.begin(), enclosed.end(), [](char e) { return e != 0; }));
    EXPECT_GE(rays, 16 * s.roots.size());
    const std::uint64_t enclosure_rays = rays;
    const std::vector<double> share =
        front_shares(s.scene, s.roots, *s.visibility, s.triangle_piece, 1, enclosed, 0.5, rays);
    EXPECT_TRUE(std::all_of(share.begin(), share.end(), [](double f) { return f == 1.0; }));
    EXPECT_EQ(rays, enclosure_rays);  // an enclosed patch's share is 1 without a ray
}

TEST(Enclosure, ARoomWithoutItsCeilingIsOpenAndItsFloorSeesTheSky) {
    const testing::LinkableScene s(room(false));
    std::uint64_t rays = 0;
    const std::vector<char> enclosed =
        enclosed_patches(s.scene, s.roots, *s.visibility, s.triangle_piece, 1, rays);
    const std::uint64_t enclosure_rays = rays;
    const std::vector<double> share =
        front_shares(s.scene, s.roots, *s.visibility, s.triangle_piece, 1, enclosed, 0.5, rays);
    EXPECT_GT(rays, enclosure_rays);
    int floor_patches = 0;
    for (std::size_t i = 0; i < s.roots.size(); ++i) {
        EXPECT_GE(share[i], 0.0);
        EXPECT_LE(share[i], 1.0);
        if (s.roots.patch(i).normal.z < 0.5) continue;
        // Even a corner of the floor sees the sky over 17 % of its view.
        ++floor_patches;
        EXPECT_EQ(enclosed[i], 0) << "floor patch " << i;
        EXPECT_LT(share[i], 0.9) << "floor patch " << i;
    }
    EXPECT_GT(floor_patches, 0);
}

// A time limit or cancel during the surveys: the patches not yet surveyed count as open (their
// factors are not completed to 1) and their shares as 1, without casting their rays.
TEST(Enclosure, AStopLeavesTheRestUnsurveyed) {
    const testing::LinkableScene s(room(true));
    std::uint64_t rays = 0;
    const auto stop = [] { return true; };
    const std::vector<char> enclosed =
        enclosed_patches(s.scene, s.roots, *s.visibility, s.triangle_piece, 1, rays, stop);
    EXPECT_TRUE(std::none_of(enclosed.begin(), enclosed.end(), [](char e) { return e != 0; }));
    const std::vector<double> share = front_shares(s.scene, s.roots, *s.visibility,
                                                   s.triangle_piece, 1, enclosed, 0.5, rays, stop);
    EXPECT_TRUE(std::all_of(share.begin(), share.end(), [](double f) { return f == 1.0; }));
    EXPECT_EQ(rays, 0u);
}

}  // namespace
}  // namespace radiant
