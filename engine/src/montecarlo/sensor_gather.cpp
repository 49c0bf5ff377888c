#include "montecarlo/sensor_gather.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>

#include "geometry/cosine_direction.h"
#include "montecarlo/channel_product.h"
#include "montecarlo/sample_variance.h"
#include "montecarlo/set_allotment.h"
#include "parallel/fork_join.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

constexpr int kStrata = 8;  // kStrata² = SensorGather::kRaysPerSet
static_assert(kStrata * kStrata == SensorGather::kRaysPerSet);
constexpr std::uint64_t kSensorStream = 0x73656e736f72ull, kEyeStream = 0x657965ull;
constexpr std::uint64_t kCheapStream = 0x6368656170ull;  // a set's cheap rays, apart from its own
constexpr int kBatches = PhotonField::kBatches;
// A hit nearer than this many times its element's size sees light that varies across the
// element (a desk's edge beside a stack of books): it is gathered one bounce further.
constexpr double kNearHit = 1.0;
// Rays from a sensor or a hit end beyond anything in the scene.
double ray_length(const PreparedScene& scene) { return 4 * scene.diagonal_m + 1; }
// One ray in this many checks a far hit's element average against the path beyond it (see
// GatheredPoint::depth_difference_squared): the check costs rays and the direct light at their
// ends, so checking every ray made the furnished offices' gathers about twice as dear. The checked
// rays lie on diagonals of the strata, so that every row and column of them has its share.
constexpr int kDepthCheckEvery = 4;
bool checks_depth(int ray) { return (ray / kStrata + ray % kStrata) % kDepthCheckEvery == 0; }
// A check's path goes on while it lands too near for an element's average, up to this many
// bounces: in a room's corners and under its desks the first bounce often does, and reading its
// average there made the check see a bias in the example office that its answer did not have.
constexpr int kMaxCheckBounces = 4;

}  // namespace

SensorGather::SensorGather(const PreparedScene& scene, const ElementMesh& mesh,
                           const LightSources& sources, const SideDirectCache& cache,
                           const Visibility& visibility, std::uint64_t seed, Points which)
    : scene_(scene),
      mesh_(mesh),
      sources_(sources),
      cache_(cache),
      visibility_(visibility),
      seed_(seed),
      stream_(which == Points::sensors ? kSensorStream : kEyeStream) {
    if (which == Points::eyes) {
        for (const PreparedObserver& o : scene.observers) {
            points_.push_back({.position = o.position,
                               .receiver = SensorReceiver(SensorKind::planar, o.view),
                               .background = true});
            set_sizes_.push_back(1);
        }
        return;
    }
    for (const PreparedSensorSet& set : scene.sensors) {
        for (const Vec3& p : set.points)
            points_.push_back({.position = p, .receiver = SensorReceiver(set.kind, set.normal)});
        set_sizes_.push_back(set.points.size());
    }
}

std::size_t SensorGather::bytes_per_point() { return sizeof(Point); }

std::size_t SensorGather::bytes_per_set() const {
    std::size_t hits = 0, near = 0, aiming = 0, cheap = 0, cheap_rays = 0, tallied = 0,
                tallied_rays = 0;
    for (const Point& p : points_) {
        hits += p.hits.size();
        near += p.near.size();
        aiming += p.aimed.empty() ? 0 : 1;
        // An undecided point keeps its control's mean; one with cheap rays, that and theirs.
        cheap += p.cheap == 0 ? 0 : sizeof(double) + cheap_bytes(p.cheap, !p.aimed.empty());
        cheap_rays += static_cast<std::size_t>(p.cheap_rays_per_set());
        tallied += p.cheap_tally.size();
        tallied_rays += p.set_cheap.size() * static_cast<std::size_t>(p.cheap_rays_per_set());
    }
    // A tally grows by a side per cheap ray at most, and less as its sides repeat: at the share
    // seen so far.
    const double tally_share =
        tallied_rays > 0 ? static_cast<double>(tallied) / static_cast<double>(tallied_rays) : 1.0;
    cheap += static_cast<std::size_t>(
        std::ceil(tally_share * static_cast<double>(cheap_rays * sizeof(SideWeight))));
    const double share = hits > 0 ? static_cast<double>(near) / static_cast<double>(hits) : 1.0;
    const double aiming_share =
        points_.empty() ? 0.0 : static_cast<double>(aiming) / static_cast<double>(points_.size());
    const double rays = kRaysPerSet + aiming_share * kAimedRaysPerSet;
    const std::size_t cheap_share = points_.empty() ? 0 : cheap / points_.size();
    return sizeof(double) + cheap_share + kRaysPerSet / kDepthCheckEvery * sizeof(FarBounce) +
           static_cast<std::size_t>(
               std::ceil(rays * (sizeof(int) + share * sizeof(NearHit)) +
                         aiming_share * (kRaysPerSet + kAimedRaysPerSet) * sizeof(float)));
}

