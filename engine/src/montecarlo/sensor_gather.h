// Sensor illuminance by final gather over the photon field: the luminaires' light exactly (one
// shadow ray each), the emitting surfaces' by the exact factors of their parts times sampled
// visibility (on a floor of many rooms, those of the other rooms drawn as a few clusters of the
// light tree), and the reflected light from sets of cosine-distributed rays. Where a ray lands, the
// light that point reflects is its direct light found there (next-event estimation) plus the photon
// field's indirect irradiance on the element; a ray that lands nearer than its element's size (a
// point beside a stack of books) bounces once more, as the element's average is not the light of
// that spot. The rays and the direct light are kept, so a denser photon field re-prices them
// without casting them again. Where sides far brighter than the room face a point (the inside
// of a lamp's shade), a few rays per set aim at them, weighed against the cosine rays by the
// balance heuristic (see BrightSides). Where the first sets show that which element a ray lands
// on spreads them most (a room lit from its surfaces), each later set adds many cheap rays that
// read their elements' cached direct light and field (SideDirectCache, ControlPilot): the exact
// rays then measure only how far the spots they land on differ from that.
//
// Each point's error has three parts, all measured from the data:
//   gather noise   the spread of its ray sets;
//   photon noise   the spread of its value over the field's batches;
//   discretisation the change when the field is read at the coarser level of the mesh (the
//                  elements' bisection parents), less what the photon noise explains
//                  (set_errors takes the difference over a sensor set); and, from one far
//                  hit in four whose path goes on (see FarBounce), how far the element averages
//                  are from the light of the spots the rays land on, less its noise.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "montecarlo/bright_sides.h"
#include "montecarlo/control_pilot.h"
#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "montecarlo/photon_field.h"
#include "montecarlo/side_direct_cache.h"

namespace radiant {

/// One point's value and the variances of its error parts (lux and lux²). The coarser level's
/// difference comes with its own noise variance: the bias is what the difference holds beyond
/// its noise, which only a sum over many points tells reliably.
struct GatheredPoint {
    double illuminance = 0;
    int sets = 0;  ///< the ray sets it was gathered from
    double gather_variance = 0;
    double photon_variance = 0;
    /// What each batch of the photon field alone gives the point's reflected light (lux): all
    /// points read the same field, so a set's error holds a shared part these measure.
    std::array<double, PhotonField::kBatches> photon_batches{};
    double coarse_difference_squared = 0;
    double coarse_difference_variance = 0;
    /// The same for reading each far hit's element average instead of following the path
    /// beyond it: the average misses how the light varies over a partly hidden element (the
    /// back of a bookshelf's compartment, seen only above the books).
    double depth_difference_squared = 0;
    double depth_difference_variance = 0;
};

class SensorGather {
public:
    static constexpr int kRaysPerSet = 64;  ///< 8 × 8 strata of the cosine-weighted hemisphere
    /// Rays per set aimed at bright sides, besides the cosine rays, at points that aim.
    static constexpr int kAimedRaysPerSet = 16;
    static constexpr int kAimsPerCosineRays = kRaysPerSet / kAimedRaysPerSet;

    /// What a gather measures: the sensor points, in the order of the sets; or the UGR
    /// observers' eyes, each facing its line of sight and gathering all light but the
    /// luminaires' (their glare is rated apart; what remains is the background, E_ind = π L_b).
    enum class Points { sensors, eyes };

    /// `cache` holds the direct light of `sources` at `mesh`'s sides; gathers may share it.
    SensorGather(const PreparedScene& scene, const ElementMesh& mesh, const LightSources& sources,
                 const SideDirectCache& cache, const Visibility& visibility, std::uint64_t seed,
                 Points which = Points::sensors);

