#include "montecarlo/light_sources.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "formfactor/luminaire_light.h"
#include "formfactor/point_polygon.h"
#include "geometry/cosine_direction.h"
#include "geometry/triangle_point.h"
#include "montecarlo/cdf_draw.h"

namespace radiant {
namespace {

// A sensor's view of an emitting piece is split into parts no longer than this share of their
// distance, at most this many times (4^3 parts per fan triangle), each seen through one ray.
constexpr double kPartSize = 0.3;
constexpr int kMaxPieceSplits = 3;
// A piece whose vertices lie within this share of its distance from its centroid is small: its
// light is sampled with the point kernel rather than its exact factor (piece_part).
constexpr double kSmallPiece = 0.1;

constexpr double kPi = std::numbers::pi;
// Next-event estimation visits every source up to this many, else draws from the light tree:
// a floor of a hundred rooms must not cast a hundred shadow rays per hit.
constexpr std::size_t kMaxNextEventSources = 16;
// Sources drawn per point beyond that: with the draw following each source's rough light, a
// few carry most of it, and every draw costs a shadow ray (a floor of 16 rooms: 16 draws held
// the gather's time at 90 % of the solve).
constexpr std::size_t kNextEventDraws = 4;
// Beyond kMaxNextEventSources sources, as long as they make at most that many surfaces (and
// luminaires), each surface gets one draw of its own, among its pieces by their rough light:
// drawn from all sources at once, the pieces of lamps' bulbs hidden in their shades took the
// draws from the light that arrived (a living room's gather took 13 times the rays of the same
// room with point luminaires). Up to this many pieces in all, as each draw weighs each piece.
constexpr std::size_t kMaxSurfaceDrawPieces = 1024;
// Runs of at least this many pieces are drawn for far points by FarPieceDraw's tables.
constexpr std::size_t kFarDrawPieces = 16;
// Share of a draw of sources that goes by power alone rather than down the light tree.
constexpr double kPowerShare = 0.1;
// A sensor's cut of the light tree: clusters hold at most this share of the bounds on the
// light the cut's nodes could send, and the cut has at most this many nodes (rooms of a floor
// beyond the sensor's own are a few clusters; a room's own panels are each on their own).
constexpr double kCutRelativeBound = 0.01;
constexpr std::size_t kCutMaxNodes = 32;
// Up to this many nodes, a node the sensor sees part of (by kSeenProbes shadow rays to its
// pieces) is split further: a cluster is one source drawn by power per set, mostly the back of a
// lamp's bulb or a piece hidden by its shade, which put 10–15 % of a set's light at points
// beside a living room's lamps; listed on their own, the bulbs' pieces took the room's solve at
// tolerance 0.01 from 46 M rays to 17 M (124 M to 42 M with 256 work-plane points). Panels in
// rooms behind walls, seen by no probe, stay clusters: split, they cost a floor of 16 rooms 28 %
// more rays for nothing.
constexpr std::size_t kCutMaxSeenNodes = 128;
constexpr int kSeenProbes = 4;
constexpr int kGammaCells = 180;
constexpr int kCCells = 72;

// Draws for a point of a small part with the density of its light toward the sensor (see
// piece_part) before one is taken anyway: a draw is a few multiplications and no ray.
constexpr int kMaxKernelDraws = 64;

// A uniformly drawn point of triangle `t`.
Vec3 uniform_point(const std::array<Vec3, 3>& t, SampleStream& rng) {
    const double r1 = rng.next(), r2 = rng.next();
    return uniform_triangle_point(t[0], t[1], t[2], r1, r2);
}

// A point of triangle `t` (centroid `centre`, plane normal `normal`, facing x) drawn with
// density ∝ the point kernel cosθ cosθ' / r² toward x (normal n), by rejection from uniform
// points: the kernel is (n·d) h / r⁴ with h the plane's distance from x, and (n·d) is largest at
// a vertex and r smallest at least the centre's distance less the vertices' spread about it.
Vec3 kernel_point(const Vec3& x, const Vec3& n, const std::array<Vec3, 3>& t, const Vec3& centre,
                  const Vec3& normal, SampleStream& rng) {
    double spread = 0, most_ahead = 0;
    for (const Vec3& v : t) {
        spread = std::max(spread, length(v - centre));
        most_ahead = std::max(most_ahead, dot(n, v - x));
    }
    const double h = -dot(normal, centre - x);
    const double r_min = std::max(h, length(centre - x) - spread);
    const double bound = most_ahead / (r_min * r_min * r_min * r_min);
    Vec3 y;
    for (int draw = 0; draw < kMaxKernelDraws; ++draw) {
        y = uniform_point(t, rng);
        const double r2 = length_squared(y - x);
        if (rng.next() * bound * r2 * r2 <= std::max(0.0, dot(n, y - x))) break;
    }
    return y;
}

Rgb scaled(const Rgb& c, double s) { return {c[0] * s, c[1] * s, c[2] * s}; }

void add(Rgb& a, const Rgb& b) {
    for (int c = 0; c < 3; ++c) a[c] += b[c];
}

Vec3 photometric_direction(const PreparedLuminaire& l, double gamma, double c) {
    return l.aim * std::cos(gamma) +
           (l.c0_axis * std::cos(c) + l.c90_axis * std::sin(c)) * std::sin(gamma);
}

// The largest intensity per lumen of flux in any direction.
double peak_intensity_per_lm(const PreparedLuminaire& l) {
    switch (l.distribution) {
        case Distribution::isotropic:
            return 1 / (4 * kPi);
        case Distribution::lambertian:
            return 1 / kPi;
        case Distribution::photometric:
            break;
    }
    return l.table->peak_candela() / l.table->flux_lm();
}

}  // namespace

LightSources::LightSources(const PreparedScene& scene, double ray_epsilon, int component)
    : scene_(scene), epsilon_(ray_epsilon), component_(component) {
    tables_.resize(scene.luminaires.size());
    for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
        const PreparedLuminaire& l = scene.luminaires[i];
        // Another component's luminaire keeps its index with no power: it is never drawn.
        source_power_.push_back(included(i) ? luminance(l.flux_lm) : 0.0);
        if (!included(i)) continue;
        if (l.distribution != Distribution::photometric) continue;
        // Each cell weighs the largest intensity at its centre and corners, so that no cell
        // with light is never drawn; the photon's weight corrects for the difference.
        std::vector<double>& cdf = tables_[i].cdf;
        double sum = 0;
        for (int g = 0; g < kGammaCells; ++g) {
            const double g0 = kPi * g / kGammaCells, g1 = kPi * (g + 1) / kGammaCells;
            for (int k = 0; k < kCCells; ++k) {
                const double c0 = 2 * kPi * k / kCCells, c1 = 2 * kPi * (k + 1) / kCCells;
                double peak = 0;
                for (const auto& [gg, cc] : {std::pair{0.5 * (g0 + g1), 0.5 * (c0 + c1)},
                                             {g0, c0},
                                             {g0, c1},
                                             {g1, c0},
                                             {g1, c1}}) {
                    peak = std::max(peak, intensity_per_lm(l, photometric_direction(l, gg, cc)));
                }
                sum += peak * (std::cos(g0) - std::cos(g1)) * (c1 - c0);
                cdf.push_back(sum);
            }
        }
    }
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const Piece& p = scene.pieces[i];
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(p.material)];
        if (!m.emits() || (component >= 0 && m.component != component)) continue;
        EmittingPiece e;
        e.piece = static_cast<int>(i);
        e.exitance = m.exitance_lm_m2;
        double area = 0;
        for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
            area += 0.5 *
                    length(cross(p.vertices[k] - p.vertices[0], p.vertices[k + 1] - p.vertices[0]));
            e.fan_cdf.push_back(area);
        }
        if (!(area > 0)) continue;
        Vec3 centroid{0, 0, 0};
        for (const Vec3& v : p.vertices) centroid += v;
        e.centroid = centroid / static_cast<double>(p.vertices.size());
        e.area = area;
        for (const Vec3& v : p.vertices) e.radius = std::max(e.radius, length(v - e.centroid));
        e.power = luminance(m.exitance_lm_m2) * area;
        source_power_.push_back(e.power);
        rough_.push_back({e.centroid, p.normal, area / kPi, e.power});
        pieces_.push_back(std::move(e));
    }
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        const int surface = scene.pieces[static_cast<std::size_t>(pieces_[i].piece)].surface;
        if (i == 0 ||
            scene.pieces[static_cast<std::size_t>(pieces_[i - 1].piece)].surface != surface) {
            surface_runs_.push_back({i, i, 0, nullptr});
        }
        surface_runs_.back().end = i + 1;
        surface_runs_.back().power += std::max(source_power_[scene.luminaires.size() + i], 0.0);
    }
    // Where landings weigh every piece of each run (direct_at), a run of many pieces gets a
    // draw for far points: the living room's bulbs, spheres of 320 facets each, held a third of
    // its solve in that weighing.
    if (scene.luminaires.size() + surface_runs_.size() <= kMaxNextEventSources &&
        pieces_.size() <= kMaxSurfaceDrawPieces) {
        for (SurfaceRun& run : surface_runs_) {
            if (run.end - run.first < kFarDrawPieces) continue;
            std::vector<Vec3> centroids, normals;
            std::vector<double> powers;
            for (std::size_t k = run.first; k < run.end; ++k) {
                centroids.push_back(rough_[k].centroid);
                normals.push_back(rough_[k].normal);
                powers.push_back(std::max(source_power_[scene.luminaires.size() + k], 0.0));
            }
            run.far = std::make_shared<const FarPieceDraw>(centroids, normals, powers, kPowerShare);
        }
    }
    for (const double w : source_power_) {
        total_power_ += std::max(w, 0.0);
        source_cdf_.push_back(total_power_);
    }
    std::vector<LightTreeSource> tree_sources;
    for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
        const PreparedLuminaire& l = scene.luminaires[i];
        Box at;
        at.add(l.position);
        // Another component's luminaire is a leaf without power: a cut or a draw finds no light.
        const double power = source_power_[i];
        tree_sources.push_back({at, power, power * peak_intensity_per_lm(l)});
    }
    for (const EmittingPiece& e : pieces_) {
        Box bounds;
        bounds.add(scene.pieces[static_cast<std::size_t>(e.piece)].vertices);
        tree_sources.push_back({bounds, e.power, e.power / kPi,
                                scene.pieces[static_cast<std::size_t>(e.piece)].normal});
    }
    tree_ = LightTree(tree_sources);
}

