#include "montecarlo/element_mesh.h"

#include <algorithm>
#include <cmath>

#include "parallel/fork_join.h"
#include "parallel/per_thread.h"

namespace radiant {
namespace {

struct Splitter {
    double max_edge_squared;
    std::vector<MeshElement>* out;  ///< null: count only
    std::size_t count = 0;

    // Bisects `t` across its longest edge until every edge is at most the target. Returns the
    // element's index when `t` needed no split, else −1.
    int split(const Triangle& t, const MeshElement& proto) {
        const double ab = length_squared(t.b - t.a), bc = length_squared(t.c - t.b),
                     ca = length_squared(t.a - t.c);
        const double longest = std::max({ab, bc, ca});
        if (longest <= max_edge_squared) {
            ++count;
            if (!out) return -1;
            MeshElement e = proto;
            e.triangle = t;
            e.area_m2 = 0.5 * length(cross(t.b - t.a, t.c - t.a));
            out->push_back(e);
            return static_cast<int>(out->size()) - 1;
        }
        // Rotate so that a→b is the longest edge; its midpoint m cuts t into (a, m, c), (m, b, c).
        Triangle r = t;
        if (longest == bc) r = {t.b, t.c, t.a};
        if (longest == ca && longest != bc) r = {t.c, t.a, t.b};
        const Vec3 m = 0.5 * (r.a + r.b);
        const int first = split({r.a, m, r.c}, proto);
        const int second = split({m, r.b, r.c}, proto);
        if (first >= 0 && second >= 0) {
            (*out)[static_cast<std::size_t>(first)].sibling = second;
            (*out)[static_cast<std::size_t>(second)].sibling = first;
        }
        return -1;
    }
};

// Runs `splitter` over every piece's fan of triangles.
void split_pieces(const PreparedScene& scene, Splitter& splitter) {
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const Piece& piece = scene.pieces[i];
        MeshElement proto;
        proto.normal = piece.normal;
        proto.piece = static_cast<int>(i);
        proto.surface = piece.surface;
        proto.material = piece.material;
        // Convex pieces: a fan from the first vertex.
        for (std::size_t k = 1; k + 1 < piece.vertices.size(); ++k) {
            splitter.split({piece.vertices[0], piece.vertices[k], piece.vertices[k + 1]}, proto);
        }
    }
}

}  // namespace

ElementCount ElementMesh::count(const PreparedScene& scene, double max_edge_m) {
    const double h = std::max(max_edge_m, 1e-9);
    ElementCount out;
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        Splitter splitter{h * h, nullptr, 0};
        const Piece& piece = scene.pieces[i];
        for (std::size_t k = 1; k + 1 < piece.vertices.size(); ++k)
            splitter.split({piece.vertices[0], piece.vertices[k], piece.vertices[k + 1]}, {});
        out.elements += splitter.count;
        const bool two_sided = scene.materials[static_cast<std::size_t>(piece.material)].two_sided;
        out.sides += splitter.count * (two_sided ? 2 : 1);
    }
    return out;
}

ElementMesh::ElementMesh(const PreparedScene& scene, double max_edge_m) {
    const double h = std::max(max_edge_m, 1e-9);
    // Counted first, so the lists hold exactly their elements (the memory budget's estimate).
    const ElementCount counted = count(scene, h);
    elements_.reserve(counted.elements);
    sides_.reserve(counted.sides);
    Splitter splitter{h * h, &elements_, 0};
    split_pieces(scene, splitter);
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
