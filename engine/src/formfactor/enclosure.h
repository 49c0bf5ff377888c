// Which patches look into a closed enclosure? From such a patch every direction ends on the
// front of some patch, so the visible form factors at each of its points sum to exactly 1 — a
// constraint that sampled visibility alone keeps only to ~1e-3, and that ρ/(1−ρ) amplifies.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "meshing/patch_mesh.h"
#include "visibility/visibility.h"

namespace radiant {

/// enclosed[i] = 1 when `rays_per_patch` cosine-distributed rays from stratified points of
/// patch i all land on a patch front (a one-sided piece's back, or nothing, makes it 0).
/// `triangle_piece` maps the visibility's triangles to pieces. Deterministic in `seed`.
std::vector<char> enclosed_patches(const PreparedScene& scene, const PatchMesh& patches,
                                   const Visibility& visibility,
                                   std::span<const int> triangle_piece, std::uint64_t seed,
                                   int rays_per_patch = 16);

/// Mean distance (m) from the surfaces to the next surface along cosine-distributed rays:
/// the mean free path of light between bounces, over which radiosity varies. It equals 4V/S in
/// a convex room (Cauchy) and does not depend on the scene's orientation. Rays that escape are
/// not counted; with no hit at all it is the scene's diagonal. Neither are rays across a
/// near-contact gap (a parallel surface facing it nearer than 2 % of either's size, such as an
/// emitter 1 mm above a floor): light there travels almost nothing, yet radiosity over the gap
/// is as smooth as what the gap sees, except in a strip along its edges that refinement
/// resolves; counting them would shrink every patch of the scene to the gap's width.
/// `triangle_piece` maps the visibility's triangles to pieces. Deterministic in `seed`.
double mean_free_path(const PreparedScene& scene, const Visibility& visibility,
                      std::span<const int> triangle_piece, std::uint64_t seed, int rays = 4096);

}  // namespace radiant