Vec3 LightSources::point_on(const EmittingPiece& e, double r1, double r2, double r3) const {
    const Piece& p = scene_.pieces[static_cast<std::size_t>(e.piece)];
    const std::size_t k = draw_index(e.fan_cdf, r1) + 1;
    const double s = std::sqrt(r2);
    return p.vertices[0] * (1 - s) + p.vertices[k] * (s * (1 - r3)) + p.vertices[k + 1] * (s * r3);
}

Vec3 LightSources::luminaire_direction(std::size_t i, SampleStream& rng, double& weight) const {
    const PreparedLuminaire& l = scene_.luminaires[i];
    const double r1 = rng.next(), r2 = rng.next();
    weight = 1;
    switch (l.distribution) {
        case Distribution::isotropic: {
            const double z = 1 - 2 * r1, s = std::sqrt(std::max(0.0, 1 - z * z));
            return {s * std::cos(2 * kPi * r2), s * std::sin(2 * kPi * r2), z};
        }
        case Distribution::lambertian:
            return cosine_direction(l.aim, r1, r2);
        case Distribution::photometric:
            break;
    }
    const std::vector<double>& cdf = tables_[i].cdf;
    const std::size_t cell = draw_index(cdf, rng.next());
    const int g = static_cast<int>(cell) / kCCells, k = static_cast<int>(cell) % kCCells;
    const double cos0 = std::cos(kPi * g / kGammaCells),
                 cos1 = std::cos(kPi * (g + 1) / kGammaCells);
    const double gamma = std::acos(std::clamp(cos0 + (cos1 - cos0) * r1, -1.0, 1.0));
    const double c = 2 * kPi * (k + r2) / kCCells;
    const Vec3 u = photometric_direction(l, gamma, c);
    const double cell_weight = cdf[cell] - (cell > 0 ? cdf[cell - 1] : 0.0);
    const double solid_angle = (cos0 - cos1) * 2 * kPi / kCCells;
    const double pdf = cell_weight / (cdf.back() * solid_angle);
    weight = pdf > 0 ? intensity_per_lm(l, u) / pdf : 0.0;
    return u;
}