std::size_t SensorGather::memory_bytes() const {
    std::size_t bytes = points_.capacity() * sizeof(Point);
    for (const Point& p : points_) {
        bytes += (p.set_direct.capacity() + p.set_control.capacity() + p.set_cheap.capacity()) *
                     sizeof(double) +
                 (p.hits.capacity() + p.cheap_hits.capacity()) * sizeof(int) +
                 p.cheap_tally.capacity() * sizeof(SideWeight) +
                 p.cheap_weights.capacity() * sizeof(float) + p.far.capacity() * sizeof(FarBounce) +
                 p.near.capacity() * sizeof(NearHit) + p.aimed.capacity() * sizeof(AimedSide) +
                 p.weights.capacity() * sizeof(float) +
                 p.sources.pieces.capacity() * sizeof(std::size_t) +
                 p.sources.clusters.capacity() * sizeof(int);
    }
    return bytes;
}

SensorGather::Bounce SensorGather::bounce(const Vec3& x, const Vec3& n, SampleStream& rng,
                                          std::uint64_t& rays) const {
    const double eps = visibility_.epsilon();
    const Vec3 from = x + n * eps;
    const Vec3 d = cosine_direction(n, rng.next(), rng.next());
    ++rays;
    const RayHit hit = visibility_.intersect(from, d, ray_length(scene_));
    Bounce out;
    out.side = hit.triangle < 0 ? -1 : mesh_.side_hit(hit.triangle, d);
    if (out.side < 0) return out;
    const MeshElement& e = mesh_[static_cast<std::size_t>(hit.triangle)];
    out.reflectance = scene_.materials[static_cast<std::size_t>(e.material)].reflectance;
    out.position = from + d * hit.t;
    out.normal = mesh_.side_normal(out.side);
    out.near = hit.t < kNearHit * std::sqrt(e.area_m2);
    out.direct = sources_.direct_at(out.position, out.normal, visibility_, rng, rays);
    return out;
}

SensorGather::FarBounce SensorGather::check_path(const Bounce& first, const Rgb& rho,
                                                 SampleStream& rng, std::uint64_t& rays) const {
    FarBounce out;
    Rgb through = rho;
    double direct = 0;
    Bounce at = first;
    // The gather's own rule one level down: a spot too near for its element's average is read
    // one bounce further, up to kMaxCheckBounces bounces in all.
    for (int bounces = 1; at.side >= 0; ++bounces) {
        direct += photometric(times(through, times(at.reflectance, at.direct)), scene_.channels);
        if (!at.near || bounces == kMaxCheckBounces) {
            out.second = at.side;
            break;
        }
        through = times(through, at.reflectance);
        at = bounce(at.position, at.normal, rng, rays);
    }
    out.direct = static_cast<float>(direct);
    for (int c = 0; c < 3; ++c)
        out.through[static_cast<std::size_t>(c)] =
            static_cast<float>(through[static_cast<std::size_t>(c)]);
    return out;
}

double SensorGather::balance_weight(const Aim& aimed, const Vec3& n, const Vec3& d, int side,
                                    double t) const {
    const double cosine = std::max(0.0, dot(n, d)) / std::numbers::pi;
    if (!(cosine > 0)) return 0;
    const double aimed_density = side < 0 ? 0.0 : bright_.density(aimed, side, t, d);
    return kRaysPerSet * cosine / (kRaysPerSet * cosine + kAimedRaysPerSet * aimed_density);
}

