// Sides of the element mesh far brighter than the room around them — the inside of a lamp's
// shade, a wall under a washer — for a sensor's gather to aim rays at. Cosine-distributed rays
// find a small bright patch by chance, a few in a set or none, and the spread of that count held
// a living room's gather near its shaded lamps at hundreds of thousands of rays per point. A few
// rays per set aimed at those sides, weighed against the cosine rays by the balance heuristic
// (Veach and Guibas 1995), take that spread out and leave the estimate unbiased.
//
// The two kinds of rays are weighed as samples of the points the sensor sees: a side's aimed
// rays draw its points uniformly by area, so the density of either kind at a seen point needs
// only the side that point lies on, and an aimed ray that something hides from its side has
// drawn a point the sensor does not see (it brings nothing).
#pragma once

#include <vector>

#include "geometry/random.h"
#include "montecarlo/element_mesh.h"
#include "montecarlo/photon_field.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// One side a point's aimed rays go to, with the probability that a ray picks it.
struct AimedSide {
    int side = 0;
    float probability = 0;
    float cdf = 0;  ///< the probabilities summed up to this side's, inclusive
};

/// What a point aims at: its sides in ascending order.
using Aim = std::vector<AimedSide>;

/// An aimed ray: its direction and the side it was drawn on.
struct AimedRay {
    Vec3 direction;
    int side = -1;
};

class BrightSides {
public:
    /// Sides per point, the most light first: at most kMaxAimed where the points' lists fit in
    /// kAimsBytes, never fewer than kMinAimed. Elements cut finer near lamps split a shade's
    /// bright inside into thousands of sides; a living room's points under its pendant, aiming at
    /// 1 024 of them, spread 2.3 times more per ray set than aiming at all.
    static constexpr std::size_t kMinAimed = 1024;
    static constexpr std::size_t kMaxAimed = 4096;
    static constexpr std::size_t kAimsBytes = std::size_t{64} << 20;
    /// The sides per point for `points` points that aim.
    static std::size_t most_aimed(std::size_t points);

    BrightSides() = default;
    /// The sides whose reflected light on `field` (all of it, direct and reflected) is well above
    /// the surfaces' mean, the most light first.
    BrightSides(const PreparedScene& scene, const ElementMesh& mesh, const PhotonField& field);

    bool empty() const { return sides_.empty(); }

    /// The sides worth aiming at from x (unit normal n), at most `most`, each by roughly the
    /// light it sends to x unoccluded; none where together they send little beside the room's
    /// mean.
    Aim aim(const Vec3& x, const Vec3& n, std::size_t most) const;

    /// A ray from `origin` toward a point drawn uniformly on a side of `aimed`, the side picked by
    /// uniform u (stratified by the caller), the point by `rng`.
    AimedRay draw(const Aim& aimed, const Vec3& origin, SampleStream& rng, double u) const;

    /// The solid-angle density with which draw() gives the point at distance t along unit
    /// direction d, on `side`: 0 for a side not aimed at.
    double density(const Aim& aimed, int side, double t, const Vec3& d) const;

private:
    /// What aim() weighs of a bright side, kept together: every point reads every side.
    struct Bright {
        int side = 0;
        Vec3 centre;
        Vec3 normal;       ///< the side's front
        double area = 0;   ///< m²
        double power = 0;  ///< photometric lm: radiosity × area
    };
    const MeshElement& element(int side) const {
        return (*mesh_)[static_cast<std::size_t>(
            mesh_->sides()[static_cast<std::size_t>(side)].element)];
    }
    const ElementMesh* mesh_ = nullptr;
    std::vector<Bright> sides_;
    double mean_reflected_ = 0;
};

}  // namespace radiant