Photon LightSources::emit(SampleStream& rng) const {
    Photon photon;
    if (empty()) return photon;
    const std::size_t s = draw_index(source_cdf_, rng.next());
    const double share = source_power_[s] / total_power_;
    if (s < scene_.luminaires.size()) {
        const PreparedLuminaire& l = scene_.luminaires[s];
        double weight = 1;
        photon.direction = luminaire_direction(s, rng, weight);
        photon.origin = l.position;
        photon.flux = scaled(l.flux_lm, weight / share);
        return photon;
    }
    const EmittingPiece& e = pieces_[s - scene_.luminaires.size()];
    const Piece& p = scene_.pieces[static_cast<std::size_t>(e.piece)];
    const double r1 = rng.next(), r2 = rng.next(), r3 = rng.next();
    photon.origin = point_on(e, r1, r2, r3) + p.normal * epsilon_;
    photon.direction = cosine_direction(p.normal, rng.next(), rng.next());
    photon.flux = scaled(e.exitance, e.fan_cdf.back() / share);
    return photon;
}

Vec3 LightSources::source_point(std::size_t s) const {
    const std::size_t luminaires = scene_.luminaires.size();
    if (s < luminaires) return scene_.luminaires[s].position;
    const EmittingPiece& e = pieces_[s - luminaires];
    return e.centroid + scene_.pieces[static_cast<std::size_t>(e.piece)].normal * epsilon_;
}