    /// Casts ray sets until the points of each sensor set (each eye: a set of one) have
    /// `sets[s]` per point on average, allotted by how each point's sets spread in `last` (the
    /// points' previous evaluate(), if any; see allot_sets), or evenly; the exact luminaire light
    /// comes with a point's first set. Returns the rays cast. Parallel over points;
    /// deterministic.
    std::uint64_t gather(const std::vector<int>& sets, const std::function<bool()>& stop,
                         const std::vector<GatheredPoint>& last = {});
    /// The same, `sets` per point in every sensor set, evenly.
    std::uint64_t gather(int sets, const std::function<bool()>& stop);
    /// After the first gather (the pilot), whether the points of each sensor set take cheap
    /// rays in every set, and how many (cheap_rays_per_set, from their sets' spread with and
    /// without the control); those that do get them for the sets they have, so that every set
    /// is of one kind, unless that takes more than `max_bytes` (cheap rays only save rays).
    /// Called when another gather follows: a solve that its first round ends needs none.
    /// Returns the rays cast. Parallel over points; deterministic.
    std::uint64_t take_cheap_rays(const std::function<bool()>& stop, std::size_t max_bytes);
    /// Points not gathered yet aim part of their rays at the bright sides of `field` (the
    /// sensors' fixed-normal points; not the eyes, nor receivers that average their normal), if
    /// all points' aims take at most `max_bytes`; else none aims.
    void aim_at_bright_sides(const PhotonField& field, std::size_t max_bytes);
    /// What the points' aims hold.
    std::size_t aims_bytes() const;
    /// The ray sets per point on average, over every point.
    int sets() const;
    /// The same within each sensor set.
    std::vector<int> set_means() const;
    /// Whether the last gather gave every point the sets allotted to it (not cut short).
    bool reached() const { return reached_; }
    /// The sensor sets' sizes, in the order of the points.
    const std::vector<std::size_t>& set_sizes() const { return set_sizes_; }
    std::size_t points() const { return points_.size(); }

