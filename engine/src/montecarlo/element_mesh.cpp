#include "montecarlo/element_mesh.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/polygon_split.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"

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

    // Bisects `t` across its longest edge until every edge is at most `h`. Returns the
    // element's index when `t` needed no split, else −1.
    int bisect(const Triangle& t, const MeshElement& proto, double h) {
        Triangle first, second;
        if (!halve(t, h, first, second)) return add(t, proto);
        const int a = bisect(first, proto, h);
        pair(a, bisect(second, proto, h));
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

// How many elements bisecting `t` to fit within h makes, counted up to just past `limit`.
std::size_t bisection_count(const Triangle& t, double h, std::size_t limit) {
    Triangle first, second;
    if (!halve(t, h, first, second)) return 1;
    const std::size_t a = bisection_count(first, h, limit);
    return a > limit ? a : a + bisection_count(second, h, limit - a);
}

// A strip's cells replace bisection only where bisection makes more than this many times their
// elements: elsewhere (a pendant's 1.6 m by 26 cm housing, 18 elements against 12) the two
// meshes are alike and the estimates were measured on bisection's.
constexpr std::size_t kStripGain = 2;

// One piece's elements: a narrow piece's strip of cells where bisection would make slivers by
// the score, else its fan of triangles bisected to fit within `h`.
void split_piece(const Piece& piece, int index, double h, Elements& elements) {
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
    const std::size_t limit = strip ? kStripGain * 2 * strip->cells : 0;
    std::size_t bisected = 0;
    for (std::size_t k = 1; k + 1 < v.size() && strip && bisected <= limit; ++k)
        bisected += bisection_count({v[0], v[k], v[k + 1]}, h, limit - bisected);
    if (!strip || bisected <= limit) {
        // Convex pieces: a fan from the first vertex.
        for (std::size_t k = 1; k + 1 < v.size(); ++k)
            elements.bisect({v[0], v[k], v[k + 1]}, proto, h);
        return;
    }
    for_each_cell(v, *strip, [&](const std::vector<Vec3>& cell) {
        std::vector<int> made;
        for (std::size_t k = 1; k + 1 < cell.size(); ++k)
            made.push_back(elements.bisect({cell[0], cell[k], cell[k + 1]}, proto, h));
        if (made.size() == 2) elements.pair(made[0], made[1]);
    });
}

}  // namespace

ElementCount ElementMesh::count(const PreparedScene& scene, double max_edge_m) {
    const double h = std::max(max_edge_m, 1e-9);
    ElementCount out;
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        Elements elements{nullptr, 0};
        const Piece& piece = scene.pieces[i];
        split_piece(piece, static_cast<int>(i), h, elements);
        out.elements += elements.count;
        const bool two_sided = scene.materials[static_cast<std::size_t>(piece.material)].two_sided;
        out.sides += elements.count * (two_sided ? 2 : 1);
    }
    return out;
}

ElementMesh::ElementMesh(const PreparedScene& scene, double max_edge_m) {
    const double h = std::max(max_edge_m, 1e-9);
    // Counted first, so the lists hold exactly their elements (the memory budget's estimate).
    const ElementCount counted = count(scene, h);
    elements_.reserve(counted.elements);
    sides_.reserve(counted.sides);
    Elements elements{&elements_, 0};
    for (std::size_t i = 0; i < scene.pieces.size(); ++i)
        split_piece(scene.pieces[i], static_cast<int>(i), h, elements);
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