Rgb LightSources::part(std::size_t s, const Vec3& x, const Vec3& n, const Visibility& visibility,
                       SampleStream& rng, std::uint64_t& rays) const {
    const std::size_t luminaires = scene_.luminaires.size();
    if (s < luminaires) {
        return included(s) ? luminaire_irradiance_from(scene_.luminaires[s], visibility, x, n, rays)
                           : Rgb{0, 0, 0};
    }
    return piece_part(pieces_[s - luminaires], x, n, visibility, rng, false, rays);
}

Rgb LightSources::luminaire_at(std::size_t i, const Vec3& x, const SensorReceiver& receiver,
                               const Visibility& visibility, std::uint64_t& rays) const {
    if (!included(i)) return {0, 0, 0};
    const PreparedLuminaire& l = scene_.luminaires[i];
    if (receiver.fixed())
        return luminaire_irradiance_from(l, visibility, x, receiver.normal_at(0), rays);
    const Vec3 d = l.position - x;
    const double d2 = length_squared(d);
    if (!(d2 > 0)) return {0, 0, 0};
    const Vec3 w = d / std::sqrt(d2);
    const double kernel = std::max(0.0, intensity_per_lm(l, -w)) * receiver.weight(w) / d2;
    if (!(kernel > 0)) return {0, 0, 0};
    ++rays;
    if (!visibility.visible(x + receiver.offset_normal() * epsilon_, l.position)) return {0, 0, 0};
    return scaled(l.flux_lm, kernel);
}

