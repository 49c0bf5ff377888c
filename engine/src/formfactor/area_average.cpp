#include "formfactor/area_average.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

#include "formfactor/point_polygon.h"
#include "formfactor/quadrature.h"
#include "formfactor/receiver_rule.h"

namespace radiant {
namespace {

// Degree of the rule on each piece: exact for the smooth part, cheap (4 points on a quad).
constexpr int kDegree = 2;

struct CubaturePiece {
    std::vector<Vec3> polygon;
    double value = 0;  ///< the quarters' rules together: this piece's best estimate
    double error = 0;  ///< estimated error of `value`
    bool operator<(const CubaturePiece& other) const { return error < other.error; }
};

double segment_distance(const Vec3& x, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double l2 = length_squared(ab);
    const double t = l2 > 0 ? std::clamp(dot(x - a, ab) / l2, 0.0, 1.0) : 0.0;
    return length(x - (a + ab * t));
}

}  // namespace

double area_averaged_factor(std::span<const Vec3> receiver, const Vec3& receiver_normal,
                            std::span<const Vec3> source, const Vec3& source_normal,
                            double relative_tolerance, double absolute_tolerance_m2,
                            int max_pieces) {
    const double area = polygon_area(receiver);
    if (!(area > 0) || receiver.size() < 3 || source.size() < 3) return 0;
    const Vec3 source_point = source[0];
    auto factor = [&](const Vec3& x) {
        return front_point_to_polygon_factor(x, receiver_normal, source, source_normal);
    };
    // Σ w F over the piece's rule; `lo`, `hi` track the factors seen.
    auto integral = [&](const std::vector<Vec3>& polygon, double& lo, double& hi) {
        double sum = 0;
        for (const QuadraturePoint& q : polygon_quadrature(polygon, kDegree)) {
            const double f = factor(q.position);
            lo = std::min(lo, f);
            hi = std::max(hi, f);
            sum += q.weight * f;
        }
        return sum;
    };
    // Rules on a piece and on its quarters agree by chance where neither has a point in the
    // strip, about as wide as the distance g to the source's plane, along the source's edges
    // in which the factor changes by the spread it has over the piece (from about 1 to about 0
    // under a close parallel source): a piece larger than g near an edge carries an error of
    // up to its share of that strip, about g × its size × that spread.
    auto strip_error = [&](const std::vector<Vec3>& polygon, double piece_area, double spread) {
        const Vec3 c = polygon_centroid(polygon);
        double radius = 0;
        for (const Vec3& v : polygon) radius = std::max(radius, length(v - c));
        const double g = std::abs(dot(c - source_point, source_normal));
        if (radius < g) return 0.0;
        double edge = 1e300;
        for (std::size_t i = 0; i < source.size(); ++i) {
            edge = std::min(edge, segment_distance(c, source[i], source[(i + 1) % source.size()]));
        }
        if (edge > 2 * radius + 2 * g) return 0.0;
        return spread * std::min(piece_area, 2 * radius * g);
    };
    auto make = [&](std::vector<Vec3> polygon, double whole) {
        CubaturePiece p;
        double quarters = 0, lo = 1e300, hi = -1e300;
        for (const auto& part : split_in_four(polygon)) quarters += integral(part, lo, hi);
        for (const Vec3& v : polygon) {
            const double f = factor(v);
            lo = std::min(lo, f);
            hi = std::max(hi, f);
        }
        p.value = quarters;
        p.error = std::max(std::abs(quarters - whole),
                           strip_error(polygon, polygon_area(polygon), hi - lo));
        p.polygon = std::move(polygon);
        return p;
    };
    double lo = 0, hi = 0;  // unused: the pieces' own spreads include their quarters' points
    const std::vector<Vec3> first(receiver.begin(), receiver.end());
    std::priority_queue<CubaturePiece> pieces;
    pieces.push(make(first, integral(first, lo, hi)));
    double total = pieces.top().value, error = pieces.top().error;
    while (!pieces.empty() && static_cast<int>(pieces.size()) + 3 <= max_pieces &&
           error > relative_tolerance * total && error > absolute_tolerance_m2 &&
           error > 1e-15 * area) {
        CubaturePiece worst = pieces.top();
        pieces.pop();
        total -= worst.value;
        error -= worst.error;
        for (auto& part : split_in_four(worst.polygon)) {
            const double whole = integral(part, lo, hi);
            CubaturePiece p = make(std::move(part), whole);
            total += p.value;
            error += p.error;
            pieces.push(std::move(p));
        }
    }
    return std::max(total, 0.0) / area;
}

}  // namespace radiant
