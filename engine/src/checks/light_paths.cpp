#include "checks/light_paths.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "checks/side_hit.h"
#include "formfactor/luminaire_light.h"
#include "geometry/cosine_direction.h"
#include "geometry/random.h"
#include "parallel/fork_join.h"

namespace radiant {
namespace {

// Each luminaire casts its share of kLightPaths, within these bounds: enough directions to see
// what surrounds it, and no more than its share needs. With very many luminaires the lower bound
// falls, so that the directions stay near kMaxLuminaireDirections in all.
constexpr std::size_t kMinDirectionsPerLuminaire = 64;
constexpr std::size_t kMaxDirectionsPerLuminaire = 1024;
constexpr std::size_t kMaxLuminaireDirections = 1u << 18;
// Emitting surfaces, when there are any, get at least this many paths.
constexpr std::size_t kMinEmitterPaths = 256;
// A path in a furnace of reflectance 0.99 bounces a hundred times on average; a few so long
// change no share that matters, so they end here as absorbed.
constexpr int kMaxBounces = 64;
constexpr std::size_t kChunk = 256;
// Key of the paths' sample streams.
constexpr std::uint64_t kPathStream = 0x6c6f7373ull;
// near_distance() of a small model, relative to its diagonal.
constexpr double kNearDiagonalShare = 0.05;
constexpr double kNearMeters = 0.1;

struct PathStart {
    Vec3 origin, direction;
    double flux_lm = 0;
    int luminaire = -1;  ///< −1: an emitting surface
    int emitter = -1;    ///< an emitting surface's engine surface; −1: a luminaire
    /// A luminaire's: what it would send along `direction` aimed the other way.
    double reversed_lm = 0;
};

struct Frame {
    Vec3 t, b, n;
};

Frame frame_about(const Vec3& n) {
    const Vec3 t =
        normalized(std::abs(n.x) < 0.9 ? cross(n, Vec3{1, 0, 0}) : cross(n, Vec3{0, 1, 0}));
    return {t, cross(n, t), n};
}

// Directions over the whole sphere with the lattice's pole on the aim, weighted by the
// luminaire's intensity: a quadrature of its flux. Directions without light stay (they show
// what surrounds the luminaire). A beam so narrow that no direction sees it goes along the aim.
void luminaire_starts(const PreparedLuminaire& l, int index, std::size_t count,
                      std::vector<PathStart>& out) {
    const double flux = luminance(l.flux_lm);
    const Frame f = frame_about(l.aim);
    const std::size_t first = out.size();
    double total = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 s = sphere_direction(k, count);
        const Vec3 u = f.t * s.x + f.b * s.y + f.n * s.z;
        const double intensity = std::max(0.0, intensity_per_lm(l, u));
        out.push_back(
            {l.position, u, intensity, index, -1, std::max(0.0, intensity_per_lm(l, -u))});
        total += intensity;
    }
    if (!(total > 0)) {
        for (std::size_t k = first; k < out.size(); ++k) out[k].flux_lm = out[k].reversed_lm = 0;
        if (flux > 0) out.push_back({l.position, l.aim, flux, index});
        return;
    }
    for (std::size_t k = first; k < out.size(); ++k) {
        out[k].flux_lm *= flux / total;
        out[k].reversed_lm *= flux / total;
    }
}

// Points drawn on the emitting triangles by power, leaving in cosine-distributed directions.
void emitter_starts(const CheckedScene& input, double power_lm, std::size_t count,
                    std::uint64_t seed, std::vector<PathStart>& out) {
    const PreparedScene& scene = input.prepared;
    std::vector<std::size_t> triangles;
    std::vector<double> cdf;
    double sum = 0;
    for (std::size_t i = 0; i < input.triangles.size(); ++i) {
        const Piece& p = scene.pieces[static_cast<std::size_t>(input.triangle_piece[i])];
        const double exitance =
            luminance(scene.materials[static_cast<std::size_t>(p.material)].exitance_lm_m2);
        if (!(exitance > 0)) continue;
        const Triangle& t = input.triangles[i];
        sum += exitance * 0.5 * length(cross(t.b - t.a, t.c - t.a));
        triangles.push_back(i);
        cdf.push_back(sum);
    }
    if (!(sum > 0)) return;
    const double eps = input.visibility.epsilon();
    for (std::size_t k = 0; k < count; ++k) {
        SampleStream rng(seed, kPathStream, ~std::uint64_t{0} - k);
        const auto at = std::upper_bound(cdf.begin(), cdf.end(), rng.next() * sum);
        const std::size_t i =
            triangles[std::min(static_cast<std::size_t>(at - cdf.begin()), cdf.size() - 1)];
        const Triangle& t = input.triangles[i];
        const Piece& piece = scene.pieces[static_cast<std::size_t>(input.triangle_piece[i])];
        const Vec3 n = piece.normal;
        const double s = std::sqrt(rng.next()), r = rng.next();
        const Vec3 x = t.a * (1 - s) + t.b * (s * (1 - r)) + t.c * (s * r);
        out.push_back({x + n * eps, cosine_direction(n, rng.next(), rng.next()),
                       power_lm / static_cast<double>(count), -1, piece.surface});
    }
}

std::vector<PathStart> path_starts(const CheckedScene& input, double& emitted_lm) {
    const PreparedScene& scene = input.prepared;
    const EmittedLight emitted = emitted_light(scene);
    const double emitter_lm = emitted.surfaces_lm;
    emitted_lm = emitted.total_lm();
    std::vector<PathStart> starts;
    if (!(emitted_lm > 0)) return starts;
    const std::size_t lowest = std::clamp<std::size_t>(
        kMaxLuminaireDirections / std::max<std::size_t>(scene.luminaires.size(), 1), 4,
        kMinDirectionsPerLuminaire);
    for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
        const double share = luminance(scene.luminaires[i].flux_lm) / emitted_lm;
        const auto wanted = static_cast<std::size_t>(std::ceil(share * kLightPaths));
        luminaire_starts(scene.luminaires[i], static_cast<int>(i),
                         std::clamp(wanted, lowest, kMaxDirectionsPerLuminaire), starts);
    }
    if (emitter_lm > 0) {
        const auto wanted =
            static_cast<std::size_t>(std::ceil(emitter_lm / emitted_lm * kLightPaths));
        emitter_starts(input, emitter_lm, std::max(wanted, kMinEmitterPaths), input.seed, starts);
    }
    return starts;
}

