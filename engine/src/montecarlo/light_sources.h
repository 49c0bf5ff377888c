// Where the light starts: photons leave luminaires and emitting surfaces in proportion to their
// photometric power, and direct light at a point is estimated from every source (next-event
// estimation), so that the photons need carry only the reflected light.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/random.h"
#include "montecarlo/light_tree.h"
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
    LightSources(const PreparedScene& scene, double ray_epsilon);

    bool empty() const { return total_power_ <= 0; }

    /// One photon from three uniform numbers and a few more drawn from `rng`.
    Photon emit(SampleStream& rng) const;

    /// Direct irradiance (lux, per channel) at x with unit normal n: every luminaire exactly,
    /// with one shadow ray each; every emitting piece by its exact unoccluded factor times the
    /// visibility of one point drawn on it, which never exceeds the unoccluded light (no
    /// outliers next to a panel). With many sources (a floor of rooms) a few are drawn from the
    /// light tree by what each would roughly send to x unoccluded, mixed with a draw by power
    /// so that none that could light x is never drawn. Counts rays into `rays`.
    Rgb direct_at(const Vec3& x, const Vec3& n, const Visibility& visibility, SampleStream& rng,
                  std::uint64_t& rays) const;

    /// The sources as a sensor at x (unit normal n) sees them: the light tree's cut there. The
    /// luminaires of the cut are exact (one shadow ray each, counted into `rays`); its emitting
    /// pieces and clusters are sampled by sensor_set_light().
    struct SensorSources {
        Rgb luminaires{0, 0, 0};  ///< lux, per channel
        std::vector<std::size_t> pieces;
        std::vector<int> clusters;
    };
    SensorSources sensor_sources(const Vec3& x, const Vec3& n, const Visibility& visibility,
                                 std::uint64_t& rays) const;

    /// One sample of the light of `sources`' emitting pieces (exact factors, `samples`
    /// visibility points each) and clusters (one source each, drawn by power; its bound keeps
    /// the sample small) at x: lux, per channel.
    Rgb sensor_set_light(const SensorSources& sources, const Vec3& x, const Vec3& n,
                         const Visibility& visibility, SampleStream& rng, int samples,
                         std::uint64_t& rays) const;

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
    /// Source s's light at x: a luminaire exactly, an emitting piece with `samples` points.
    Rgb part(std::size_t s, const Vec3& x, const Vec3& n, const Visibility& visibility,
             SampleStream& rng, int samples, std::uint64_t& rays) const;
    Rgb piece_part(const EmittingPiece& e, const Vec3& x, const Vec3& n,
                   const Visibility& visibility, SampleStream& rng, int samples,
                   std::uint64_t& rays) const;

    const PreparedScene& scene_;
    double epsilon_;
    std::vector<EmittingPiece> pieces_;
    std::vector<DirectionTable> tables_;  ///< per luminaire; empty cdf unless photometric
    /// Sources in one list (luminaires first, then emitting pieces) by photometric power.
    std::vector<double> source_power_;
    std::vector<double> source_cdf_;
    double total_power_ = 0;
    LightTree tree_;
};

}  // namespace radiant