void SensorGather::gather_point(std::size_t index, Point& point, int sets,
                                std::uint64_t& rays) const {
    const int channels = scene_.channels;
    const double eps = visibility_.epsilon();
    const double t_max = ray_length(scene_);
    const SensorReceiver& receiver = point.receiver;
    const bool fixed = receiver.fixed();
    const Vec3 fixed_normal = receiver.normal_at(0);
    if (point.set_direct.empty()) {
        point.sources =
            sources_.sensor_sources(point.position, receiver, visibility_, !point.background, rays);
        point.luminaires = photometric(point.sources.luminaires, channels);
    }
    const bool aims = !point.aimed.empty();
    const auto per_set = static_cast<std::size_t>(point.rays_per_set());
    // Exactly what `sets` need: the memory budget counts them so (bytes_per_set).
    point.set_direct.reserve(static_cast<std::size_t>(sets));
    point.hits.reserve(static_cast<std::size_t>(sets) * per_set);
    if (aims) point.weights.reserve(static_cast<std::size_t>(sets) * per_set);
    point.far.reserve(static_cast<std::size_t>(sets) * kRaysPerSet / kDepthCheckEvery);
    if (point.cheap != 0) point.set_control.reserve(static_cast<std::size_t>(sets));
    if (point.cheap > 0) {
        const auto cheap_per_set = static_cast<std::size_t>(point.cheap_rays_per_set());
        point.set_cheap.reserve(static_cast<std::size_t>(sets));
        point.cheap_hits.reserve(static_cast<std::size_t>(sets) * cheap_per_set);
        if (aims) point.cheap_weights.reserve(static_cast<std::size_t>(sets) * cheap_per_set);
    }
    const std::size_t had = point.set_direct.size();
    for (int set = static_cast<int>(had); set < sets; ++set) {
        const std::uint64_t rays_before = rays;
        SampleStream rng(seed_, stream_, index, static_cast<std::uint64_t>(set));
        // A kind that averages receiver normals draws the emitting surfaces' one per set, and
        // one per ray in strata turned by a random offset (any offset covers every stratum).
        const Vec3 set_normal = fixed ? fixed_normal : receiver.normal_at(rng.next());
        const int offset = fixed ? 0 : static_cast<int>(rng.next() * kRaysPerSet);
        double direct = photometric(sources_.sensor_set_light(point.sources, point.position,
                                                              set_normal, visibility_, rng, rays),
                                    channels);
        double reflected = 0, control = 0;
        // One ray's landing, its light weighed against the aimed rays' where the point aims;
        // `aimed_side`: the side an aimed ray was drawn on, −1 for a cosine ray; `check`: a far
        // hit's path goes on (check_path).
        const auto cast = [&](const Vec3& origin, const Vec3& normal, const Vec3& d, int aimed_side,
                              bool check) {
            ++rays;
            const RayHit hit = visibility_.intersect(origin, d, t_max);
            const int side = hit.triangle < 0 ? -1 : mesh_.side_hit(hit.triangle, d);
            // An aimed ray that lands elsewhere drew a point the sensor does not see.
            const double weight = !aims ? 1.0
                                  : aimed_side >= 0 && side != aimed_side
                                      ? 0.0
                                      : balance_weight(point.aimed, normal, d, side, hit.t);
            if (aims) point.weights.push_back(static_cast<float>(weight));
            // The light this ray brings (f) and the control's value where it lands (g).
            double f = 0, g = 0;
            const auto tally = [&] {
                reflected += f;
                control += g;
            };
            if (side < 0 || !(weight > 0)) {
                point.hits.push_back(-1);
                tally();
                return;
            }
            const MeshElement& e = mesh_[static_cast<std::size_t>(hit.triangle)];
            const Rgb& rho = scene_.materials[static_cast<std::size_t>(e.material)].reflectance;
            const Vec3 n = mesh_.side_normal(side);
            const Vec3 x = origin + d * hit.t;
            const Rgb h = sources_.direct_at(x, n, visibility_, rng, rays);
            f = weight * photometric(times(rho, h), channels);
            if (point.cheap != 0) g = weight * cache_.reflected(side);
            // One bounce further, where the element's average is not the light of this spot:
            // always for a near hit; for a far one only to measure what the average misses
            // (check_path).
            const bool far = hit.t >= kNearHit * std::sqrt(e.area_m2);
            if (far && !check) {
                point.hits.push_back(side);
                tally();
                return;
            }
            const Bounce further = bounce(x, n, rng, rays);
            if (far) {
                point.hits.push_back(side);
                point.far.push_back(check_path(further, rho, rng, rays));
                tally();
                return;
            }
            if (further.side >= 0)
                f += weight *
                     photometric(times(rho, times(further.reflectance, further.direct)), channels);
            tally();
            point.hits.push_back(-2 - static_cast<int>(point.near.size()));
            point.near.push_back({side, further.side});
        };
        for (int k = 0; k < kRaysPerSet; ++k) {
            const Vec3 normal =
                fixed ? fixed_normal
                      : receiver.normal_at(((k + offset) % kRaysPerSet + rng.next()) / kRaysPerSet);
            const Vec3 origin = point.position + normal * eps;
            const double r1 = (k / kStrata + rng.next()) / kStrata;
            const double r2 = (k % kStrata + rng.next()) / kStrata;
            const Vec3 d = cosine_direction(normal, r1, r2);
            cast(origin, normal, d, -1, checks_depth(k));
        }
        if (aims) {
            const Vec3 origin = point.position + fixed_normal * eps;
            // In strata of the sides' probabilities, as the cosine rays are in strata of the
            // hemisphere.
            for (int k = 0; k < kAimedRaysPerSet; ++k) {
                const AimedRay ray =
                    bright_.draw(point.aimed, origin, rng, (k + rng.next()) / kAimedRaysPerSet);
                if (dot(fixed_normal, ray.direction) > 0) {
                    cast(origin, fixed_normal, ray.direction, ray.side, false);
                } else {  // behind the sensor: nothing to cast
                    point.weights.push_back(0);
                    point.hits.push_back(-1);
                }
            }
        }
        point.set_direct.push_back(direct + reflected / kRaysPerSet);
        if (point.cheap != 0) point.set_control.push_back(control / kRaysPerSet);
        if (point.cheap > 0) point.set_cheap.push_back(cast_cheap(index, point, set, rays));
        if (point.cheap < 0) point.pilot_rays += static_cast<double>(rays - rays_before);
    }
    if (point.cheap > 0 && had < point.set_cheap.size())
        tally_cheap(point, had, point.set_cheap.size());
}

