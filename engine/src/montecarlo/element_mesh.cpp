#include "montecarlo/element_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "geometry/polygon_split.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "radiant/box.h"

namespace radiant {
namespace {

// Cuts `t` at the midpoint m of its longest edge a→b into (a, m, c) and (m, b, c), unless every
// edge is at most h (then false).
bool halve(const Triangle& t, double h, Triangle& first, Triangle& second) {
    const double ab = length_squared(t.b - t.a), bc = length_squared(t.c - t.b),
                 ca = length_squared(t.a - t.c);
    const double longest = std::max({ab, bc, ca});
    if (longest <= h * h) return false;
    Triangle r = t;
    if (longest == bc) r = {t.b, t.c, t.a};
    if (longest == ca && longest != bc) r = {t.c, t.a, t.b};
    const Vec3 m = 0.5 * (r.a + r.b);
    first = {r.a, m, r.c};
    second = {m, r.b, r.c};
    return true;
}

// A compact light source: a luminaire, or an emitting surface at most half the reach across (a
// lamp's bulb, a downlight's disc), as a ball; a thin one (a strip light) is a chain of them
// (compact_emitters). One that shines only to one side of a plane (a downlight's table dark
// above the horizontal, a flat emitter) lights nothing behind it: the ceiling round a downlight
// is lit only by what the room reflects, and is not cut finer.
struct CompactLight {
    Vec3 centre;
    double radius = 0;
    Vec3 front{0, 0, 0};  ///< unit; zero: it shines all round
    double plane = 0;     ///< it lights only points x with dot(x, front) > plane
};

// The light of `l` reaches some point of the convex hull of `corners`.
bool lights_any(const CompactLight& l, const Vec3* corners, std::size_t n, double eps) {
    if (l.front == Vec3{0, 0, 0}) return true;
    for (std::size_t k = 0; k < n; ++k)
        if (dot(corners[k], l.front) > l.plane + eps) return true;
    return false;
}

// A luminaire as a light: photometric tables without light past the horizontal, and lambertian
// ones, shine only in front of the plane through it across its aim.
CompactLight luminaire_light(const PreparedLuminaire& l) {
    CompactLight out{l.position, 0};
    const bool one_sided = l.distribution == Distribution::lambertian ||
                           (l.distribution == Distribution::photometric &&
                            l.table->widest_lit_gamma_rad() <= std::numbers::pi / 2);
    if (one_sided) {
        out.front = l.aim;
        out.plane = dot(l.position, l.aim);
    }
    return out;
}

// The longest edge each triangle may keep (ElementSizing). Lights within a quarter of the reach
// of each other count as one (so that a swarm of tiny emitters costs no more than a lamp); those
// within reach of a piece are found once, on a grid of cells as wide as the reach, and each of
// its triangles is sized by the nearest of them.
class EdgeLimit {
public:
    EdgeLimit(const PreparedScene& scene, const ElementSizing& sizing)
        : h_(std::max(sizing.max_edge_m, 1e-9)), reach_(std::max(sizing.light_reach_m, 0.0)) {
        if (!(reach_ > 0)) return;
        std::vector<CompactLight> found;
        for (const PreparedLuminaire& l : scene.luminaires) found.push_back(luminaire_light(l));
        for (const CompactLight& l : compact_emitters(scene, reach_ / 4)) found.push_back(l);
        // Merged by cells a quarter of the reach wide: each cell's lights as one ball.
        std::map<std::array<double, 3>, std::vector<CompactLight>> merged;
        for (const CompactLight& l : found) merged[cell_of(l.centre, reach_ / 4)].push_back(l);
        for (const auto& [cell, members] : merged) {
            Vec3 centre{0, 0, 0};
            for (const CompactLight& l : members) centre = centre + l.centre;
            centre = centre / static_cast<double>(members.size());
            CompactLight cell_light{centre, 0, members.front().front, members.front().plane};
            for (const CompactLight& l : members) {
                cell_light.radius =
                    std::max(cell_light.radius, length(l.centre - centre) + l.radius);
                // Facing one way, they light the union of their half-spaces.
                if (!(dot(l.front, cell_light.front) > 1 - 1e-9)) cell_light.front = {0, 0, 0};
                cell_light.plane = std::min(cell_light.plane, l.plane);
            }
            lights_.push_back(cell_light);
            cells_[key(cell_of(centre, reach_))].push_back(lights_.back());
        }
    }

