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
    queries.reserve(static_cast<std::size_t>(m));
    for (const Vec3& y : stratified_points(polygon, m, u)) {
        const Vec3 to_centre = centre - y;
        const double d = length(to_centre);
        const Vec3 inset = d > 0 ? y + to_centre * (std::min(2 * eps, 0.5 * d) / d) : y;
        queries.push_back({from, inset + normal * eps});
    }
    // One shaft of rays: the backend traces it as a coherent packet.
    std::vector<std::uint8_t> open(queries.size());
    visibility.visible_batch(queries, open);
    rays += queries.size();
    int seen = 0;
    for (const std::uint8_t v : open) seen += v;
    return queries.empty() ? 0.0 : seen / static_cast<double>(queries.size());
}

}  // namespace radiant
