// The scene as a user describes it: lengths in the scene's own unit, materials by name.
// This mirrors radiant-scene/1 (proto/schema/scene.schema.json) without any JSON; the engine
// converts it to SI units when it prepares a solve.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

enum class LengthUnit { m, cm, mm, ft, in };

/// Metres per one `unit` (exact by definition of each unit).
double meters_per_unit(LengthUnit unit);

/// Linear RGB triple; gray values are stored as three equal channels.
using Rgb = std::array<double, 3>;

struct Emission {
    enum class Kind { exitance, flux };
    Kind kind = Kind::exitance;
    double value = 0;          ///< lm/m² for `exitance`, lm for `flux` (spread over all area using it)
    std::optional<Rgb> color;  ///< relative colour; normalised so that its luminance is 1
};

struct Material {
    std::string name;
    Rgb reflectance{0, 0, 0};   ///< each channel in [0, 1)
    bool rgb_reflectance = false;  ///< true when the input gave [r,g,b] rather than one number
    std::optional<Emission> emission;
    bool two_sided = false;  ///< back side reflects too (it never emits)
};

using Polygon = std::vector<Vec3>;

struct MeshGeometry {
    std::vector<Vec3> vertices;
    std::vector<std::vector<int>> faces;  ///< polygonal faces, counter-clockwise seen from the front
};

struct BoxGeometry {
    Vec3 min, max;
    bool facing_in = true;  ///< true: a room (normals inward); false: an object (normals outward)
};

struct Surface {
    std::string name;
    std::string material;
    std::variant<Polygon, MeshGeometry, BoxGeometry> geometry;
};

enum class Distribution { isotropic, lambertian };

struct Luminaire {
    std::string name;
    Vec3 position;
    double flux_lm = 0;
    Distribution distribution = Distribution::isotropic;
    Vec3 aim{0, 0, -1};  ///< axis of a lambertian distribution
    std::optional<Rgb> color;
};

struct SensorSet {
    std::string name;
    std::vector<Vec3> points;  ///< grids are expanded to their cell centres, row-major, u fastest
    Vec3 normal{0, 0, 1};
};

struct Settings {
    double tolerance = 0.01;  ///< target relative error of the solve
    std::optional<double> max_seconds;
    std::string method = "auto";
};

struct Scene {
    std::string name;
    LengthUnit units = LengthUnit::m;
    std::vector<Material> materials;  ///< in the order of the input document
    std::vector<Surface> surfaces;
    std::vector<Luminaire> luminaires;
    std::vector<SensorSet> sensors;
    Settings settings;
};

/// One refusal: where in the scene document (a JSON pointer such as "/surfaces/3/polygon") and why.
struct Problem {
    std::string pointer;
    std::string message;
};

/// Hard limits on a scene, documented in the README; the proto layer also limits file size.
struct SceneLimits {
    std::size_t max_surfaces = 200000;
    std::size_t max_vertices = 2000000;
    std::size_t max_sensor_points = 1000000;
    std::size_t max_luminaires = 100000;
};

/// Semantic checks the JSON schema cannot express (geometry, references, ranges, finiteness).
/// Returns an empty list when the scene can be solved. Thread-safe; pure.
std::vector<Problem> check_scene(const Scene& scene, const SceneLimits& limits = {});

}  // namespace radiant