    double max_edge() const { return h_; }

    // The lights within reach of the bounds of `v`.
    std::vector<CompactLight> near(const std::vector<Vec3>& v) const {
        std::vector<CompactLight> out;
        if (lights_.empty()) return out;
        const Box bounds = bounding_box(v);
        // A light's ball may reach a cell beside its centre's.
        const double margin = reach_ * 1.5;
        const Vec3 r{margin, margin, margin};
        const std::array<double, 3> a = cell_of(bounds.lo - r, reach_);
        const std::array<double, 3> b = cell_of(bounds.hi + r, reach_);
        const double cells = (b[0] - a[0] + 1) * (b[1] - a[1] + 1) * (b[2] - a[2] + 1);
        const auto within = [&](const CompactLight& l) {
            return distance(bounds, bounding_box({&l.centre, 1})) - l.radius <= reach_ &&
                   lights_any(l, v.data(), v.size(), eps_);
        };
        // A piece wider than the lights are many (a floor slab) scans them all.
        if (cells > static_cast<double>(lights_.size())) {
            for (const CompactLight& l : lights_)
                if (within(l)) out.push_back(l);
            return out;
        }
        // Counted by offsets: far from the origin a cell's coordinate plus one may round to itself.
        const auto count = [&](int axis) { return static_cast<int>(b[axis] - a[axis]) + 1; };
        for (int x = 0; x < count(0); ++x) {
            for (int y = 0; y < count(1); ++y) {
                for (int z = 0; z < count(2); ++z) {
                    const auto list = cells_.find(key({a[0] + x, a[1] + y, a[2] + z}));
                    if (list == cells_.end()) continue;
                    for (const CompactLight& l : list->second)
                        if (within(l)) out.push_back(l);
                }
            }
        }
        return out;
    }

    // The edge `t` may keep, with `lights` those near its piece.
    double of(const Triangle& t, const std::vector<CompactLight>& lights) const {
        if (lights.empty()) return h_;
        const Ball b = ball(t);
        const std::array<Vec3, 3> corners{t.a, t.b, t.c};
        double nearest = reach_;
        for (const CompactLight& l : lights) {
            if (lights_any(l, corners.data(), corners.size(), eps_))
                nearest = std::min(nearest, length(l.centre - b.centre) - b.radius - l.radius);
        }
        return h_ * std::clamp(nearest / reach_, ElementSizing::kFinest, 1.0);
    }

    // A list of lights this long is narrowed to those within reach of each triangle as it is
    // cut: a hall's ceiling under 20 000 downlights took 35 s to cut, each of its triangles
    // weighing every one of them.
    static constexpr std::size_t kShortList = 16;