Rgb LightSources::piece_part(const EmittingPiece& e, const Vec3& x, const Vec3& n,
                             const Visibility& visibility, SampleStream& rng, bool in_parts,
                             std::uint64_t& rays) const {
    const Piece& p = scene_.pieces[static_cast<std::size_t>(e.piece)];
    const Vec3 from = x + n * epsilon_;
    const auto seen_at = [&](const Vec3& y) {
        ++rays;
        return visibility.visible(from, y + p.normal * epsilon_) ? 1.0 : 0.0;
    };
    if (!in_parts && e.radius < kSmallPiece * length(e.centroid - x)) {
        // Small from x (a facet of a lamp's bulb across the room): the point kernel at one
        // uniform point, area-weighted, is unbiased and nearly as steady as the exact factor,
        // whose arc tangents held a tenth of a living room's solve.
        const double r1 = rng.next(), r2 = rng.next(), r3 = rng.next();
        const Vec3 y = point_on(e, r1, r2, r3);
        const Vec3 d = y - x;
        const double d2 = length_squared(d);
        const double cos_x = dot(n, d), cos_p = -dot(p.normal, d);
        if (!(cos_x > 0 && cos_p > 0 && d2 > 0)) return {0, 0, 0};
        return scaled(e.exitance, e.area * cos_x * cos_p / (kPi * d2 * d2) * seen_at(y));
    }
    const double factor = front_point_to_polygon_factor(x, n, p.vertices, p.normal);
    if (!(factor > 0)) return {0, 0, 0};
    if (!in_parts) {
        const double r1 = rng.next(), r2 = rng.next(), r3 = rng.next();
        return scaled(e.exitance, factor * seen_at(point_on(e, r1, r2, r3)));
    }
    // Each fan triangle split by its midpoints until its parts look small from x, each part's
    // exact factor times the visibility of one point drawn with the density of the light it
    // sends to x: the whole factor times the share of points seen would weight the points by
    // area, not by their light, which is biased where a shadow falls on one end of a large piece
    // (sensors beside the furnished office's monitors got 3–5 % too much or too little of a
    // ceiling panel's light, at any number of samples); within a part, uniform points still left
    // 0.4–0.8 % of the mean at points in a monitor's penumbra, against a brute-force integral.
    // A hidden piece stays exactly dark, a piece in full view exactly lit. A part still large
    // after the last split (x almost on the piece) draws uniformly.
    double sum = 0;
    const auto add_part = [&](const auto& self, const Vec3& a, const Vec3& b, const Vec3& c,
                              int depth) -> void {
        const std::array<Vec3, 3> t{a, b, c};
        const double part_factor = front_point_to_polygon_factor(x, n, t, p.normal);
        if (!(part_factor > 0)) return;
        const double edge2 =
            std::max({length_squared(b - a), length_squared(c - b), length_squared(a - c)});
        const Vec3 centre = (a + b + c) * (1.0 / 3);
        if (depth < kMaxPieceSplits && edge2 > kPartSize * kPartSize * length_squared(centre - x)) {
            const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
            self(self, a, ab, ca, depth + 1);
            self(self, ab, b, bc, depth + 1);
            self(self, ca, bc, c, depth + 1);
            self(self, ab, bc, ca, depth + 1);
            return;
        }
        const bool small = edge2 <= kPartSize * kPartSize * length_squared(centre - x);
        sum += part_factor * seen_at(small ? kernel_point(x, n, t, centre, p.normal, rng)
                                           : uniform_point(t, rng));
    };
    const std::vector<Vec3>& v = p.vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) add_part(add_part, v[0], v[k], v[k + 1], 0);
    return scaled(e.exitance, sum);
}

double LightSources::rough_light(std::size_t s, const Vec3& x, const Vec3& n) const {
    const std::size_t luminaires = scene_.luminaires.size();
    if (s < luminaires) {
        return source_power_[s] * direct_kernel_per_lm(scene_.luminaires[s], x, n);
    }
    const RoughPiece& e = rough_[s - luminaires];
    const Vec3 d = e.centroid - x;
    const double cos_x = dot(n, d), cos_p = -dot(e.normal, d);
    // Half a bulb faces away from any point: no division for those.
    if (!(cos_x > 0 && cos_p > 0)) return 0;
    const double d2 = std::max(dot(d, d), e.least_d2);
    return e.power * cos_x * cos_p / (kPi * d2 * d2);
}

Rgb LightSources::direct_at(const Vec3& x, const Vec3& n, const Visibility& visibility,
                            SampleStream& rng, std::uint64_t& rays) const {
    Rgb sum{0, 0, 0};
    const std::size_t count = source_power_.size();
    if (count <= kMaxNextEventSources) {
        for (std::size_t s = 0; s < count; ++s) add(sum, part(s, x, n, visibility, rng, rays));
        return sum;
    }
    const std::size_t luminaires = scene_.luminaires.size();
    if (luminaires + surface_runs_.size() <= kMaxNextEventSources &&
        pieces_.size() <= kMaxSurfaceDrawPieces) {
        for (std::size_t s = 0; s < luminaires; ++s) add(sum, part(s, x, n, visibility, rng, rays));
        for (const auto& run : surface_runs_)
            add(sum, surface_part(run, x, n, visibility, rng, rays));
        return sum;
    }
    const auto leaf = [&](std::size_t s) { return rough_light(s, x, n); };
    for (std::size_t k = 0; k < kNextEventDraws; ++k) {
        const double r = rng.next();
        std::size_t s = 0;
        double by_tree = 0;
        if (r >= kPowerShare) {
            if (!tree_.draw(x, n, (r - kPowerShare) / (1 - kPowerShare), leaf, s, by_tree)) {
                continue;
            }
        } else {
            s = draw_index(source_cdf_, r / kPowerShare);
            by_tree = tree_.probability(s, x, n, leaf);
        }
        const double p = ((1 - kPowerShare) * by_tree +
                          kPowerShare * std::max(source_power_[s], 0.0) / total_power_) *
                         kNextEventDraws;
        if (p > 0) add(sum, scaled(part(s, x, n, visibility, rng, rays), 1 / p));
    }
    return sum;
}

