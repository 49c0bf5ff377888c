// The floor under a work plane: the named surfaces' upward-facing horizontal faces in a frame
// along their longest outline edge, their outline, and the furniture standing on them. Work
// planes and the bands around task areas place their grid points on it.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "radiant/scene.h"

namespace radiant {

/// The usual desk height: a work plane's default, and where a grid's floor is taken to be.
inline constexpr double kWorkplaneHeightM = 0.8;

class FloorPlan {
public:
    /// The floor of `surfaces` (scene units), or why there is none.
    static std::variant<FloorPlan, std::string> of(const Scene& scene,
                                                   const std::vector<std::string>& surfaces);

    Vec3 u_axis() const { return u_axis_; }
    Vec3 v_axis() const { return v_axis_; }
    /// The bounding rectangle in the plan's (u, v) coordinates.
    double u0() const { return u0_; }
    double u1() const { return u1_; }
    double v0() const { return v0_; }
    double v1() const { return v1_; }
    /// Height of the first floor face.
    double z() const { return z_; }
    double tolerance() const { return tolerance_; }

    /// Height of the floor face under (u, v), or none where no face is.
    std::optional<double> height_at(double u, double v) const;
    /// Whether (u, v) is nearer than `distance` to the floor's outline.
    bool near_outline(double u, double v, double distance) const;
    /// Whether x lies inside furniture (a box facing out, or a closed mesh with outward faces).
    bool in_furniture(const Vec3& x) const;
    /// The point at plan coordinates (u, v) and height z.
    Vec3 point(double u, double v, double z) const {
        return u_axis_ * u + v_axis_ * v + Vec3{0, 0, z};
    }

private:
    struct Face {
        std::vector<std::pair<double, double>> corners;
        double z = 0;
    };
    struct Solid {
        std::vector<std::vector<Vec3>> faces;  ///< empty for a box: its bounds are the solid
        Vec3 lo, hi;
    };
    Vec3 u_axis_{1, 0, 0}, v_axis_{0, 1, 0};
    double u0_ = 0, u1_ = 0, v0_ = 0, v1_ = 0, z_ = 0, tolerance_ = 0;
    std::vector<Face> faces_;
    std::vector<std::pair<std::pair<double, double>, std::pair<double, double>>> outline_;
    std::vector<Solid> solids_;
};

}  // namespace radiant