    // The lights of `lights` within reach of `t` or of any triangle cut from it: its pieces'
    // balls lie within three times its own round its centroid.
    std::vector<CompactLight> near(const Triangle& t,
                                   const std::vector<CompactLight>& lights) const {
        const Ball b = ball(t);
        const std::array<Vec3, 3> corners{t.a, t.b, t.c};
        std::vector<CompactLight> out;
        for (const CompactLight& l : lights) {
            if (length(l.centre - b.centre) - 3 * b.radius - l.radius <= reach_ &&
                lights_any(l, corners.data(), corners.size(), eps_))
                out.push_back(l);
        }
        return out;
    }

private:
    struct Ball {
        Vec3 centre;
        double radius = 0;
    };
    // A ball round `t`: its centroid, out to its farthest corner.
    static Ball ball(const Triangle& t) {
        const Vec3 centre = (t.a + t.b + t.c) / 3.0;
        return {centre,
                std::sqrt(std::max({length_squared(t.a - centre), length_squared(t.b - centre),
                                    length_squared(t.c - centre)}))};
    }
    // Each emitting surface whose bounding ball's radius is at most `widest`, as that ball; one
    // longer but at most `widest` thick about its length (a strip light under a cabinet), as a
    // chain of balls along it. A flat one (every piece in one plane, facing one way) shines only
    // from its front.
    static std::vector<CompactLight> compact_emitters(const PreparedScene& scene, double widest) {
        struct Emitter {
            Box box;  // empty: the surface emits nothing
            std::vector<const Piece*> pieces;
            Vec3 front{0, 0, 0};
            double lowest = 0, highest = 0;  // its pieces' extent along `front`
            bool flat = true;
        };
        std::vector<Emitter> emitting(scene.surface_names.size());
        for (const Piece& piece : scene.pieces) {
            if (!scene.materials[static_cast<std::size_t>(piece.material)].emits()) continue;
            Emitter& e = emitting[static_cast<std::size_t>(piece.surface)];
            if (e.box.empty()) {
                e.front = piece.normal;
                e.lowest = e.highest = dot(piece.vertices.front(), piece.normal);
            }
            e.box.add(piece.vertices);
            e.pieces.push_back(&piece);
            e.flat = e.flat && dot(piece.normal, e.front) > 1 - 1e-9;
            for (const Vec3& v : piece.vertices) {
                e.lowest = std::min(e.lowest, dot(v, e.front));
                e.highest = std::max(e.highest, dot(v, e.front));
            }
        }
        std::vector<CompactLight> out;
        std::size_t chained = 0;  // balls in chains so far
        for (const Emitter& e : emitting) {
            if (e.box.empty()) continue;
            const std::size_t first = out.size();
            const double radius = 0.5 * length(e.box.size());
            if (radius <= widest) {
                out.push_back({e.box.centre(), radius});
            } else {
                chain_of_balls(e.pieces, e.box.centre(), widest, chained, out);
            }
            if (!e.flat || e.highest - e.lowest > 1e-9 * (1 + radius)) continue;
            for (std::size_t k = first; k < out.size(); ++k) {
                out[k].front = e.front;
                out[k].plane = e.lowest;
            }
        }
        return out;
    }
    // Where every vertex of the pieces lies within `widest` of the segment between the two
    // farthest apart (roughly: the one farthest from `centre`, and the one farthest from that),
    // balls along that segment at most `widest` apart, each reaching as far from it as the
    // farthest vertex and half the spacing beyond; else nothing. Nothing either where the
    // chains would hold more than kMostChainedBalls in all (`chained` so far): a strip
    // kilometres long beside rooms metres wide would make millions, a hostile scene billions.
    static constexpr std::size_t kMostChainedBalls = std::size_t{1} << 16;
    static void chain_of_balls(const std::vector<const Piece*>& pieces, const Vec3& centre,
                               double widest, std::size_t& chained,
                               std::vector<CompactLight>& out) {
        const auto farthest_from = [&](const Vec3& x) {
            Vec3 best = x;
            for (const Piece* p : pieces)
                for (const Vec3& v : p->vertices)
                    if (length_squared(v - x) > length_squared(best - x)) best = v;
            return best;
        };
        const Vec3 a = farthest_from(centre);
        const Vec3 b = farthest_from(a);
        const double span = length(b - a);
        if (!(span > 0)) return;
        const Vec3 along = (b - a) / span;
        double thickness = 0;
        for (const Piece* p : pieces) {
            for (const Vec3& v : p->vertices) {
                const double t = std::clamp(dot(v - a, along), 0.0, span);
                thickness = std::max(thickness, length(v - (a + along * t)));
            }
        }
        const double balls = std::ceil(span / widest);
        if (thickness > widest || !(balls <= static_cast<double>(kMostChainedBalls - chained)))
            return;
        chained += static_cast<std::size_t>(balls);
        const double step = span / balls;
        for (double k = 0; k < balls; ++k)
            out.push_back({a + along * ((k + 0.5) * step), thickness + step / 2});
    }
    static std::array<double, 3> cell_of(const Vec3& p, double size) {
        return {std::floor(p.x / size), std::floor(p.y / size), std::floor(p.z / size)};
    }
    static std::size_t key(const std::array<double, 3>& c) {
        // Cells whose keys collide share a list: `near` still keeps only what is within reach.
        const std::hash<double> hash;
        return hash(c[0]) ^ (hash(c[1]) * 0x9e3779b97f4a7c15ULL) ^
               (hash(c[2]) * 0xff51afd7ed558ccdULL);
    }