    /// Every point's value and error parts on `field`, in the order of the sets and their
    /// points.
    std::vector<GatheredPoint> evaluate(const PhotonField& field) const;
    std::size_t memory_bytes() const;
    /// What one more ray set costs at one point: its value, its rays' landings, and the near
    /// hits among them at the share seen so far (every ray, before any is cast).
    std::size_t bytes_per_set() const;
    /// What a point holds before any set, besides its lists' heap blocks.
    static std::size_t bytes_per_point();

private:
    /// A ray that landed too near for its element's average light, and the side its one
    /// further bounce landed on (or −1).
    struct NearHit {
        int first = 0;
        int second = -1;
    };
    /// A far hit's check: where the path beyond it first lands far enough for an element's
    /// average (`second`, −1 for nowhere), the reflectances along the way before that element's
    /// own (`through`, the hit's included), and the direct light the path's spots send back
    /// (lux), to compare with the hit's element average.
    struct FarBounce {
        int second = -1;
        float direct = 0;
        std::array<float, 3> through{};
    };
    /// A side the cheap rays of a point landed on, and their weights summed over its sets.
    struct SideWeight {
        int side = 0;
        float weight = 0;
    };
    struct Point {
        /// Cheap rays per set (see ControlPilot): −1 until the pilot decides; from then on every
        /// set has them.
        int cheap = -1;
        Vec3 position;
        SensorReceiver receiver;
        bool background = false;                ///< an observer's eye: no luminaire light
        LightSources::SensorSources sources{};  ///< the light tree's cut at the point
        double luminaires = 0;                  ///< photometric, exact
        std::vector<double> set_direct{};  ///< per set: emitting pieces + mean ρ ⊙ E_direct(hit)
        /// per set, while the pilot runs or with cheap rays: the exact rays' mean of the control
        std::vector<double> set_control{};
        std::vector<double> set_cheap{};     ///< per set with cheap rays: their mean of the control
        std::vector<int> cheap_hits{};       ///< per cheap ray, set by set: its side, −1 for none
        std::vector<float> cheap_weights{};  ///< with aimed sides, per cheap ray: as `weights`
        /// The cheap rays' landings over all sets, by side (ascending): what the photon field's
        /// batches give the point is read through them, as its value is.
        std::vector<SideWeight> cheap_tally{};
        double pilot_rays = 0;  ///< what the sets gathered before the pilot decided cast
        /// per ray, set by set: the side it landed on, −1 for none, or −2 − i for near[i]
        std::vector<int> hits{};
        std::vector<NearHit> near{};
        /// per far hit of a ray that checks its depth, in the order of `hits`: the path beyond
        std::vector<FarBounce> far{};
        /// The bright sides the point aims at (none: cosine rays only), set before its first set.
        Aim aimed{};
        /// With aimed sides, per ray in the order of `hits`: its balance-heuristic weight.
        std::vector<float> weights{};
        int rays_per_set() const {
            return aimed.empty() ? kRaysPerSet : kRaysPerSet + kAimedRaysPerSet;
        }
        /// Cheap rays per set, the aimed ones included (in the exact rays' proportion).
        int cheap_rays_per_set() const { return cheap_rays(cheap, !aimed.empty()); }
    };
    /// Where a cosine-distributed ray from a hit lands, and what lights that spot directly.
    struct Bounce {
        int side = -1;
        Rgb reflectance{0, 0, 0};
        Rgb direct{0, 0, 0};
        Vec3 position, normal;
        bool near = false;  ///< nearer than its element's size: its average is not that spot's
    };
    Bounce bounce(const Vec3& x, const Vec3& n, SampleStream& rng, std::uint64_t& rays) const;
    /// A far hit's check (see FarBounce), from the first bounce beyond it (`first`) on, through
    /// the hit's reflectance `rho`.
    FarBounce check_path(const Bounce& first, const Rgb& rho, SampleStream& rng,
                         std::uint64_t& rays) const;
    void gather_point(std::size_t index, Point& point, int sets, std::uint64_t& rays) const;
    /// Set `set`'s cheap rays at a point that takes them: returns their mean of the control.
    double cast_cheap(std::size_t index, Point& point, int set, std::uint64_t& rays) const;
    /// Adds the cheap rays of sets [from, to) to the point's tally.
    static void tally_cheap(Point& point, std::size_t from, std::size_t to);
    /// The cheap rays a set casts for `cheap` cosine ones, with those aimed where it `aims`.
    static int cheap_rays(int cheap, bool aims) {
        return cheap <= 0 ? 0 : aims ? cheap + cheap / kAimsPerCosineRays : cheap;
    }
    /// What they add to a set: their mean, their sides and, where it aims, their weights.
    static std::size_t cheap_bytes(int cheap, bool aims) {
        if (cheap <= 0) return 0;
        return sizeof(double) + static_cast<std::size_t>(cheap_rays(cheap, aims)) *
                                    (sizeof(int) + (aims ? sizeof(float) : 0));
    }
    /// The cheap rays per set the pilot's sets of points [first, first + size) pay for, or −1
    /// where no point has two sets to tell a spread by.
    int pilot_choice(std::size_t first, std::size_t size) const;
    /// The weight of a ray in unit direction d from a point with unit normal n that aims at
    /// `aimed`, landing on `side` (−1: none) at distance t: the cosine rays' density over the
    /// sum of both kinds' (balance heuristic).
    double balance_weight(const Aim& aimed, const Vec3& n, const Vec3& d, int side, double t) const;

    const PreparedScene& scene_;
    const ElementMesh& mesh_;
    const LightSources& sources_;
    const SideDirectCache& cache_;
    const Visibility& visibility_;
    std::uint64_t seed_;
    std::uint64_t stream_;  ///< keys the points' samples: the eyes' apart from the sensors'
    std::vector<Point> points_;
    std::vector<std::size_t> set_sizes_;
    std::vector<int> set_cheap_;  ///< per sensor set: its points' cheap rays, −1 undecided
    BrightSides bright_;
    bool reached_ = false;
};

}  // namespace radiant
