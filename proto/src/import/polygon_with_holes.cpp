#include "import/polygon_with_holes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiant::proto {
namespace {

struct Point2 {
    double u, v;
};

double cross(const Point2& o, const Point2& a, const Point2& b) {
    return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
}

double signed_area(const std::vector<Point2>& p, const std::vector<int>& ring) {
    double area = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point2& a = p[static_cast<std::size_t>(ring[i])];
        const Point2& b = p[static_cast<std::size_t>(ring[(i + 1) % ring.size()])];
        area += a.u * b.v - b.u * a.v;
    }
    return area / 2;
}

bool same(const Point2& a, const Point2& b) { return a.u == b.u && a.v == b.v; }

/// Inside or on the boundary of the counter-clockwise triangle abc.
bool in_triangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

/// The 2D coordinates of every vertex, projected along the outer ring's dominant normal axis and
/// mirrored if needed so that the outer ring runs counter-clockwise.
std::vector<Point2> project(const std::vector<Vec3>& all, const std::vector<Vec3>& outer,
                            bool& mirrored) {
    Vec3 n{};
    for (std::size_t i = 0; i < outer.size(); ++i) {  // Newell's normal
        const Vec3& a = outer[i];
        const Vec3& b = outer[(i + 1) % outer.size()];
        n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    const int k = std::abs(n.x) >= std::abs(n.y) && std::abs(n.x) >= std::abs(n.z) ? 0
                  : std::abs(n.y) >= std::abs(n.z)                                 ? 1
                                                                                   : 2;
    std::vector<Point2> p;
    for (const Vec3& a : all) p.push_back({a[(k + 1) % 3], a[(k + 2) % 3]});
    mirrored = n[k] < 0;
    if (mirrored) {
        for (Point2& q : p) q.u = -q.u;
    }
    return p;
}

/// Splices `hole` (clockwise) into `ring` (counter-clockwise) through a bridge from the hole's
/// rightmost vertex to a ring vertex it sees. False when no such vertex exists.
bool bridge(const std::vector<Point2>& p, std::vector<int>& ring, const std::vector<int>& hole) {
    const auto at = [&](int i) -> const Point2& { return p[static_cast<std::size_t>(i)]; };
    const auto m_it =
        std::max_element(hole.begin(), hole.end(), [&](int a, int b) { return at(a).u < at(b).u; });
    const Point2 m = at(*m_it);
    // The nearest ring edge crossed by the ray from m towards +u.
    double best_u = std::numeric_limits<double>::infinity();
    std::size_t best_edge = ring.size();
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point2& a = at(ring[i]);
        const Point2& b = at(ring[(i + 1) % ring.size()]);
        if ((a.v > m.v) == (b.v > m.v)) continue;
        const double u = a.u + (m.v - a.v) * (b.u - a.u) / (b.v - a.v);
        if (u >= m.u && u < best_u) best_u = u, best_edge = i;
    }
    if (best_edge == ring.size()) return false;
    const Point2 hit{best_u, m.v};
    std::size_t pick = best_edge;
    if (at(ring[(best_edge + 1) % ring.size()]).u > at(ring[best_edge]).u) {
        pick = (best_edge + 1) % ring.size();
    }
    // A ring vertex inside the triangle (m, hit, pick) would block the bridge: take the one
    // closest in angle to the ray instead.
    const Point2 candidate = at(ring[pick]);
    double best_angle = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point2& r = at(ring[i]);
        if (same(r, candidate) || r.u < m.u) continue;
        const bool inside = candidate.v >= m.v ? in_triangle(r, m, hit, candidate)
                                               : in_triangle(r, m, candidate, hit);
        if (!inside) continue;
        const double angle = std::abs(std::atan2(r.v - m.v, r.u - m.u));
        if (angle < best_angle) best_angle = angle, pick = i;
    }
    std::vector<int> spliced(ring.begin(), ring.begin() + static_cast<long>(pick) + 1);
    const auto start = static_cast<std::size_t>(m_it - hole.begin());
    for (std::size_t k = 0; k <= hole.size(); ++k)
        spliced.push_back(hole[(start + k) % hole.size()]);
    spliced.insert(spliced.end(), ring.begin() + static_cast<long>(pick), ring.end());
    ring = std::move(spliced);
    return true;
}