    double h_, reach_;
    double eps_ = 1e-7 * reach_;  // what counts as on a light's plane
    std::vector<CompactLight> lights_;
    std::unordered_map<std::size_t, std::vector<CompactLight>> cells_;
};

// Collects elements (or only counts them, without `out`).
struct Elements {
    std::vector<MeshElement>* out;
    std::size_t count = 0;

    // Returns the new element's index, or −1 when only counting.
    int add(const Triangle& t, const MeshElement& proto) {
        ++count;
        if (!out) return -1;
        MeshElement e = proto;
        e.triangle = t;
        e.area_m2 = 0.5 * length(cross(t.b - t.a, t.c - t.a));
        out->push_back(e);
        return static_cast<int>(out->size()) - 1;
    }

    void pair(int first, int second) {
        if (first < 0 || second < 0) return;
        (*out)[static_cast<std::size_t>(first)].sibling = second;
        (*out)[static_cast<std::size_t>(second)].sibling = first;
    }

    // Bisects `t` across its longest edge until every edge is within `limit` (with `lights`
    // near its piece). Returns the element's index when `t` needed no split, else −1.
    int bisect(const Triangle& t, const MeshElement& proto, const EdgeLimit& limit,
               const std::vector<CompactLight>& lights) {
        if (lights.size() > EdgeLimit::kShortList) {
            const std::vector<CompactLight> nearer = limit.near(t, lights);
            if (nearer.size() < lights.size()) return bisect(t, proto, limit, nearer);
        }
        Triangle first, second;
        if (!halve(t, limit.of(t, lights), first, second)) return add(t, proto);
        const int a = bisect(first, proto, limit, lights);
        pair(a, bisect(second, proto, limit, lights));
        return -1;
    }
};

// How a narrow piece is cut into a strip of cells along its longest edge (see strip_of).
struct Strip {
    Vec3 along;        ///< unit, the longest edge's direction
    double start = 0;  ///< the piece's least extent along it
    double step = 0;   ///< the cells' length
    std::size_t cells = 0;
    double eps = 0;  ///< what counts as on a cut
};

// The strip of a convex piece narrower than h/√2 across its longest edge: cells h/2 long along
// that edge (about as long as bisecting its triangles makes them), whose two triangles fit and
// are each other's coarser half; none for a wider piece. Bisecting a strip's triangles instead
// triples their number per halving of their length (a rack's beam, 24 m by 12 cm: 1 458 elements
// a face at h = 0.71 m, where its strip has 138).
std::optional<Strip> strip_of(const Piece& piece, double h) {
    const std::vector<Vec3>& v = piece.vertices;
    Strip strip;
    double longest = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const Vec3 edge = v[(k + 1) % v.size()] - v[k];
        if (length(edge) > longest) {
            longest = length(edge);
            strip.along = edge / longest;
        }
    }
    const Vec3 across = cross(piece.normal, strip.along);
    double u0 = dot(v[0], strip.along), u1 = u0, v0 = dot(v[0], across), v1 = v0;
    for (const Vec3& p : v) {
        u0 = std::min(u0, dot(p, strip.along));
        u1 = std::max(u1, dot(p, strip.along));
        v0 = std::min(v0, dot(p, across));
        v1 = std::max(v1, dot(p, across));
    }
    // A little under h, so that rounding never leaves a diagonal just over it.
    const double fit = h * (1 - 1e-6);
    if (!(longest > 0) || v1 - v0 > fit / std::sqrt(2.0)) return std::nullopt;
    strip.start = u0;
    strip.cells = static_cast<std::size_t>(std::max(1.0, std::ceil((u1 - u0) / (fit / 2))));
    strip.step = (u1 - u0) / static_cast<double>(strip.cells);
    strip.eps = 1e-9 * longest;
    return strip;
}

// Calls `visit` with each cell of the strip over convex polygon `v`, in order along it, one at a
// time (a count holds no more than one).
template <class Visit>
void for_each_cell(const std::vector<Vec3>& v, const Strip& strip, const Visit& visit) {
    std::vector<Vec3> rest = v;
    for (std::size_t k = 1; k <= strip.cells && !rest.empty(); ++k) {
        std::vector<Vec3> cell;
        if (k < strip.cells) {
            const Vec3 cut = strip.along * (strip.start + strip.step * static_cast<double>(k));
            auto [beyond, before] = split_by_plane(rest, cut, strip.along, strip.eps);
            cell = std::move(before);
            rest = std::move(beyond);
        } else {
            cell = std::move(rest);
            rest.clear();
        }
        cell = simplify_polygon(cell, strip.eps);
        if (cell.size() >= 3) visit(cell);
    }
}

// How many elements bisecting `t` makes, counted up to just past `most`.
std::size_t bisection_count(const Triangle& t, const EdgeLimit& limit,
                            const std::vector<CompactLight>& lights, std::size_t most) {
    if (lights.size() > EdgeLimit::kShortList) {
        const std::vector<CompactLight> nearer = limit.near(t, lights);
        if (nearer.size() < lights.size()) return bisection_count(t, limit, nearer, most);
    }
    Triangle first, second;
    if (!halve(t, limit.of(t, lights), first, second)) return 1;
    const std::size_t a = bisection_count(first, limit, lights, most);
    return a > most ? a : a + bisection_count(second, limit, lights, most - a);
}

// A strip's cells replace bisection only where bisection makes more than this many times their
// elements: elsewhere (a pendant's 1.6 m by 26 cm housing, 18 elements against 12) the two
// meshes are alike and the estimates were measured on bisection's.
constexpr std::size_t kStripGain = 2;

// One piece's elements: a narrow piece's strip of cells where bisection would make slivers by
// the score, else its fan of triangles bisected to fit within `limit`.
void split_piece(const Piece& piece, int index, const EdgeLimit& limit, Elements& elements) {
    const double h = limit.max_edge();
    const std::vector<CompactLight> lights = limit.near(piece.vertices);
    MeshElement proto;
    proto.normal = piece.normal;
    proto.piece = index;
    proto.surface = piece.surface;
    proto.material = piece.material;
    const std::vector<Vec3>& v = piece.vertices;
    bool fits = true;
    for (std::size_t k = 0; k < v.size() && fits; ++k)
        fits = length(v[(k + 1) % v.size()] - v[k]) <= h;
    const std::optional<Strip> strip = fits ? std::nullopt : strip_of(piece, h);
    // A strip's cells are quadrilaterals but for its ends: about two elements each.
    const std::size_t most = strip ? kStripGain * 2 * strip->cells : 0;
    std::size_t bisected = 0;
    for (std::size_t k = 1; k + 1 < v.size() && strip && bisected <= most; ++k)
        bisected += bisection_count({v[0], v[k], v[k + 1]}, limit, lights, most - bisected);
    if (!strip || bisected <= most) {
        // Convex pieces: a fan from the first vertex.
        for (std::size_t k = 1; k + 1 < v.size(); ++k)
            elements.bisect({v[0], v[k], v[k + 1]}, proto, limit, lights);
        return;
    }
    for_each_cell(v, *strip, [&](const std::vector<Vec3>& cell) {
        std::vector<int> made;
        for (std::size_t k = 1; k + 1 < cell.size(); ++k)
            made.push_back(elements.bisect({cell[0], cell[k], cell[k + 1]}, proto, limit, lights));
        if (made.size() == 2) elements.pair(made[0], made[1]);
    });
}

}  // namespace

