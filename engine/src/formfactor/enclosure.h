// Which patches look into a closed enclosure? From such a patch every direction ends on the
// front of some patch, so the visible form factors at each of its points sum to exactly 1 — a
// constraint that sampled visibility alone keeps only to ~1e-3, and that ρ/(1−ρ) amplifies.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "meshing/patch_mesh.h"
#include "visibility/visibility.h"

namespace radiant {

/// enclosed[i] = 1 when every ray cast from patch i lands on a patch front (the back of a
/// one-sided piece makes it 0), and no ray from any patch of its piece escapes the scene (an
/// opening: what one patch sees through it, its neighbours see too). Each patch casts at least
/// `min_rays_per_patch` rays and each piece at least `min_rays_per_piece`, from stratified
/// points in cosine-distributed directions stratified over the hemisphere, so an opening seen
/// over a share F of it goes unnoticed only when F is well under 1/min_rays_per_piece. That
/// matters: an enclosed patch's factors are completed to sum to 1, so an opening taken for a
/// wall would add its F to all the patch receives. `triangle_piece` maps the visibility's
/// triangles to pieces. Deterministic in `seed`. Adds the rays it casts to `cast`. Once
/// `should_stop` (asked now and then) is true, the patches not yet surveyed are taken as open.
std::vector<char> enclosed_patches(const PreparedScene& scene, const PatchMesh& patches,
                                   const Visibility& visibility,
                                   std::span<const int> triangle_piece, std::uint64_t seed,
                                   std::uint64_t& cast,
                                   const std::function<bool()>& should_stop = nullptr,
                                   int min_rays_per_patch = 16, int min_rays_per_piece = 256);

/// Fewest rays front_shares casts from a patch, whatever its budget.
constexpr int kMinFrontShareRays = 256;

/// Per patch, the share of its cosine-weighted hemisphere that ends on a surface front, from
/// `rays_per_patch` stratified rays (as enclosed_patches casts them; fewer, down to
/// kMinFrontShareRays, when all would exceed `max_rays`); 1 where `enclosed`. It is what a
/// patch's factors should sum to: the hierarchical solver completes those that see an opening
/// or a back to it. A share found to be well under `wanted` after a first 64 rays (a patch
/// inside furniture, under a box) is left at that rough estimate. Adds the rays it casts to
/// `cast`. Once `should_stop` (asked now and then) is true, the shares not yet measured stay 1.
std::vector<double> front_shares(const PreparedScene& scene, const PatchMesh& patches,
                                 const Visibility& visibility, std::span<const int> triangle_piece,
                                 std::uint64_t seed, std::span<const char> enclosed, double wanted,
                                 std::uint64_t& cast,
                                 const std::function<bool()>& should_stop = nullptr,
                                 int rays_per_patch = 1024, std::size_t max_rays = 1u << 23);

/// Mean distance (m) from the surfaces to the next surface along cosine-distributed rays:
/// the mean free path of light between bounces, over which radiosity varies. It equals 4V/S in
/// a convex room (Cauchy) and does not depend on the scene's orientation. Rays that escape are
/// not counted; with no hit at all it is the scene's diagonal. Neither are rays across a
/// near-contact gap (a parallel surface facing it nearer than 2 % of either's size, such as an
/// emitter 1 mm above a floor): light there travels almost nothing, yet radiosity over the gap
/// is as smooth as what the gap sees, except in a strip along its edges that refinement
/// resolves; counting them would shrink every patch of the scene to the gap's width.
/// `triangle_piece` maps the visibility's triangles to pieces. Deterministic in `seed`. Adds the
/// rays it casts to `cast`.
double mean_free_path(const PreparedScene& scene, const Visibility& visibility,
                      std::span<const int> triangle_piece, std::uint64_t seed, std::uint64_t& cast,
                      int rays = 4096);

}  // namespace radiant
