#include "checks/side_hit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace radiant {

SideHit side_hit(const CheckedScene& input, const Vec3& origin, const Vec3& direction) {
    const double eps = input.visibility.epsilon();
    const double t_max = 4 * input.prepared.diagonal_m + 1;
    const RayHit hit = input.visibility.intersect(origin + direction * eps, direction, t_max);
    SideHit out;
    if (hit.triangle < 0) return out;
    out.piece = input.triangle_piece[static_cast<std::size_t>(hit.triangle)];
    const Piece& piece = input.prepared.pieces[static_cast<std::size_t>(out.piece)];
    out.back = dot(direction, piece.normal) > 0;
    out.black =
        out.back && !input.prepared.materials[static_cast<std::size_t>(piece.material)].two_sided;
    out.t = hit.t + eps;
    return out;
}

Vec3 sphere_direction(std::size_t k, std::size_t n) {
    const double golden_angle = std::numbers::pi * (3 - std::sqrt(5.0));
    const double z = 1 - (2 * static_cast<double>(k) + 1) / static_cast<double>(n);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = golden_angle * static_cast<double>(k);
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace radiant