struct PathEnd {
    SideHit first;
    int lost_surface = -1;  ///< the surface whose black back took the path
    bool escaped = false;
    /// A luminaire's: the surface it lies on whose front it sends the path into, and through:
    /// the light is lost.
    int touched = -1;
};

// The surface whose front a luminaire at `origin` lies on and sends light along `direction`
// into, and through (−1: none), given the ray's first hit beyond the stretch side_hit() skips.
// The probe starts kTouchDistance behind the luminaire and ends as far beyond it; a first hit
// on a front within that reach is the surface met a hair in front, which reflects the light.
int touched_surface(const CheckedScene& input, const Vec3& origin, const Vec3& direction,
                    const SideHit& first) {
    const double reach = std::max(kTouchDistance, 16 * input.visibility.epsilon());
    if (!first.escaped() && !first.black && first.t <= reach) return -1;
    const RayHit hit = input.visibility.intersect(origin - direction * reach, direction, 2 * reach);
    if (hit.triangle < 0) return -1;
    const Piece& piece = input.prepared.pieces[static_cast<std::size_t>(
        input.triangle_piece[static_cast<std::size_t>(hit.triangle)])];
    return dot(direction, piece.normal) < 0 ? piece.surface : -1;
}

PathEnd trace(const CheckedScene& input, const PathStart& start, std::size_t index,
              std::uint64_t& rays) {
    const PreparedScene& scene = input.prepared;
    SampleStream rng(input.seed, kPathStream, index);
    Vec3 origin = start.origin, direction = start.direction;
    PathEnd end;
    for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
        ++rays;
        const SideHit hit = side_hit(input, origin, direction);
        if (bounce == 0) {
            end.first = hit;
            if (start.luminaire >= 0 && start.flux_lm > 0) {
                ++rays;
                end.touched = touched_surface(input, origin, direction, hit);
            }
        }
        if (!(start.flux_lm > 0)) break;  // a direction without light: only its first hit counts
        if (hit.escaped()) {
            end.escaped = true;
            break;
        }
        const Piece& piece = scene.pieces[static_cast<std::size_t>(hit.piece)];
        if (hit.black) {
            end.lost_surface = piece.surface;
            break;
        }
        const double rho =
            luminance(scene.materials[static_cast<std::size_t>(piece.material)].reflectance);
        if (rng.next() >= rho) break;
        const Vec3 n = hit.back ? -piece.normal : piece.normal;
        origin = origin + direction * hit.t + n * input.visibility.epsilon();
        direction = cosine_direction(n, rng.next(), rng.next());
    }
    return end;
}