void SensorGather::tally_cheap(Point& point, std::size_t from, std::size_t to) {
    const auto m = static_cast<std::size_t>(point.cheap_rays_per_set());
    std::vector<SideWeight> added;
    added.reserve((to - from) * m);
    for (std::size_t c = from * m; c < to * m; ++c) {
        const int side = point.cheap_hits[c];
        if (side >= 0)
            added.push_back({side, point.cheap_weights.empty() ? 1.0f : point.cheap_weights[c]});
    }
    added.insert(added.end(), point.cheap_tally.begin(), point.cheap_tally.end());
    // Stable: equal sides keep their order, so the sums do not depend on the sort.
    std::ranges::stable_sort(added, {}, &SideWeight::side);
    std::vector<SideWeight> tally;
    for (const SideWeight& a : added) {
        if (!tally.empty() && tally.back().side == a.side) {
            tally.back().weight += a.weight;
        } else {
            tally.push_back(a);
        }
    }
    point.cheap_tally = std::move(tally);
}

double SensorGather::cast_cheap(std::size_t index, Point& point, int set,
                                std::uint64_t& rays) const {
    const int m = point.cheap;
    // In strata of the hemisphere, as the exact rays, rows × columns of them; where the point
    // aims, with aimed rays in the exact rays' proportion, weighed alike.
    const int rows = 1 << ((std::bit_width(static_cast<unsigned>(m)) - 1) / 2);
    const int columns = m / rows;
    const int aimed = point.cheap_rays_per_set() - m;
    const double eps = visibility_.epsilon();
    const double t_max = ray_length(scene_);
    const SensorReceiver& receiver = point.receiver;
    const bool fixed = receiver.fixed();
    const Vec3 fixed_normal = receiver.normal_at(0);
    SampleStream rng(seed_, stream_ ^ kCheapStream, index, static_cast<std::uint64_t>(set));
    const int offset = fixed ? 0 : static_cast<int>(rng.next() * m);
    double sum = 0;
    const auto cast = [&](const Vec3& normal, const Vec3& d, int aimed_side) {
        ++rays;
        const RayHit hit = visibility_.intersect(point.position + normal * eps, d, t_max);
        const int side = hit.triangle < 0 ? -1 : mesh_.side_hit(hit.triangle, d);
        const double weight = aimed == 0 ? 1.0
                              : aimed_side >= 0 && side != aimed_side
                                  ? 0.0
                                  : balance_weight(point.aimed, normal, d, side, hit.t);
        if (aimed > 0) point.cheap_weights.push_back(static_cast<float>(weight));
        point.cheap_hits.push_back(weight > 0 ? side : -1);
        if (side >= 0 && weight > 0) sum += weight * cache_.reflected(side);
    };
    for (int k = 0; k < m; ++k) {
        const Vec3 normal =
            fixed ? fixed_normal : receiver.normal_at(((k + offset) % m + rng.next()) / m);
        const double r1 = (k / columns + rng.next()) / rows;
        const double r2 = (k % columns + rng.next()) / columns;
        cast(normal, cosine_direction(normal, r1, r2), -1);
    }
    for (int k = 0; k < aimed; ++k) {
        const AimedRay ray = bright_.draw(point.aimed, point.position + fixed_normal * eps, rng,
                                          (k + rng.next()) / aimed);
        if (dot(fixed_normal, ray.direction) > 0) {
            cast(fixed_normal, ray.direction, ray.side);
        } else {  // behind the sensor: nothing to cast
            point.cheap_weights.push_back(0);
            point.cheap_hits.push_back(-1);
        }
    }
    return sum / m;
}

