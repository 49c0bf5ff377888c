// OcclusionCulling must be conservative: whenever a piece lies between two others it has to be
// reported as a possible blocker, or no shadow ray is cast and light passes through it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/prepared_scene.h"
#include "scene_builder.h"
#include "visibility/occlusion_culling.h"

namespace radiant {
namespace {

// A 4 × 4 × 3 m room (facing in) with something between its west and east walls.
Scene room_with(Surface inside) {
    Scene scene;
    scene.name = "culling";
    scene.materials = {testing::gray("wall", 0.5)};
    scene.surfaces = {testing::box_surface("room", "wall", {0, 0, 0}, {4, 4, 3}, true),
                      std::move(inside)};
    return scene;
}

int piece_with_normal(const PreparedScene& p, int surface, const Vec3& normal) {
    for (std::size_t i = 0; i < p.pieces.size(); ++i) {
        if (p.pieces[i].surface == surface && dot(p.pieces[i].normal, normal) > 0.999) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

struct WestEast {
    int west = -1, east = -1;
};

WestEast west_east(const PreparedScene& p) {
    return {piece_with_normal(p, 0, {1, 0, 0}), piece_with_normal(p, 0, {-1, 0, 0})};
}

bool blocked_between(const PreparedScene& p, const OcclusionCulling& c, WestEast we) {
    const Piece& a = p.pieces[static_cast<std::size_t>(we.west)];
    const Piece& b = p.pieces[static_cast<std::size_t>(we.east)];
    return c.maybe_blocked(we.west, a.vertices, a.normal, we.east, b.vertices, b.normal);
}

TEST(OcclusionCulling, ConvexRoomHasNoOccluders) {
    Scene scene = room_with(testing::polygon_surface(
        "floor-rug", "wall", testing::rect({1, 1, 0}, {1, 0, 0}, {0, 1, 0})));
    const PreparedScene p = prepare_scene(scene);
    const OcclusionCulling c(p);
    EXPECT_EQ(c.occluder_count(), 0u);
}

// The hierarchical solver casts no shadow ray at all in a convex scene; one piece that could
// block (a panel hung 1 cm under the ceiling, a table) must be found.
TEST(OcclusionCulling, NothingCanOccludeOnlyInAConvexScene) {
    EXPECT_TRUE(nothing_can_occlude(prepare_scene(room_with(testing::polygon_surface(
        "floor-rug", "wall", testing::rect({1, 1, 0}, {1, 0, 0}, {0, 1, 0}))))));
    EXPECT_FALSE(nothing_can_occlude(prepare_scene(room_with(testing::polygon_surface(
        "panel", "wall", testing::ceiling_rect(1.5, 2.5, 1.5, 2.5, 2.99))))));
    EXPECT_FALSE(nothing_can_occlude(prepare_scene(
        room_with(testing::box_surface("table", "wall", {1, 1, 0.7}, {2, 2, 0.75}, false)))));
    // A sensor behind a wall (outside the room) makes the wall a possible blocker.
    Scene outside = room_with(testing::polygon_surface(
        "floor-rug", "wall", testing::rect({1, 1, 0}, {1, 0, 0}, {0, 1, 0})));
    outside.sensors.push_back(testing::sensor_points("out", {{5, 2, 1}}));
    EXPECT_FALSE(nothing_can_occlude(prepare_scene(outside)));
}

TEST(OcclusionCulling, TiltedPanelBetweenWallsMayBlock) {
    // Not axis aligned: its bounding box has volume.
    const PreparedScene p = prepare_scene(room_with(testing::polygon_surface(
        "panel", "wall", testing::rect({1.5, 0.5, 0.5}, {1.0, 0, 0.5}, {0, 3.0, 0.2}))));
    const OcclusionCulling c(p);
    const WestEast we = west_east(p);
    ASSERT_GE(we.west, 0);
    ASSERT_GE(we.east, 0);
    EXPECT_GE(c.occluder_count(), 1u);
    EXPECT_TRUE(blocked_between(p, c, we));
}

TEST(OcclusionCulling, AxisAlignedPanelBetweenWallsMayBlock) {
    // A vertical 2 × 2 m square at x = 2 (facing west), squarely between the west and east walls.
    const PreparedScene p = prepare_scene(room_with(testing::polygon_surface(
        "panel", "wall", testing::rect({2, 1, 0.5}, {0, 0, 2}, {0, 2, 0}))));
    const OcclusionCulling c(p);
    const WestEast we = west_east(p);
    ASSERT_GE(we.west, 0);
    ASSERT_GE(we.east, 0);
    EXPECT_GE(c.occluder_count(), 1u);
    const Piece& west = p.pieces[static_cast<std::size_t>(we.west)];
    const bool from_point = c.maybe_blocked_from_point(
        Vec3{0.01, 2, 1.5} - p.world_origin, west.normal, we.east,  // engine's local frame
        p.pieces[static_cast<std::size_t>(we.east)].vertices,
        p.pieces[static_cast<std::size_t>(we.east)].normal);
    EXPECT_TRUE(blocked_between(p, c, we));
    EXPECT_TRUE(from_point);
}

TEST(OcclusionCulling, FloatingBoxBetweenWallsMayBlock) {
    const PreparedScene p = prepare_scene(
        room_with(testing::box_surface("block", "wall", {1.5, 1.5, 1}, {2.5, 2.5, 2}, false)));
    const OcclusionCulling c(p);
    const WestEast we = west_east(p);
    ASSERT_GE(we.west, 0);
    ASSERT_GE(we.east, 0);
    EXPECT_EQ(c.occluder_count(), 6u);  // the block's faces; the room's are on the convex hull
    EXPECT_TRUE(blocked_between(p, c, we));
}

// Two-sided slats of a blind: the back of the slat beyond the next one faces the other way from
// its piece, and the next slat, behind that piece's front, still stands between.
TEST(OcclusionCulling, SlatBehindTheNextOneOfATwoSidedBlindMayBeBlocked) {
    Scene scene;
    scene.name = "blind";
    Material slat = testing::gray("slat", 0.8);
    slat.two_sided = true;
    scene.materials = {testing::gray("wall", 0.5), slat};
    scene.surfaces = {testing::box_surface("room", "wall", {0, 0, 0}, {4, 4, 3}, true)};
    const double half = 0.025 * std::sqrt(0.5);  // 5 cm slats at 45°, 72 mm apart
    for (int k = 0; k < 3; ++k) {
        scene.surfaces.push_back(
            testing::polygon_surface("slat" + std::to_string(k), "slat",
                                     testing::rect({1, 2 - half, 1 + 0.072 * k - half}, {2, 0, 0},
                                                   {0, 2 * half, 2 * half})));
    }
    const PreparedScene p = prepare_scene(scene);
    const OcclusionCulling c(p);
    const int first = piece_with_normal(p, 1, {0, -std::sqrt(0.5), std::sqrt(0.5)});
    const int third = piece_with_normal(p, 3, {0, -std::sqrt(0.5), std::sqrt(0.5)});
    ASSERT_GE(first, 0);
    ASSERT_GE(third, 0);
    const Piece& a = p.pieces[static_cast<std::size_t>(first)];
    const Piece& b = p.pieces[static_cast<std::size_t>(third)];
    const std::vector<Vec3> back(b.vertices.rbegin(), b.vertices.rend());
    EXPECT_TRUE(c.maybe_blocked(first, a.vertices, a.normal, third, back, -b.normal));
}

}  // namespace
}  // namespace radiant
