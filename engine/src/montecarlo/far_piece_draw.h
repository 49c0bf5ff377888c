// Drawing one piece of an emitting surface seen from afar (a lamp's bulb across the room) by the
// light it sends there, in constant time rather than by weighing every piece at every landing.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

/// Seen from beyond kFarRadii of its radius, a surface's pieces differ in the light they send a
/// point mostly by how each faces it: their weights, power × the cosine toward the point, are
/// tabulated for the centres of 96 directions (a cube's faces in 4 × 4 cells), and the point's
/// direction picks a table. A share of each draw goes by power alone, so that every piece with
/// power can be drawn and the draw stays unbiased however rough the table.
class FarPieceDraw {
public:
    static constexpr double kFarRadii = 8;
    static constexpr int kCells = 4;  ///< per cube face side
    static constexpr std::size_t kDirections = 6 * kCells * kCells;

    /// The pieces' centroids, unit front normals and powers (each at least 0), alike in length;
    /// `power_share` of each draw goes by power.
    FarPieceDraw(const std::vector<Vec3>& centroids, const std::vector<Vec3>& normals,
                 const std::vector<double>& powers, double power_share);

    /// Whether `x` is far enough for the tables.
    bool far(const Vec3& x) const;
    /// A piece for `x` (far) drawn with `r` in [0, 1), and its probability.
    std::size_t draw(const Vec3& x, double r, double& probability) const;

private:
    static std::size_t direction_of(const Vec3& u);
    double weight(std::size_t direction, std::size_t piece) const;

    Vec3 centre_;
    double radius_ = 0;
    double share_;
    std::vector<Vec3> normals_;
    std::vector<double> powers_, power_cdf_;
    std::array<Vec3, kDirections> towards_;  ///< each direction's unit centre
    std::vector<double> cdf_;                ///< [direction × pieces + piece], cumulative weight
};

}  // namespace radiant