void SensorGather::aim_at_bright_sides(const PhotonField& field, std::size_t max_bytes) {
    bright_ = BrightSides(scene_, mesh_, field);
    if (bright_.empty()) return;
    const std::size_t before = aims_bytes();
    const auto aims = [](const Point& p) {
        return p.set_direct.empty() && p.receiver.fixed() && !p.background;
    };
    const std::size_t most = BrightSides::most_aimed(
        static_cast<std::size_t>(std::count_if(points_.begin(), points_.end(), aims)));
    parallel_for(0, points_.size(), [&](std::size_t i) {
        Point& p = points_[i];
        if (aims(p)) p.aimed = bright_.aim(p.position, p.receiver.normal_at(0), most);
    });
    if (aims_bytes() - before <= max_bytes) return;
    // Aiming only saves rays: where its lists do not fit, the points do without.
    for (Point& p : points_) {
        if (p.set_direct.empty()) Aim().swap(p.aimed);
    }
}

std::size_t SensorGather::aims_bytes() const {
    std::size_t bytes = 0;
    for (const Point& p : points_) bytes += p.aimed.capacity() * sizeof(AimedSide);
    return bytes;
}

std::uint64_t SensorGather::gather(const std::vector<int>& sets, const std::function<bool()>& stop,
                                   const std::vector<GatheredPoint>& last) {
    std::vector<int> has(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i)
        has[i] = static_cast<int>(points_[i].set_direct.size());
    // A point's spread per set: its mean's variance times its sets.
    std::vector<double> spread;
    if (last.size() == points_.size()) {
        for (const GatheredPoint& g : last) spread.push_back(std::sqrt(g.gather_variance * g.sets));
    }
    const std::vector<int> target = allot_sets(sets, has, spread, set_sizes_);
    std::vector<std::uint64_t> rays(points_.size(), 0);
    const std::uint64_t cache_rays = cache_.rays();
    parallel_for(0, points_.size(), [&](std::size_t i) {
        if (!stop()) gather_point(i, points_[i], target[i], rays[i]);
    });
    reached_ = true;
    for (std::size_t i = 0; i < points_.size(); ++i)
        reached_ = reached_ && points_[i].set_direct.size() >= static_cast<std::size_t>(target[i]);
    std::uint64_t total = cache_.rays() - cache_rays;
    for (const std::uint64_t r : rays) total += r;
    return total;
}

