// Shared parts of the visibility interface: the scale-aware ray epsilon, the degeneracy rule
// both implementations apply, and the default (per-query) batch.
#include "visibility/visibility.h"
#include "radiant/box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace radiant {

bool is_degenerate(const Triangle& t) {
    if (!is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c)) return true;
    const Vec3 e0 = t.b - t.a;
    const Vec3 e1 = t.c - t.a;
    const Vec3 e2 = t.c - t.b;
    const double longest2 = std::max({length_squared(e0), length_squared(e1), length_squared(e2)});
    // |e0×e1| = 2·area; relative to the longest edge squared it is a scale-free flatness measure.
    return !(length(cross(e0, e1)) > 1e-12 * longest2);
}

double ray_epsilon(std::span<const Triangle> triangles) {
    // Empty input: any small positive offset will do (nothing can be hit).
    constexpr double kEmptySceneEpsilon = 1e-6;
    // Floor that keeps ε a normal, positive number when all vertices sit at the origin.
    constexpr double kMinEpsilon = 1e-9;

    Box box;
    double max_abs = 0.0;
    for (const Triangle& t : triangles) {
        for (const Vec3* v : {&t.a, &t.b, &t.c}) {
            if (!is_finite(*v)) continue;
            box.add(*v);
            for (int i = 0; i < 3; ++i) max_abs = std::max(max_abs, std::abs((*v)[i]));
        }
    }
    if (box.empty()) return kEmptySceneEpsilon;

    const double diagonal = length(box.size());
    // Embree works in float: the spacing of floats at the largest coordinate bounds how far a
    // rounded ray origin or vertex can move, so stay 32 spacings clear of it.
    const float m = static_cast<float>(max_abs);
    const double ulp =
        static_cast<double>(std::nextafter(m, std::numeric_limits<float>::infinity()) - m);
    return std::max({1e-6 * diagonal, 32.0 * ulp, kMinEpsilon});
}

void Visibility::visible_batch(std::span<const SegmentQuery> queries,
                               std::span<std::uint8_t> out) const {
    if (queries.size() != out.size())
        throw std::invalid_argument("visible_batch: queries and out differ in size");
    for (std::size_t i = 0; i < queries.size(); ++i)
        out[i] = visible(queries[i].from, queries[i].to) ? 1 : 0;
}

}  // namespace radiant
