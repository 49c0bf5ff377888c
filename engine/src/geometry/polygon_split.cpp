#include "geometry/polygon_split.h"

#include <algorithm>
#include <cmath>

namespace radiant {
namespace {

struct Point2 {
    double u, v;
};

double cross2(const Point2& o, const Point2& a, const Point2& b) {
    return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
}

// Projects onto the coordinate plane most parallel to the polygon, flipping one axis when needed
// so that counter-clockwise about `n` stays counter-clockwise in 2-D.
std::vector<Point2> project(std::span<const Vec3> polygon, const Vec3& n) {
    const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    int drop = 2;
    if (ax >= ay && ax >= az)
        drop = 0;
    else if (ay >= az)
        drop = 1;
    const int iu = (drop + 1) % 3, iv = (drop + 2) % 3;
    const double sign = n[drop] >= 0 ? 1.0 : -1.0;
    std::vector<Point2> out;
    out.reserve(polygon.size());
    for (const Vec3& p : polygon) out.push_back({p[iu], sign * p[iv]});
    return out;
}

// Closed test: a reflex vertex exactly on an ear's diagonal must block that ear, or the cut
// runs through the vertex and the pieces overlap.
bool inside_triangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

bool same(const Point2& a, const Point2& b) { return a.u == b.u && a.v == b.v; }

}  // namespace

bool is_convex(std::span<const Vec3> polygon, const Vec3& n) {
    const std::size_t k = polygon.size();
    if (k < 3) return false;
    double scale = 0;
    for (std::size_t i = 0; i < k; ++i) scale = std::max(scale, length(polygon[i] - polygon[0]));
    const double eps = 1e-12 * scale * scale;
    for (std::size_t i = 0; i < k; ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % k];
        const Vec3& c = polygon[(i + 2) % k];
        if (dot(cross(b - a, c - b), n) < -eps) return false;
    }
    return true;
}

std::vector<std::vector<Vec3>> triangulate(std::span<const Vec3> polygon, const Vec3& n) {
    std::vector<std::vector<Vec3>> triangles;
    const std::vector<Point2> p = project(polygon, n);
    std::vector<int> idx(polygon.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
    // Ear clipping: O(k²) per polygon, fine for the architectural polygons it serves.
    std::size_t guard = 0;
    while (idx.size() > 3 && guard++ < 4 * polygon.size() * polygon.size()) {
        bool clipped = false;
        const std::size_t m = idx.size();
        for (std::size_t i = 0; i < m; ++i) {
            const int ia = idx[(i + m - 1) % m], ib = idx[i], ic = idx[(i + 1) % m];
            if (cross2(p[ia], p[ib], p[ic]) <= 0) continue;  // reflex or collinear: not an ear
            bool empty = true;
            for (const int j : idx) {
                if (j == ia || j == ib || j == ic) continue;
                if (same(p[j], p[ia]) || same(p[j], p[ib]) || same(p[j], p[ic])) continue;
                if (inside_triangle(p[j], p[ia], p[ib], p[ic])) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            triangles.push_back({polygon[ia], polygon[ib], polygon[ic]});
            idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
            break;
        }
        if (!clipped) {
            // Only collinear runs remain: drop one collinear vertex and go on.
            idx.erase(idx.begin());
        }
    }
    if (idx.size() == 3) triangles.push_back({polygon[idx[0]], polygon[idx[1]], polygon[idx[2]]});
    return triangles;
}

std::vector<std::vector<Vec3>> convex_pieces(std::span<const Vec3> polygon, const Vec3& n,
                                             double planarity_tolerance) {
    double off_plane = 0;
    for (const Vec3& v : polygon) off_plane = std::max(off_plane, std::abs(dot(v - polygon[0], n)));
    if (off_plane <= planarity_tolerance && is_convex(polygon, n)) {
        return {std::vector<Vec3>(polygon.begin(), polygon.end())};
    }
    return triangulate(polygon, n);
}

std::pair<std::vector<Vec3>, std::vector<Vec3>> split_by_plane(std::span<const Vec3> polygon,
                                                               const Vec3& o, const Vec3& m,
                                                               double eps) {
    std::vector<Vec3> pos, neg;
    const std::size_t k = polygon.size();
    std::vector<double> d(k);
    for (std::size_t i = 0; i < k; ++i) {
        d[i] = dot(polygon[i] - o, m);
        if (std::abs(d[i]) <= eps) d[i] = 0;
    }
    for (std::size_t i = 0; i < k; ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % k];
        const double da = d[i], db = d[(i + 1) % k];
        if (da >= 0) pos.push_back(a);
        if (da <= 0) neg.push_back(a);
        if ((da > 0 && db < 0) || (da < 0 && db > 0)) {
            const Vec3 x = a + (b - a) * (da / (da - db));
            pos.push_back(x);
            neg.push_back(x);
        }
    }
    const bool any_pos = std::any_of(d.begin(), d.end(), [](double v) { return v > 0; });
    const bool any_neg = std::any_of(d.begin(), d.end(), [](double v) { return v < 0; });
    if (!any_pos) pos.clear();
    if (!any_neg) neg.clear();
    return {pos, neg};
}

std::vector<Vec3> simplify_polygon(std::span<const Vec3> polygon, double eps) {
    std::vector<Vec3> out;
    for (const Vec3& v : polygon) {
        if (out.empty() || length(v - out.back()) > eps) out.push_back(v);
    }
    while (out.size() > 1 && length(out.front() - out.back()) <= eps) out.pop_back();
    // Drop vertices that lie on the segment between their neighbours.
    bool changed = true;
    while (changed && out.size() > 3) {
        changed = false;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const Vec3& a = out[(i + out.size() - 1) % out.size()];
            const Vec3& b = out[i];
            const Vec3& c = out[(i + 1) % out.size()];
            const double ac = length(c - a);
            if (ac > 0 && length(cross(b - a, c - a)) / ac <= eps) {
                out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                break;
            }
        }
    }
    return out;
}

}  // namespace radiant
