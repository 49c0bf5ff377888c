#include "formfactor/hemicube.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace radiant {
namespace {

struct Frame {
    Vec3 t1, t2, n;
};

// Branchless orthonormal basis around a unit normal (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited"): no special axis, no cancellation near n = ±z.
Frame make_frame(const Vec3& normal) {
    const Vec3 n = normalized(normal);
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return {
        {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
}

class Accumulator {
public:
    Accumulator(const Vec3& origin, const Visibility& vis, std::span<const int> triangle_patch,
                std::vector<double>& factors)
        : origin_(origin), vis_(vis), triangle_patch_(triangle_patch), factors_(factors) {}

    // One pixel: cast through its centre and credit its delta form factor to the patch hit.
    void add(const Vec3& direction, double delta) {
        const int tri = vis_.first_hit(origin_, direction, std::numeric_limits<double>::infinity());
        if (tri < 0 || static_cast<std::size_t>(tri) >= triangle_patch_.size()) return;
        const int patch = triangle_patch_[static_cast<std::size_t>(tri)];
        if (patch >= 0 && static_cast<std::size_t>(patch) < factors_.size()) {
            factors_[static_cast<std::size_t>(patch)] += delta;
        }
    }

private:
    Vec3 origin_;
    const Visibility& vis_;
    std::span<const int> triangle_patch_;
    std::vector<double>& factors_;
};

// Top face z = 1 of the unit hemicube: ΔF = ΔA / (π (x² + y² + 1)²).
void top_face(const Frame& f, int res, Accumulator& acc) {
    const double h = 2.0 / res;
    for (int i = 0; i < res; ++i) {
        const double x = -1.0 + (i + 0.5) * h;
        for (int j = 0; j < res; ++j) {
            const double y = -1.0 + (j + 0.5) * h;
            const double r = x * x + y * y + 1.0;
            acc.add(f.t1 * x + f.t2 * y + f.n, h * h / (std::numbers::pi * r * r));
        }
    }
}

// Side half-face with outward axis `side`, spanned by `along` (y in [−1, 1]) and n (z in
// [0, 1]): ΔF = z ΔA / (π (y² + z² + 1)²).
void side_face(const Vec3& side, const Vec3& along, const Vec3& n, int res, Accumulator& acc) {
    const int rows = std::max(1, res / 2);
    const double hy = 2.0 / res, hz = 1.0 / rows;
    for (int i = 0; i < res; ++i) {
        const double y = -1.0 + (i + 0.5) * hy;
        for (int k = 0; k < rows; ++k) {
            const double z = (k + 0.5) * hz;
            const double r = y * y + z * z + 1.0;
            acc.add(side + along * y + n * z, z * hy * hz / (std::numbers::pi * r * r));
        }
    }
}

}  // namespace

std::vector<double> hemicube_factors(const Vec3& x, const Vec3& n, int resolution,
                                     const Visibility& vis, std::span<const int> triangle_patch,
                                     std::size_t patch_count) {
    std::vector<double> factors(patch_count, 0.0);
    const Frame f = make_frame(n);
    if (resolution <= 0 || f.n == Vec3{}) return factors;
    Accumulator acc(x + f.n * vis.epsilon(), vis, triangle_patch, factors);
    top_face(f, resolution, acc);
    side_face(f.t1, f.t2, f.n, resolution, acc);
    side_face(-f.t1, f.t2, f.n, resolution, acc);
    side_face(f.t2, f.t1, f.n, resolution, acc);
    side_face(-f.t2, f.t1, f.n, resolution, acc);
    return factors;
}

}  // namespace radiant