bool is_ear(const std::vector<Point2>& p, const std::vector<int>& ring, std::size_t i) {
    const auto at = [&](std::size_t k) -> const Point2& {
        return p[static_cast<std::size_t>(ring[(k + ring.size()) % ring.size()])];
    };
    const Point2& a = at(i - 1 + ring.size());
    const Point2& b = at(i);
    const Point2& c = at(i + 1);
    if (cross(a, b, c) <= 0) return false;  // reflex or flat
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const Point2& q = at(k);
        // Bridge ends repeat a corner's position; they do not block the ear.
        if (same(q, a) || same(q, b) || same(q, c)) continue;
        if (in_triangle(q, a, b, c)) return false;
    }
    return true;
}

}  // namespace

std::optional<std::vector<std::array<int, 3>>> triangulate_with_holes(
    const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes) {
    std::vector<Vec3> all = outer;
    std::vector<int> ring(outer.size());
    for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = static_cast<int>(i);
    std::vector<std::vector<int>> hole_rings;
    for (const auto& hole : holes) {
        std::vector<int> h;
        for (const Vec3& v : hole) {
            h.push_back(static_cast<int>(all.size()));
            all.push_back(v);
        }
        hole_rings.push_back(std::move(h));
    }
    bool mirrored = false;
    const std::vector<Point2> p = project(all, outer, mirrored);
    // The triangles must cover exactly the outer area less the holes' (each ear is counter-
    // clockwise, so overlaps add up): otherwise holes overlap or reach outside the boundary.
    double expected_area = signed_area(p, ring);
    if (!(expected_area > 0)) return std::nullopt;
    for (auto& h : hole_rings) {
        const double area = signed_area(p, h);
        if (h.size() < 3 || area == 0) return std::nullopt;
        if (area > 0) std::reverse(h.begin(), h.end());
        expected_area -= std::abs(area);
    }
    if (!(expected_area > 0)) return std::nullopt;
    // Rightmost holes first, so each bridge only crosses ring edges already placed.
    std::sort(hole_rings.begin(), hole_rings.end(), [&](const auto& a, const auto& b) {
        const auto right = [&](const std::vector<int>& h) {
            double u = -std::numeric_limits<double>::infinity();
            for (const int i : h) u = std::max(u, p[static_cast<std::size_t>(i)].u);
            return u;
        };
        return right(a) > right(b);
    });
    for (const auto& h : hole_rings) {
        if (!bridge(p, ring, h)) return std::nullopt;
    }

    std::vector<std::array<int, 3>> triangles;
    while (ring.size() > 3) {
        std::size_t ear = ring.size();
        for (std::size_t i = 0; i < ring.size() && ear == ring.size(); ++i) {
            if (is_ear(p, ring, i)) ear = i;
        }
        if (ear == ring.size()) {
            // No ear: drop a vertex where the ring doubles back or runs straight, if any.
            std::size_t flat = ring.size();
            for (std::size_t i = 0; i < ring.size() && flat == ring.size(); ++i) {
                const Point2& a =
                    p[static_cast<std::size_t>(ring[(i + ring.size() - 1) % ring.size()])];
                const Point2& b = p[static_cast<std::size_t>(ring[i])];
                const Point2& c = p[static_cast<std::size_t>(ring[(i + 1) % ring.size()])];
                if (cross(a, b, c) == 0) flat = i;
            }
            if (flat == ring.size()) return std::nullopt;
            ring.erase(ring.begin() + static_cast<long>(flat));
            continue;
        }
        const std::size_t prev = (ear + ring.size() - 1) % ring.size();
        const std::size_t next = (ear + 1) % ring.size();
        triangles.push_back({ring[prev], ring[ear], ring[next]});
        ring.erase(ring.begin() + static_cast<long>(ear));
    }
    if (ring.size() == 3 &&
        cross(p[static_cast<std::size_t>(ring[0])], p[static_cast<std::size_t>(ring[1])],
              p[static_cast<std::size_t>(ring[2])]) > 0) {
        triangles.push_back({ring[0], ring[1], ring[2]});
    }
    double covered = 0;
    for (const auto& t : triangles) {
        covered += cross(p[static_cast<std::size_t>(t[0])], p[static_cast<std::size_t>(t[1])],
                         p[static_cast<std::size_t>(t[2])]) /
                   2;
    }
    if (triangles.empty() || std::abs(covered - expected_area) > 1e-9 * expected_area) {
        return std::nullopt;
    }
    return triangles;
}

}  // namespace radiant::proto
