#include "checks/emitter_placement.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "checks/side_hit.h"
#include "checks/warning_text.h"
#include "geometry/cosine_direction.h"
#include "geometry/random.h"
#include "geometry/triangle_point.h"

namespace radiant {
namespace {

// Probes per emitting surface, fewer when there are very many surfaces, so that the check
// costs at most about kMaxProbes rays.
constexpr std::size_t kProbesPerSurface = 64;
constexpr std::size_t kMinProbesPerSurface = 8;
constexpr std::size_t kMaxProbes = std::size_t{1} << 18;
// Key of the probes' sample streams.
constexpr std::uint64_t kProbeStream = 0x67617073ull;

// An emitting surface's triangles of the ray tracer, with their cumulative area.
struct EmitterTriangles {
    std::vector<std::size_t> triangles;
    std::vector<double> cdf;
};

}  // namespace

std::vector<bool> check_emitter_placement(const CheckedScene& input, std::vector<Warning>& out,
                                          std::uint64_t& rays) {
    const PreparedScene& scene = input.prepared;
    std::vector<bool> behind(input.scene.surfaces.size(), false);
    std::map<int, EmitterTriangles> emitters;  // by engine surface, in order
    for (std::size_t i = 0; i < input.triangles.size(); ++i) {
        const Piece& p = scene.pieces[static_cast<std::size_t>(input.triangle_piece[i])];
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(p.material)];
        if (!(luminance(m.exitance_lm_m2) > 0)) continue;
        const Triangle& t = input.triangles[i];
        const double area = 0.5 * length(cross(t.b - t.a, t.c - t.a));
        if (!(area > 0)) continue;
        EmitterTriangles& e = emitters[p.surface];
        e.triangles.push_back(i);
        e.cdf.push_back((e.cdf.empty() ? 0.0 : e.cdf.back()) + area);
    }
    if (emitters.empty()) return behind;
    const Box model = model_bounds(scene);
    const auto holds_the_model = [&](int surface) {
        Box bounds;
        for (const Piece& p : scene.pieces) {
            if (p.surface == surface) bounds.add(p.vertices);
        }
        return is_room_sized(bounds.size(), model);
    };
    const std::size_t probes =
        std::clamp(kMaxProbes / emitters.size(), kMinProbesPerSurface, kProbesPerSurface);
    const double eps = input.visibility.epsilon();
    for (const auto& [surface, e] : emitters) {
        const auto s = static_cast<std::size_t>(surface);
        const double gap = kNearGapShare * std::sqrt(scene.surface_area_m2[s]);
        std::size_t near = 0, black = 0, escaped = 0;
        std::vector<double> depths;  // how far in front the near hits' surfaces lie
        std::map<int, std::size_t> met, black_met;
        for (std::size_t k = 0; k < probes; ++k) {
            SampleStream rng(input.seed, kProbeStream, s, k);
            const auto at = std::upper_bound(e.cdf.begin(), e.cdf.end(), rng.next() * e.cdf.back());
            const std::size_t i = e.triangles[std::min(static_cast<std::size_t>(at - e.cdf.begin()),
                                                       e.cdf.size() - 1)];
            const Triangle& t = input.triangles[i];
            const Vec3 n = scene.pieces[static_cast<std::size_t>(input.triangle_piece[i])].normal;
            const double r1 = rng.next(), r2 = rng.next();
            const Vec3 x = uniform_triangle_point(t.a, t.b, t.c, r1, r2);
            const Vec3 d = cosine_direction(n, rng.next(), rng.next());
            ++rays;
            const SideHit hit = side_hit(input, x + n * eps, d);
            if (hit.escaped()) {
                ++escaped;
                continue;
            }
            // Its own other side (a furnace's thin slab, a room that glows) is what it encloses.
            const int other = scene.pieces[static_cast<std::size_t>(hit.piece)].surface;
            if (other == surface) continue;
            if (hit.black) {
                ++black;
                ++black_met[other];
            }
            if (!(hit.t < gap)) continue;
            ++near;
            depths.push_back(hit.t * dot(d, n));
            ++met[other];
        }
        const auto most_met = [](const std::map<int, std::size_t>& counts) {
            return std::max_element(
                       counts.begin(), counts.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; })
                ->first;
        };
        const double black_share = static_cast<double>(black) / static_cast<double>(probes);
        // A surface that holds most of the model is the room, wound or faced the wrong way:
        // back_face_light says so.
        if (escaped == 0 && black_share >= kBehindShare && !holds_the_model(most_met(black_met))) {
            behind[s] = true;
            out.push_back(
                {"emitter_behind_surface",
                 surface_label(input.scene, s) + " sends " + percent(black_share) +
                     " of its light onto the black back of " +
                     surface_label(input.scene, static_cast<std::size_t>(most_met(black_met))) +
                     ", where it is lost: does it lie inside a closed object or behind that "
                     "surface (move it out, an LED strip onto its shelf, not into it), or is "
                     "that surface wound the wrong way?",
                 surface_pointer(input.scene, s)});
            continue;
        }
        const double share = static_cast<double>(near) / static_cast<double>(probes);
        if (share < kTrappedShare) continue;
        std::nth_element(depths.begin(), depths.begin() + static_cast<long>(depths.size() / 2),
                         depths.end());
        out.push_back({"emitter_faces_surface",
                       surface_label(input.scene, s) + " emits toward " +
                           surface_label(input.scene, static_cast<std::size_t>(most_met(met))) +
                           " " + length_text(depths[depths.size() / 2]) +
                           " in front of it: " + percent(share) +
                           " of its light meets a surface within " + length_text(gap) +
                           ", and little of it gets out; if it should face the other way, "
                           "reverse its vertices (a polygon's front is the side from which they "
                           "run counter-clockwise)",
                       surface_pointer(input.scene, s)});
    }
    return behind;
}

}  // namespace radiant
