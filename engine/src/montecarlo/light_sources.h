// Where the light starts: photons leave luminaires and emitting surfaces in proportion to their
// photometric power, and direct light at a point is estimated from every source (next-event
// estimation), so that the photons need carry only the reflected light.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/random.h"
#include "montecarlo/far_piece_draw.h"
#include "montecarlo/light_tree.h"
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
    /// outliers next to a panel). With many pieces in few emitting surfaces (bulbs modelled as
    /// spheres), one piece of each surface is drawn; with many surfaces (a floor of rooms) a few
    /// sources are drawn from the light tree. Either draw goes by what each would roughly send
    /// to x unoccluded, mixed with a draw by power so that none that could light x is never
    /// drawn. Counts rays into `rays`.
    Rgb direct_at(const Vec3& x, const Vec3& n, const Visibility& visibility, SampleStream& rng,
                  std::uint64_t& rays) const;

    /// The sources as a sensor point sees them. A planar or vertical receiver takes the light
    /// tree's cut at x about its normal; a kind that averages receiver normals (cylinders) takes
    /// every source on its own, as no one tangent plane leaves any out. The luminaires of the cut
    /// are exact as the kind counts them (one shadow ray each, counted into `rays`), unless
    /// `with_luminaires` is false (an eye's background); its emitting pieces and clusters are
    /// sampled by sensor_set_light().
    struct SensorSources {
        Rgb luminaires{0, 0, 0};  ///< lux, per channel
        std::vector<std::size_t> pieces;
        std::vector<int> clusters;
        bool with_luminaires = true;  ///< false: a cluster's luminaires count nothing either
    };
    SensorSources sensor_sources(const Vec3& x, const SensorReceiver& receiver,
                                 const Visibility& visibility, bool with_luminaires,
                                 std::uint64_t& rays) const;

    /// One sample of the light of `sources`' emitting pieces (in parts, see piece_part) and
    /// clusters (one source each, drawn by power; its bound keeps the sample small) at x with
    /// unit normal n: lux, per channel.
    Rgb sensor_set_light(const SensorSources& sources, const Vec3& x, const Vec3& n,
                         const Visibility& visibility, SampleStream& rng,
                         std::uint64_t& rays) const;

private:
    struct EmittingPiece {
        int piece = 0;
        Rgb exitance{0, 0, 0};
        std::vector<double> fan_cdf;  ///< cumulative area of the fan triangles, last = area
        Vec3 centroid;
        double area = 0;
        double radius = 0;  ///< the farthest vertex from the centroid
        double power = 0;   ///< photometric lm
    };
    /// What rough_light() reads of a piece, packed: a landing weighs every facet of a lamp's
    /// bulb, and the pieces' own records are four times larger.
    struct RoughPiece {
        Vec3 centroid, normal;
        double least_d2 = 0;  ///< area / π: nearer than that, the point kernel is capped
        double power = 0;
    };
    /// A direction table for a photometric luminaire: cells of 1° in γ and 5° in C.
    struct DirectionTable {
        std::vector<double> cdf;  ///< cumulative intensity × solid angle over the cells
    };

    /// Roughly what source `s` sends to x unoccluded (photometric), for drawing sources.
    double rough_light(std::size_t s, const Vec3& x, const Vec3& n) const;
    /// A point of source `s` for probing whether it is seen: a luminaire's centre, a piece's
    /// centroid just in front of it.
    Vec3 source_point(std::size_t s) const;
    Vec3 point_on(const EmittingPiece& e, double r1, double r2, double r3) const;
    Vec3 luminaire_direction(std::size_t luminaire, SampleStream& rng, double& weight) const;
    /// Source s's light at x: a luminaire exactly, an emitting piece by one point.
    Rgb part(std::size_t s, const Vec3& x, const Vec3& n, const Visibility& visibility,
             SampleStream& rng, std::uint64_t& rays) const;
    /// The pieces [first, end) of pieces_ that make one emitting surface, and their power
    /// (photometric lm, each at least 0): a draw among them weighs it at every landing.
    struct SurfaceRun {
        std::size_t first = 0, end = 0;
        double power = 0;
        /// For a run of many pieces (a bulb modelled as a sphere): its draw for far points.
        std::shared_ptr<const FarPieceDraw> far;
    };
    /// One piece of an emitting surface's run of pieces, drawn by its rough light at x, its
    /// light over its probability.
    Rgb surface_part(const SurfaceRun& run, const Vec3& x, const Vec3& n,
                     const Visibility& visibility, SampleStream& rng, std::uint64_t& rays) const;
    /// Luminaire i's light at x as `receiver` counts it, exactly (one shadow ray).
    Rgb luminaire_at(std::size_t i, const Vec3& x, const SensorReceiver& receiver,
                     const Visibility& visibility, std::uint64_t& rays) const;
    /// An emitting piece's light at x: its exact factor times the visibility of one sampled
    /// point, or `in_parts`, the sum over its fan triangles' parts (split by midpoints
    /// until small as seen from x) of each part's exact factor times one sampled visibility.
    Rgb piece_part(const EmittingPiece& e, const Vec3& x, const Vec3& n,
                   const Visibility& visibility, SampleStream& rng, bool in_parts,
                   std::uint64_t& rays) const;

    bool included(std::size_t luminaire) const {
        return component_ < 0 || scene_.luminaires[luminaire].component == component_;
    }

    const PreparedScene& scene_;
    double epsilon_;
    int component_;
    std::vector<EmittingPiece> pieces_;
    std::vector<RoughPiece> rough_;         ///< one per piece
    std::vector<SurfaceRun> surface_runs_;  ///< one per emitting surface
    std::vector<DirectionTable> tables_;    ///< per luminaire; empty cdf unless photometric
    /// Sources in one list (luminaires first, then emitting pieces) by photometric power.
    std::vector<double> source_power_;
    std::vector<double> source_cdf_;
    double total_power_ = 0;
    LightTree tree_;
};

}  // namespace radiant
