// The scene as the engine solves it: SI units, in a local frame centred on the scene (so that
// single-precision ray tracing keeps its accuracy 10 km from the world origin), every surface
// side reduced to planar convex pieces, emission resolved to exitance per channel.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "design/light_components.h"
#include "photometry/intensity_table.h"
#include "radiant/scene.h"

namespace radiant {

struct PreparedMaterial {
    std::string name;
    Rgb reflectance{0, 0, 0};
    Rgb exitance_lm_m2{0, 0, 0};  ///< front side only
    bool two_sided = false;
    int component = 0;  ///< the light component its emission belongs to
    bool emits() const {
        return exitance_lm_m2[0] > 0 || exitance_lm_m2[1] > 0 || exitance_lm_m2[2] > 0;
    }
};

/// A planar convex piece of one input surface (front side; back sides are made by meshing).
struct Piece {
    std::vector<Vec3> vertices;  ///< counter-clockwise seen from the front, local frame, metres
    Vec3 normal;                 ///< unit, front side
    double area_m2 = 0;
    int surface = 0;
    int material = 0;
};

struct PreparedLuminaire {
    std::string name;
    Vec3 position;
    Rgb flux_lm{0, 0, 0};
    Distribution distribution = Distribution::isotropic;
    Vec3 aim{0, 0, -1};  ///< unit
    /// Photometric luminaires: the table (shared by copies of the scene) and the unit directions
    /// of the C0 and C90 planes, both perpendicular to `aim`.
    std::shared_ptr<const IntensityTable> table;
    Vec3 c0_axis, c90_axis;
    int component = 0;  ///< the light component it belongs to
    /// The luminous opening (metres), for glare; a point when neither the scene nor the file
    /// gives one.
    LuminousShape luminous;
};

struct PreparedSensorSet {
    std::string name;
    std::vector<Vec3> points;  ///< local frame
    Vec3 normal;               ///< unit; vertical kinds: horizontal, the facing
    SensorKind kind = SensorKind::planar;
    std::optional<SensorGrid> grid;  ///< work planes: world frame, metres
};

struct PreparedObserver {
    std::string name;
    Vec3 position;  ///< the eye, local frame
    Vec3 view;      ///< unit line of sight
};

struct PreparedScene {
    std::string name;
    int channels = 1;       ///< 1 for gray scenes, 3 when any colour differs between channels
    Vec3 world_origin;      ///< world position (metres) of the local frame's origin
    double diagonal_m = 0;  ///< bounding-box diagonal of all geometry
    double total_area_m2 = 0;
    std::vector<PreparedMaterial> materials;
    std::vector<std::string> surface_names;
    std::vector<double> surface_area_m2;
    std::vector<Piece> pieces;
    std::vector<PreparedLuminaire> luminaires;
    std::vector<PreparedSensorSet> sensors;
    std::vector<PreparedObserver> observers;
    /// Groups and maintenance factors: the components a solve keeps apart.
    LightComponents components;
};

/// Converts a scene that passed check_scene(). Degenerate pieces (zero area) are dropped.
PreparedScene prepare_scene(const Scene& scene);

/// Rec. 709 luminance weights used to collapse RGB to photometric quantities.
inline constexpr Rgb kLuminanceWeights{0.2126, 0.7152, 0.0722};

inline double luminance(const Rgb& c) {
    return kLuminanceWeights[0] * c[0] + kLuminanceWeights[1] * c[1] + kLuminanceWeights[2] * c[2];
}

}  // namespace radiant
