// Where the light starts: photons leave luminaires and emitting surfaces in proportion to their
// photometric power, and direct light at a point is estimated from every source (next-event
// estimation), so that the photons need carry only the reflected light.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/random.h"
#include "montecarlo/sensor_receiver.h"
#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// A photon as it leaves its source. `flux` is the source's flux divided by the probability of
/// this photon's source and direction: the mean over many photons is the total emitted flux.
struct Photon {
    Vec3 origin;
    Vec3 direction;  ///< unit
    Rgb flux{0, 0, 0};
};

class LightSources {
public:
    /// The scene's sources, or only those of one light component (`component` ≥ 0): a solve
    /// that keeps components apart runs the light of each through the same mesh.
    LightSources(const PreparedScene& scene, double ray_epsilon, int component = -1);

    bool empty() const { return total_power_ <= 0; }

    /// One photon from three uniform numbers and a few more drawn from `rng`.
    Photon emit(SampleStream& rng) const;

    /// Direct irradiance (lux, per channel) at x with unit normal n: every luminaire exactly,
    /// with one shadow ray each; every emitting piece by its exact unoccluded factor times the
    /// visibility of one point drawn on it, which never exceeds the unoccluded light (no
    /// outliers next to a panel). With many sources (a floor of rooms) a subset is drawn by
    /// what each would send to x unoccluded, roughly, mixed with their power so that none that
    /// could light x is never drawn. Counts rays into `rays`.
    Rgb direct_at(const Vec3& x, const Vec3& n, const Visibility& visibility, SampleStream& rng,
                  std::uint64_t& rays) const;

    /// The luminaires' light at a sensor point as its kind counts it, exactly, with one shadow
    /// ray per luminaire that could light it (lux, per channel).
    Rgb luminaires_at(const Vec3& x, const SensorReceiver& receiver, const Visibility& visibility,
                      std::uint64_t& rays) const;

    /// The emitting pieces' part of direct_at at a sensor, with `samples` visibility points per
    /// piece: irradiance of emitting surfaces only (lux, per channel).
    Rgb emitting_pieces_at(const Vec3& x, const Vec3& n, const Visibility& visibility,
                           SampleStream& rng, int samples, std::uint64_t& rays) const;

private:
    struct EmittingPiece {
        int piece = 0;
        Rgb exitance{0, 0, 0};
        std::vector<double> fan_cdf;  ///< cumulative area of the fan triangles, last = area
        Vec3 centroid;
        double power = 0;  ///< photometric lm
    };
    /// A direction table for a photometric luminaire: cells of 1° in γ and 5° in C.
    struct DirectionTable {
        std::vector<double> cdf;  ///< cumulative intensity × solid angle over the cells
    };

    /// Roughly what source `s` sends to x unoccluded (photometric), for drawing sources.
    double rough_light(std::size_t s, const Vec3& x, const Vec3& n) const;
    Vec3 point_on(const EmittingPiece& e, double r1, double r2, double r3) const;
    Vec3 luminaire_direction(std::size_t luminaire, SampleStream& rng, double& weight) const;
    Rgb luminaire_part(std::size_t luminaire, const Vec3& x, const Vec3& n,
                       const Visibility& visibility, std::uint64_t& rays) const;
    Rgb piece_part(const EmittingPiece& e, const Vec3& x, const Vec3& n,
                   const Visibility& visibility, SampleStream& rng, int samples,
                   std::uint64_t& rays) const;

    bool included(std::size_t luminaire) const {
        return component_ < 0 || scene_.luminaires[luminaire].component == component_;
    }

    const PreparedScene& scene_;
    double epsilon_;
    int component_;
    std::vector<EmittingPiece> pieces_;
    std::vector<DirectionTable> tables_;  ///< per luminaire; empty cdf unless photometric
    /// Sources in one list (luminaires first, then emitting pieces) by photometric power.
    std::vector<double> source_power_;
    std::vector<double> source_cdf_;
    double total_power_ = 0;
};

}  // namespace radiant