namespace {

// How often cutting looks at `stop`: a million triangles take seconds to cut.
constexpr std::size_t kPiecesBetweenStops = 4096;
bool stops_at(std::size_t piece, const std::function<bool()>& stop) {
    return stop && piece % kPiecesBetweenStops == 0 && stop();
}

// What cutting every piece of `scene` within `limit` makes, without holding it; false once
// `stop` says so.
bool count_elements(const PreparedScene& scene, const EdgeLimit& limit,
                    const std::function<bool()>& stop, ElementCount& out) {
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        if (stops_at(i, stop)) return false;
        Elements elements{nullptr, 0};
        const Piece& piece = scene.pieces[i];
        split_piece(piece, static_cast<int>(i), limit, elements);
        out.elements += elements.count;
        const bool two_sided = scene.materials[static_cast<std::size_t>(piece.material)].two_sided;
        out.sides += elements.count * (two_sided ? 2 : 1);
    }
    return true;
}

}  // namespace

ElementCount ElementMesh::count(const PreparedScene& scene, const ElementSizing& sizing) {
    ElementCount out;
    count_elements(scene, EdgeLimit(scene, sizing), {}, out);
    return out;
}

ElementMesh::ElementMesh(const PreparedScene& scene, const ElementSizing& sizing,
                         const std::function<bool()>& stop, std::optional<ElementCount> counted) {
    const EdgeLimit limit(scene, sizing);
    // Counted first, so the lists hold exactly their elements (the memory budget's estimate).
    if (!counted) {
        counted.emplace();
        if (!count_elements(scene, limit, stop, *counted)) return;
    }
    elements_.reserve(counted->elements);
    sides_.reserve(counted->sides);
    Elements elements{&elements_, 0};
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        if (stops_at(i, stop)) {
            elements_.clear();
            return;
        }
        split_piece(scene.pieces[i], static_cast<int>(i), limit, elements);
    }
    for (std::size_t i = 0; i < elements_.size(); ++i) {
        MeshElement& e = elements_[i];
        e.front = static_cast<int>(sides_.size());
        sides_.push_back({static_cast<int>(i), false, e.area_m2});
        if (scene.materials[static_cast<std::size_t>(e.material)].two_sided) {
            e.back = static_cast<int>(sides_.size());
            sides_.push_back({static_cast<int>(i), true, e.area_m2});
        }
    }
}

