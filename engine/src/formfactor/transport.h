// Light transport between patches, luminaires and sensors: analytic point-to-polygon factors
// (exact when unoccluded) times visibility sampled with shadow rays (Wallace, Elmquist & Haines
// 1989 style), with rays skipped where shaft culling proves the view clear.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "formfactor/quadrature.h"
#include "formfactor/sampled_views.h"
#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"
#include "visibility/occlusion_culling.h"
#include "visibility/visibility.h"

namespace radiant {

struct TransportOptions {
    /// Shadow rays per patch-to-patch link, spread over the receiver's quadrature points (at
    /// least one each): stratified over both patches, so a blocker covering a fraction f of
    /// the shaft is missed with probability about (1−f)^N.
    int rays_per_link = 16;
    int rays_per_point = 4;           ///< from a sensor point to a patch
    int emitter_rays_per_point = 16;  ///< to emitting patches, where visibility shows most
    int max_rays_per_point = 256;     ///< when a sensor's views are sampled again
    std::uint64_t seed = 1;
};

/// Everything a transport query needs; immutable after construction, shared by threads.
class Transport {
public:
    /// `enclosed` (see enclosed_patches) marks the receivers whose sampled form factors are
    /// rescaled, point by point, so that they complete the exact unoccluded ones to 1.
    Transport(const PreparedScene& scene, const PatchMesh& patches, const Visibility& visibility,
              const OcclusionCulling& culling, TransportOptions options,
              std::vector<char> enclosed);

    /// A point x's (unit normal n) view of patch j: the unoccluded fraction of its cosine-weighted
    /// hemisphere that patch j covers, and the share of it sampled visible. `key` seeds the ray
    /// samples; counts rays.
    PointView point_view(const Vec3& x, const Vec3& n, std::size_t j, std::uint64_t key,
                         std::uint64_t& rays) const;

    /// Samples x's views again to a standard deviation of `sigma` lux and moves its
    /// `irradiance` by what changed (see SampledViews); `key` as for its views.
    void resample(const SampledViews& views, const Vec3& x, const Vec3& n, double sigma,
                  std::uint64_t key, Rgb& irradiance, std::uint64_t& rays) const;

    /// Row i of the form-factor matrix (receiver i, all sources) into `row` (size = patches).
    /// `parallel` spreads the sources over the calling arena's threads (for a single row, as
    /// matrix-free shooting needs); the row is the same either way, whatever the thread count.
    void form_factor_row(std::size_t i, float* row, std::uint64_t& rays,
                         bool parallel = false) const;

    /// Irradiance (lux, per channel) from every luminaire: on patch i (area average, exact
    /// flux when unoccluded) or at a point.
    Rgb luminaire_irradiance_on_patch(std::size_t i, std::uint64_t& rays) const;
    Rgb luminaire_irradiance_at(const Vec3& x, const Vec3& n, std::uint64_t key,
                                std::uint64_t& rays) const;

    const std::vector<QuadraturePoint>& rule(std::size_t i) const { return rules_[i]; }
    const PatchMesh& patches() const { return patches_; }

private:
    bool faces_each_other(std::size_t i, std::size_t j) const;
    bool patch_emits(std::size_t j) const;
    /// Fraction of stratified shadow rays from x (lifted along n) that reach patch j.
    double visible_fraction(const Vec3& x, const Vec3& n, std::size_t j, int ray_count,
                            std::uint64_t key, std::uint64_t& rays) const;

    const PreparedScene& scene_;
    const PatchMesh& patches_;
    const Visibility& visibility_;
    const OcclusionCulling& culling_;
    TransportOptions options_;
    std::vector<std::vector<QuadraturePoint>> rules_;
    std::vector<char> enclosed_;
};

}  // namespace radiant