Rgb LightSources::surface_part(const SurfaceRun& run, const Vec3& x, const Vec3& n,
                               const Visibility& visibility, SampleStream& rng,
                               std::uint64_t& rays) const {
    const std::size_t first = scene_.luminaires.size() + run.first;
    const std::size_t size = run.end - run.first;
    if (size == 1) return part(first, x, n, visibility, rng, rays);
    const double power = run.power;
    if (!(power > 0)) return {0, 0, 0};
    // Piece k's light, drawn with probability p.
    const auto drawn = [&](std::size_t k, double p) {
        return p > 0 ? scaled(part(first + k, x, n, visibility, rng, rays), 1 / p) : Rgb{0, 0, 0};
    };
    if (run.far && run.far->far(x)) {
        double p = 0;
        const std::size_t k = run.far->draw(x, rng.next(), p);
        return drawn(k, p);
    }
    // Each piece's rough light once (a run has at most kMaxSurfaceDrawPieces).
    std::array<double, kMaxSurfaceDrawPieces> lights;
    double light = 0;
    for (std::size_t k = 0; k < size; ++k) {
        lights[k] = rough_light(first + k, x, n);
        light += lights[k];
    }
    // By rough light, mixed with a share by power so that every piece can be drawn.
    const double by_light = light > 0 ? (1 - kPowerShare) / light : 0.0;
    const double by_power = (light > 0 ? kPowerShare : 1.0) / power;
    const auto probability = [&](std::size_t k) {
        return by_light * lights[k] + by_power * std::max(source_power_[first + k], 0.0);
    };
    double r = rng.next();
    std::size_t k = 0;
    for (; k + 1 < size; ++k) {
        const double p = probability(k);
        if (r < p) break;
        r -= p;
    }
    return drawn(k, probability(k));
}

LightSources::SensorSources LightSources::sensor_sources(const Vec3& x,
                                                         const SensorReceiver& receiver,
                                                         const Visibility& visibility,
                                                         bool with_luminaires,
                                                         std::uint64_t& rays) const {
    SensorSources out;
    out.with_luminaires = with_luminaires;
    const std::size_t luminaires = scene_.luminaires.size();
    LightCut cut;
    if (receiver.fixed()) {
        const Vec3 from = x + receiver.normal_at(0) * epsilon_;
        const auto seen = [&](int node) {
            for (int k = 0; k < kSeenProbes; ++k) {
                double p = 0;
                const std::size_t s = tree_.draw_by_power(node, (k + 0.5) / kSeenProbes, p);
                ++rays;
                if (visibility.visible(from, source_point(s))) return true;
            }
            return false;
        };
        cut = tree_.cut(x, receiver.normal_at(0), kCutRelativeBound, kCutMaxNodes, kCutMaxSeenNodes,
                        seen);
    } else {
        for (std::size_t s = 0; s < luminaires + pieces_.size(); ++s) cut.sources.push_back(s);
    }
    for (const std::size_t s : cut.sources) {
        if (s >= luminaires) {
            out.pieces.push_back(s - luminaires);
        } else if (with_luminaires) {
            add(out.luminaires, luminaire_at(s, x, receiver, visibility, rays));
        }
    }
    out.clusters = cut.clusters;
    return out;
}

Rgb LightSources::sensor_set_light(const SensorSources& sources, const Vec3& x, const Vec3& n,
                                   const Visibility& visibility, SampleStream& rng,
                                   std::uint64_t& rays) const {
    Rgb sum{0, 0, 0};
    for (const std::size_t e : sources.pieces)
        add(sum, piece_part(pieces_[e], x, n, visibility, rng, true, rays));
    for (const int cluster : sources.clusters) {
        double p = 0;
        const std::size_t s = tree_.draw_by_power(cluster, rng.next(), p);
        if (s < scene_.luminaires.size() && !sources.with_luminaires) continue;
        if (p > 0) add(sum, scaled(part(s, x, n, visibility, rng, rays), 1 / p));
    }
    return sum;
}

}  // namespace radiant