void ElementMesh::measure_open_areas(const Visibility& visibility, double near_m,
                                     std::uint64_t& rays) {
    // The centroids of the element's four midpoint triangles.
    constexpr double kWeights[4][3] = {{4.0 / 6, 1.0 / 6, 1.0 / 6},
                                       {1.0 / 6, 4.0 / 6, 1.0 / 6},
                                       {1.0 / 6, 1.0 / 6, 4.0 / 6},
                                       {1.0 / 3, 1.0 / 3, 1.0 / 3}};
    const double eps = visibility.epsilon();
    PerThread<std::uint64_t> counted;
    parallel_for(0, sides_.size(), [&](std::size_t s) {
        ElementSide& side = sides_[s];
        const MeshElement& e = elements_[static_cast<std::size_t>(side.element)];
        const Vec3 n = side.back ? -e.normal : e.normal;
        int open = 0;
        for (const auto& w : kWeights) {
            const Vec3 p = e.triangle.a * w[0] + e.triangle.b * w[1] + e.triangle.c * w[2];
            ++counted.local();
            if (visibility.intersect(p + n * eps, n, near_m).triangle < 0) ++open;
        }
        side.open_area_m2 = e.area_m2 * open / 4.0;
    });
    rays += counted.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
}

std::vector<Triangle> ElementMesh::triangles() const {
    std::vector<Triangle> out;
    out.reserve(elements_.size());
    for (const MeshElement& e : elements_) out.push_back(e.triangle);
    return out;
}

}  // namespace radiant