// One luminaire's light by the surface it meets: which surface takes most.
struct SurfaceShares {
    double lm = 0;
    std::map<int, double> by_surface;
    void add(int surface, double flux_lm) {
        lm += flux_lm;
        by_surface[surface] += flux_lm;
    }
    int main() const {
        const auto most =
            std::max_element(by_surface.begin(), by_surface.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
        return most == by_surface.end() ? -1 : most->first;
    }
};

}  // namespace

double near_distance(const PreparedScene& prepared) {
    return std::min(kNearMeters, kNearDiagonalShare * prepared.diagonal_m);
}

LightPaths trace_light_paths(const CheckedScene& input, std::uint64_t& rays) {
    LightPaths out;
    const PreparedScene& scene = input.prepared;
    out.luminaires.resize(scene.luminaires.size());
    const std::vector<PathStart> starts = path_starts(input, out.emitted_lm);
    if (starts.empty()) return out;

    std::vector<PathEnd> ends(starts.size());
    const std::size_t chunks = (starts.size() + kChunk - 1) / kChunk;
    std::vector<std::uint64_t> chunk_rays(chunks, 0);
    parallel_for(0, chunks, [&](std::size_t c) {
        for (std::size_t i = c * kChunk; i < std::min(starts.size(), (c + 1) * kChunk); ++i)
            ends[i] = trace(input, starts[i], i, chunk_rays[c]);
    });
    for (const std::uint64_t r : chunk_rays) rays += r;

    // In path order: the sums do not depend on which thread traced what.
    struct Sums {
        double lm = 0;
        std::size_t directions = 0;
        SurfaceShares black, touching, near;
        double near_reversed_lm = 0;
    };
    std::vector<Sums> sums(scene.luminaires.size());
    const double near = near_distance(scene);
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const PathStart& s = starts[i];
        const PathEnd& e = ends[i];
        if (e.escaped) out.escaped_lm += s.flux_lm;
        if (e.lost_surface >= 0)
            out.lost.push_back({e.lost_surface, s.luminaire, s.emitter, s.flux_lm});
        if (s.luminaire < 0) continue;
        const auto l = static_cast<std::size_t>(s.luminaire);
        Sums& sum = sums[l];
        sum.lm += s.flux_lm;
        ++sum.directions;
        LuminaireFirstHits& first = out.luminaires[l];
        first.directions_escaped += e.first.escaped() ? 1 : 0;
        first.directions_black += e.first.black ? 1 : 0;
        if (e.touched >= 0) sum.touching.add(e.touched, s.flux_lm);
        if (e.first.escaped()) {
            first.escaped += s.flux_lm;
            continue;
        }
        const int surface = scene.pieces[static_cast<std::size_t>(e.first.piece)].surface;
        if (e.first.black) sum.black.add(surface, s.flux_lm);
        if (!e.first.black && e.first.t < near) {
            sum.near.add(surface, s.flux_lm);
            sum.near_reversed_lm += s.reversed_lm;
        }
    }
    for (std::size_t l = 0; l < scene.luminaires.size(); ++l) {
        LuminaireFirstHits& first = out.luminaires[l];
        const Sums& sum = sums[l];
        first.directions_escaped /= static_cast<double>(std::max<std::size_t>(sum.directions, 1));
        first.directions_black /= static_cast<double>(std::max<std::size_t>(sum.directions, 1));
        if (!(sum.lm > 0)) continue;
        first.escaped /= sum.lm;
        first.black_back = sum.black.lm / sum.lm;
        first.main_surface = sum.black.main();
        if (first.main_surface >= 0)
            first.main_share = sum.black.by_surface.at(first.main_surface) / sum.lm;
        first.touching = sum.touching.lm / sum.lm;
        first.touching_surface = sum.touching.main();
        first.near = sum.near.lm / sum.lm;
        first.near_reversed = sum.near_reversed_lm / sum.lm;
        first.near_surface = sum.near.main();
    }
    return out;
}

std::vector<double> black_back_shares(const LightPaths& paths, std::size_t surfaces,
                                      const std::vector<bool>& excluded,
                                      const std::vector<bool>& excluded_emitters) {
    const auto marked = [](const std::vector<bool>& flags, int i) {
        return i >= 0 && static_cast<std::size_t>(i) < flags.size() &&
               flags[static_cast<std::size_t>(i)];
    };
    std::vector<double> share(surfaces, 0.0);
    if (!(paths.emitted_lm > 0)) return share;
    for (const LostPath& p : paths.lost) {
        const bool skip = marked(excluded, p.luminaire) || marked(excluded_emitters, p.emitter);
        if (!skip) share[static_cast<std::size_t>(p.surface)] += p.flux_lm / paths.emitted_lm;
    }
    return share;
}

}  // namespace radiant
