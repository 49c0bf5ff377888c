#include "formfactor/shadow_rays.h"

#include <algorithm>
#include <vector>

#include "formfactor/quadrature.h"

namespace radiant {

double visible_fraction(const Visibility& visibility, const Vec3& x, const Vec3& n,
                        std::span<const Vec3> polygon, const Vec3& centre, const Vec3& normal,
                        int m, SampleStream& rng, std::uint64_t& rays) {
    std::vector<double> u(2 * static_cast<std::size_t>(m));
    for (double& v : u) v = rng.next();
    const double eps = visibility.epsilon();
    const Vec3 from = x + n * eps;
    std::vector<SegmentQuery> queries;
    std::vector<double> kernel;  // cos θ cos θ' / r² toward each target
    queries.reserve(static_cast<std::size_t>(m));
    kernel.reserve(static_cast<std::size_t>(m));
    for (const Vec3& y : stratified_points(polygon, m, u)) {
        const Vec3 to_centre = centre - y;
        const double d = length(to_centre);
        const Vec3 inset = d > 0 ? y + to_centre * (std::min(2 * eps, 0.5 * d) / d) : y;
        queries.push_back({from, inset + normal * eps});
        const Vec3 r = y - x;
        const double r2 = length_squared(r);
        kernel.push_back(
            r2 > 0 ? std::max(0.0, dot(n, r)) * std::max(0.0, -dot(normal, r)) / (r2 * r2) : 0.0);
    }
    // One shaft of rays: the backend traces it as a coherent packet.
    std::vector<std::uint8_t> open(queries.size());
    visibility.visible_batch(queries, open);
    rays += queries.size();
    // Each ray counts by the kernel toward its target: the fraction of the factor, not of the
    // area, that is seen. Near a source whose kernel varies (a slat 0.1 m from a window seen
    // past the next slat), the seen part is where the kernel is large, and the area fraction
    // made the slats' factors to the pane 16 % low.
    double seen = 0, total = 0;
    for (std::size_t i = 0; i < open.size(); ++i) {
        seen += open[i] * kernel[i];
        total += kernel[i];
    }
    if (total > 0) return seen / total;
    int count = 0;  // every target behind or at x: the area fraction
    for (const std::uint8_t v : open) count += v;
    return queries.empty() ? 0.0 : count / static_cast<double>(queries.size());
}

}  // namespace radiant