int SensorGather::pilot_choice(std::size_t first, std::size_t size) const {
    // Pooled over the set's points: one point's few sets say little.
    ControlPilot pilot;
    for (std::size_t i = first; i < first + size; ++i) {
        const Point& p = points_[i];
        const auto n = static_cast<int>(p.set_direct.size());
        if (n < 2 || p.set_control.size() != p.set_direct.size()) continue;
        std::vector<double> residual(p.set_direct.size());
        for (std::size_t j = 0; j < residual.size(); ++j)
            residual[j] = p.set_direct[j] - p.set_control[j];
        // Sample variances of the sets' values, not of their means.
        pilot.plain += n * sample_variance_of_mean(p.set_direct.data(), n);
        pilot.residual += n * sample_variance_of_mean(residual.data(), n);
        pilot.control += n * sample_variance_of_mean(p.set_control.data(), n);
        pilot.sets += n;  // undecided, every set it has is the pilot's
        pilot.rays += p.pilot_rays;
    }
    return pilot.sets > 0 ? cheap_rays_per_set(pilot, kRaysPerSet) : -1;
}

std::uint64_t SensorGather::take_cheap_rays(const std::function<bool()>& stop,
                                            std::size_t max_bytes) {
    set_cheap_.resize(set_sizes_.size(), -1);
    const std::uint64_t cache_rays = cache_.rays();
    std::vector<std::uint64_t> rays(points_.size(), 0);
    std::size_t first = 0;
    for (std::size_t s = 0; s < set_sizes_.size(); ++s) {
        const std::size_t begin = first, size = set_sizes_[s];
        first += size;
        if (set_cheap_[s] < 0) {
            const int cheap = pilot_choice(begin, size);
            std::size_t bytes = 0;
            for (std::size_t i = begin; i < begin + size; ++i) {
                const Point& p = points_[i];
                bytes += p.set_direct.size() * cheap_bytes(cheap, !p.aimed.empty());
            }
            set_cheap_[s] = bytes <= max_bytes ? cheap : 0;
            if (cheap > 0 && bytes <= max_bytes) max_bytes -= bytes;
        }
        const int cheap = set_cheap_[s];
        if (cheap < 0) continue;
        parallel_for(begin, begin + size, [&](std::size_t i) {
            Point& p = points_[i];
            if (p.cheap >= 0 || stop()) return;
            p.cheap = cheap;
            if (cheap == 0) {
                std::vector<double>().swap(p.set_control);
                return;
            }
            const std::size_t sets = p.set_direct.size();
            const auto per_set = static_cast<std::size_t>(p.cheap_rays_per_set());
            p.set_cheap.reserve(sets);
            p.cheap_hits.reserve(sets * per_set);
            if (!p.aimed.empty()) p.cheap_weights.reserve(sets * per_set);
            for (std::size_t set = 0; set < sets; ++set)
                p.set_cheap.push_back(cast_cheap(i, p, static_cast<int>(set), rays[i]));
            tally_cheap(p, 0, sets);
        });
    }
    std::uint64_t total = cache_.rays() - cache_rays;
    for (const std::uint64_t r : rays) total += r;
    return total;
}

std::uint64_t SensorGather::gather(int sets, const std::function<bool()>& stop) {
    return gather(std::vector<int>(set_sizes_.size(), sets), stop);
}

int SensorGather::sets() const {
    if (points_.empty()) return 0;
    std::size_t gathered = 0;
    for (const Point& p : points_) gathered += p.set_direct.size();
    return static_cast<int>(gathered / points_.size());
}

std::vector<int> SensorGather::set_means() const {
    std::vector<int> out;
    std::size_t first = 0;
    for (const std::size_t size : set_sizes_) {
        std::size_t gathered = 0;
        for (std::size_t i = first; i < first + size; ++i) gathered += points_[i].set_direct.size();
        out.push_back(size > 0 ? static_cast<int>(gathered / size) : 0);
        first += size;
    }
    return out;
}

