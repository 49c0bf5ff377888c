// A furnished office with real clutter for radiant-bench: an 8 × 6 × 2.8 m open office (walls
// 0.5, carpet 0.2, ceiling 0.8, one-sided and facing in) with six desks on thin metal legs and
// what lies on them, swivel and visitor chairs, five bookshelves holding some 350 books, four
// potted plants of 1–3k triangles, bins, boxes and a filing cabinet (office_furniture.h) —
// about 16 000 triangles — and a work-plane sensor grid at 0.8 m. Everything but the room's
// layout comes from a seed. A floor of N such rooms, each furnished from its own seed and parted
// by walls with door openings, makes the scaling series.
#pragma once

#include <cstdint>

#include "radiant/photometry.h"
#include "radiant/scene.h"

namespace radiant::bench {

/// The room, metres: x ∈ [0, width], y ∈ [0, depth], z ∈ [0, height].
inline constexpr double kRoomWidthM = 8, kRoomDepthM = 6, kRoomHeightM = 2.8;
/// The seed of furnished-office and furnished-office-ies.
inline constexpr std::uint64_t kFurnishedOfficeSeed = 2024;

/// "furnished-office": the room lit by six emitting ceiling panels (1.2 × 0.6 m, 1 cm below the
/// ceiling, facing down, 4000 lm each) and the sensor set "workplane": an EN 12464-1 work plane
/// over the floor (0.8 m high, 0.5 m border, 0.45 m spacing), its points expanded (those
/// inside furniture are left out). Throws std::logic_error if the generated scene fails
/// check_scene (a bug).
Scene furnished_office_clutter(std::uint64_t seed = kFurnishedOfficeSeed);

/// "furnished-office-ies": the same room, the panels replaced by point luminaires at their
/// centres, 2 cm below the ceiling, aimed down, with the distribution `downlight` scaled to
/// 4000 lm each.
Scene furnished_office_ies(const PhotometricTable& downlight,
                           std::uint64_t seed = kFurnishedOfficeSeed);

/// "furnished-floor-x<rooms>": `rooms` (a square: 4, 16, 64, …) rooms in a square grid, each
/// furnished from its own seed (derived from `seed` and its index) and lit by its own panels,
/// parted by 12 cm walls (closed boxes) with a 0.9 × 2.1 m door opening to every neighbour.
/// One sensor set "workplane" holds every room's work-plane points (as furnished_office_clutter
/// would place them in that room), room by room.
Scene furnished_floor(int rooms, std::uint64_t seed = kFurnishedOfficeSeed);

}  // namespace radiant::bench
