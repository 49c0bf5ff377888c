#include "montecarlo/far_piece_draw.h"

#include <algorithm>
#include <cmath>

#include "montecarlo/cdf_draw.h"

namespace radiant {
namespace {

// The cube face a direction leaves through (0–5: +x, −x, +y, −y, +z, −z), and its two other
// coordinates over the dominant one, in [−1, 1].
struct FacePoint {
    int face = 0;
    double s = 0, t = 0;
};
FacePoint face_point(const Vec3& u) {
    const double ax = std::abs(u.x), ay = std::abs(u.y), az = std::abs(u.z);
    if (ax >= ay && ax >= az) return {u.x >= 0 ? 0 : 1, u.y / ax, u.z / ax};
    if (ay >= az) return {u.y >= 0 ? 2 : 3, u.x / ay, u.z / ay};
    return {u.z >= 0 ? 4 : 5, u.x / az, u.y / az};
}

Vec3 from_face(int face, double s, double t) {
    const double sign = face % 2 == 0 ? 1.0 : -1.0;
    switch (face / 2) {
        case 0:
            return {sign, s, t};
        case 1:
            return {s, sign, t};
        default:
            return {s, t, sign};
    }
}

}  // namespace

FarPieceDraw::FarPieceDraw(const std::vector<Vec3>& centroids, const std::vector<Vec3>& normals,
                           const std::vector<double>& powers, double power_share)
    : share_(power_share), normals_(normals), powers_(powers) {
    const std::size_t n = centroids.size();
    for (const Vec3& c : centroids) centre_ += c / static_cast<double>(n);
    for (const Vec3& c : centroids) radius_ = std::max(radius_, length(c - centre_));
    double total = 0;
    for (const double p : powers_) power_cdf_.push_back(total += p);
    for (std::size_t d = 0; d < kDirections; ++d) {
        const int face = static_cast<int>(d / (kCells * kCells));
        const auto cell = static_cast<int>(d % (kCells * kCells));
        const double s = (cell / kCells + 0.5) * 2.0 / kCells - 1;
        const double t = (cell % kCells + 0.5) * 2.0 / kCells - 1;
        towards_[d] = normalized(from_face(face, s, t));
    }
    cdf_.reserve(kDirections * n);
    for (std::size_t d = 0; d < kDirections; ++d) {
        double sum = 0;
        for (std::size_t k = 0; k < n; ++k) cdf_.push_back(sum += weight(d, k));
    }
}

bool FarPieceDraw::far(const Vec3& x) const {
    return length_squared(x - centre_) >= kFarRadii * kFarRadii * radius_ * radius_;
}

std::size_t FarPieceDraw::direction_of(const Vec3& u) {
    const FacePoint f = face_point(u);
    const auto cell = [](double v) {
        return std::clamp(static_cast<int>((v + 1) / 2 * kCells), 0, kCells - 1);
    };
    return static_cast<std::size_t>(f.face * kCells * kCells + cell(f.s) * kCells + cell(f.t));
}

double FarPieceDraw::weight(std::size_t direction, std::size_t piece) const {
    return powers_[piece] * std::max(0.0, dot(normals_[piece], towards_[direction]));
}

std::size_t FarPieceDraw::draw(const Vec3& x, double r, double& probability) const {
    const std::size_t n = powers_.size();
    const double power = power_cdf_.back();
    const std::size_t d = direction_of(x - centre_);
    const auto first = cdf_.begin() + static_cast<std::ptrdiff_t>(d * n);
    const double light = *(first + static_cast<std::ptrdiff_t>(n - 1));
    // Without light toward x (every piece faces away) the draw goes by power alone.
    const double by_light = light > 0 ? (1 - share_) / light : 0.0;
    const double by_power = power > 0 ? (light > 0 ? share_ : 1.0) / power : 0.0;
    const std::size_t k = light > 0 && r < 1 - share_
                              ? draw_index({first, n}, r / (1 - share_))
                              : draw_index(power_cdf_, light > 0 ? (r - (1 - share_)) / share_ : r);
    probability = by_light * weight(d, k) + by_power * powers_[k];
    return k;
}

}  // namespace radiant