std::vector<GatheredPoint> SensorGather::evaluate(const PhotonField& field) const {
    const int channels = scene_.channels;
    const std::vector<ElementSide>& sides = mesh_.sides();
    auto reflectance = [&](int side) -> const Rgb& {
        const MeshElement& e =
            mesh_[static_cast<std::size_t>(sides[static_cast<std::size_t>(side)].element)];
        return scene_.materials[static_cast<std::size_t>(e.material)].reflectance;
    };
    // The reflected indirect light of every side: ρ ⊙ H_ind, per channel and photometric.
    std::vector<Rgb> reflected(sides.size());
    std::vector<double> reflected_lux(sides.size());
    parallel_for(0, sides.size(), [&](std::size_t s) {
        reflected[s] = times(reflectance(static_cast<int>(s)), field.indirect(static_cast<int>(s)));
        reflected_lux[s] = photometric(reflected[s], channels);
    });
    // A side's twin at the coarser level: the same side of its sibling, or none.
    auto sibling_side = [&](int side) {
        const ElementSide& s = sides[static_cast<std::size_t>(side)];
        const MeshElement& e = mesh_[static_cast<std::size_t>(s.element)];
        if (e.sibling < 0) return -1;
        const MeshElement& o = mesh_[static_cast<std::size_t>(e.sibling)];
        return s.back ? o.back : o.front;
    };
    auto area = [&](int side) {
        return side < 0 ? 0.0 : sides[static_cast<std::size_t>(side)].open_area_m2;
    };
    std::vector<GatheredPoint> out(points_.size());
    parallel_for(0, points_.size(), [&](std::size_t i) {
        const Point& p = points_[i];
        const auto sets = static_cast<int>(p.set_direct.size());
        GatheredPoint& g = out[i];
        g.illuminance = p.luminaires;
        g.sets = sets;
        if (sets == 0) return;
        std::vector<double> set_value(static_cast<std::size_t>(sets));
        std::array<double, kBatches> batch{}, batch_coarse{};
        // With cheap rays: the batches' share of what the control variate reads of the field.
        std::array<double, kBatches> controlled_batch{};
        double coarse = 0, fine_sum = 0, fine = 0;
        // Checked far hits' element average less the path beyond them: their sum, their squares'
        // sum and the sum's share of each batch (see GatheredPoint::depth_difference_squared).
        double depth_sum = 0, depth_squares = 0;
        std::array<double, kBatches> depth_batch{};
        std::size_t far = 0;
        auto check_depth = [&](int side) {
            const FarBounce& b = p.far[far++];
            double difference = reflected_lux[static_cast<std::size_t>(side)] - b.direct;
            double scale = 0;  // the second side's batch tallies, through the path's reflectances
            if (b.second >= 0) {
                const auto second = static_cast<std::size_t>(b.second);
                const Rgb through{b.through[0], b.through[1], b.through[2]};
                const double beyond = photometric(times(through, reflected[second]), channels);
                difference -= beyond;
                scale = reflected_lux[second] > 0 ? beyond / reflected_lux[second] : 0;
            }
            depth_sum += difference;
            depth_squares += difference * difference;
            for (int q = 0; q < kBatches; ++q) {
                depth_batch[static_cast<std::size_t>(q)] +=
                    field.batch_reflected(side, q) - b.direct -
                    (b.second >= 0 ? scale * field.batch_reflected(b.second, q) : 0.0);
            }
        };
        // The field's light reflected at `side` toward the point; a near hit's, through the
        // reflectance of the first surface (`first`, else none). Its batch tallies go to
        // `also` too, if given.
        auto land = [&](int side, int first, double weight,
                        std::array<double, kBatches>* also = nullptr) -> double {
            const int twin = sibling_side(side);
            const double a = area(side), b = area(twin);
            // Never 0/0, even for a sliver whose area rounds to nothing.
            const double wa = a + b > 0 ? a / (a + b) : 1.0, wb = 1 - wa;
            double value = reflected_lux[static_cast<std::size_t>(side)];
            double value_twin = twin < 0 ? value : reflected_lux[static_cast<std::size_t>(twin)];
            double scale = 1;  // the batches' photometric tallies, through `first`
            if (first >= 0) {
                const Rgb& rho = reflectance(first);
                const double through =
                    photometric(times(rho, reflected[static_cast<std::size_t>(side)]), channels);
                scale = value > 0 ? through / value : 0;
                value = through;
                value_twin =
                    twin < 0 ? value
                             : photometric(times(rho, reflected[static_cast<std::size_t>(twin)]),
                                           channels);
            }
            fine += weight * value;
            coarse += weight * (wa * value + wb * value_twin);
            for (int q = 0; q < kBatches; ++q) {
                const double f = weight * scale * field.batch_reflected(side, q);
                batch[static_cast<std::size_t>(q)] += f;
                if (also) (*also)[static_cast<std::size_t>(q)] += f;
                batch_coarse[static_cast<std::size_t>(q)] +=
                    twin < 0 ? f : wa * f + wb * scale * field.batch_reflected(twin, q);
            }
            return weight * value;
        };
        const int per_set = p.rays_per_set();
        for (int j = 0; j < sets; ++j) {
            const auto js = static_cast<std::size_t>(j);
            // With cheap rays, the field's light as the control reads it: at every cheap ray's
            // element, and where an exact ray lands near, the difference its further bounce makes.
            const bool cheap = p.cheap > 0;
            double controlled = 0;
            fine = 0;
            for (int k = 0; k < per_set; ++k) {
                const auto ray = static_cast<std::size_t>(j * per_set + k);
                const int code = p.hits[ray];
                const double weight = p.weights.empty() ? 1.0 : p.weights[ray];
                if (code >= 0) {
                    land(code, -1, weight);
                    if (k < kRaysPerSet && checks_depth(k)) check_depth(code);
                } else if (code <= -2) {
                    const NearHit& near = p.near[static_cast<std::size_t>(-2 - code)];
                    if (near.second >= 0)
                        controlled += land(near.second, near.first, weight,
                                           cheap ? &controlled_batch : nullptr);
                    controlled -= weight * reflected_lux[static_cast<std::size_t>(near.first)];
                    for (int q = 0; q < kBatches && cheap; ++q)
                        controlled_batch[static_cast<std::size_t>(q)] -=
                            weight * field.batch_reflected(near.first, q);
                }
            }
            fine_sum += fine;
            double value = p.set_direct[js] + fine / kRaysPerSet;
            if (cheap) {
                const auto m = static_cast<std::size_t>(p.cheap_rays_per_set());
                const double share = kRaysPerSet / static_cast<double>(p.cheap);
                for (std::size_t c = js * m; c < (js + 1) * m; ++c) {
                    const int side = p.cheap_hits[c];
                    const double weight = p.cheap_weights.empty() ? 1.0 : p.cheap_weights[c];
                    if (side >= 0)
                        controlled +=
                            weight * reflected_lux[static_cast<std::size_t>(side)] * share;
                }
                value = p.set_direct[js] - p.set_control[js] + p.set_cheap[js] +
                        controlled / kRaysPerSet;
            }
            set_value[js] = value;
        }
        const double rays = static_cast<double>(sets) * kRaysPerSet;
        double mean = 0;
        for (const double v : set_value) mean += v;
        g.illuminance += mean / sets;
        g.gather_variance = sample_variance_of_mean(set_value.data(), sets);
        std::array<double, kBatches> difference{};
        for (int q = 0; q < kBatches; ++q) {
            const auto qi = static_cast<std::size_t>(q);
            batch[qi] /= rays;
            batch_coarse[qi] /= rays;
            difference[qi] = batch[qi] - batch_coarse[qi];
        }
        // With cheap rays the field reaches the point's value through them and the near hits'
        // differences: its batches are read so. Read through the exact rays' few landings, each
        // element's own noise counted as if the value read that few elements.
        if (p.cheap > 0) {
            const double share = kRaysPerSet / static_cast<double>(p.cheap);
            for (const SideWeight& t : p.cheap_tally) {
                for (int q = 0; q < kBatches; ++q)
                    controlled_batch[static_cast<std::size_t>(q)] +=
                        share * t.weight * field.batch_reflected(t.side, q);
            }
            for (double& v : controlled_batch) v /= rays;
        }
        const std::array<double, kBatches>& photon = p.cheap > 0 ? controlled_batch : batch;
        g.photon_variance = sample_variance_of_mean(photon.data(), kBatches);
        g.photon_batches = photon;
        const double d = (fine_sum - coarse) / rays;
        g.coarse_difference_squared = d * d;
        g.coarse_difference_variance = sample_variance_of_mean(difference.data(), kBatches);
        const double checked = rays / kDepthCheckEvery;
        const double depth = depth_sum / checked;
        g.depth_difference_squared = depth * depth;
        for (double& v : depth_batch) v /= checked;
        g.depth_difference_variance =
            std::max(0.0, depth_squares / checked - depth * depth) / (checked - 1) +
            sample_variance_of_mean(depth_batch.data(), kBatches);
    });
    return out;
}

}  // namespace radiant
