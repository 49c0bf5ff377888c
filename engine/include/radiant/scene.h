// The scene as a user describes it: lengths in the scene's own unit, materials by name.
// This mirrors radiant-scene/1 (proto/schema/scene.schema.json) without any JSON; the engine
// converts it to SI units when it prepares a solve.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "radiant/photometry.h"
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
    double value = 0;  ///< lm/m² for `exitance`, lm for `flux` (spread over all area using it)
    std::optional<Rgb> color;  ///< relative colour; normalised so that its luminance is 1
};

struct Material {
    std::string name;
    Rgb reflectance{0, 0, 0};      ///< each channel in [0, 1)
    bool rgb_reflectance = false;  ///< true when the input gave [r,g,b] rather than one number
    std::optional<Emission> emission;
    bool two_sided = false;  ///< back side reflects too (it never emits)
};

using Polygon = std::vector<Vec3>;

struct MeshGeometry {
    std::vector<Vec3> vertices;
    std::vector<std::vector<int>>
        faces;  ///< polygonal faces, counter-clockwise seen from the front
};

struct BoxGeometry {
    Vec3 min, max;
    bool facing_in = true;  ///< true: a room (normals inward); false: an object (normals outward)
};

struct Surface {
    std::string name;
    std::string material;
    std::variant<Polygon, MeshGeometry, BoxGeometry> geometry;
    /// Where the surface comes from in the input document, as warnings name it (a JSON pointer
    /// such as "/surfaces/3"; an imported model's surfaces share their document surface's).
    /// Empty: "/surfaces/<its index>". (Initialised, so that brace initialisers may omit it.)
    std::string pointer = {};
};

enum class Distribution { isotropic, lambertian, photometric };

struct Luminaire {
    std::string name;
    Vec3 position;
    /// Emitted flux. Required for isotropic and lambertian luminaires; a photometric table is
    /// scaled to emit it, and without it emits the flux of its own intensities.
    std::optional<double> flux_lm;
    Distribution distribution = Distribution::isotropic;
    Vec3 aim{0, 0, -1};  ///< axis of a lambertian distribution; nadir (γ = 0) of a photometric one
    double rotation_deg = 0;  ///< photometric: turns the C0 plane about `aim`, like increasing C
    std::optional<PhotometricTable> photometry;  ///< set for Distribution::photometric
    std::optional<Rgb> color;
};

/// An EN 12464-1 work plane: a grid over named floor surfaces (their upward-facing horizontal
/// faces), lifted by `height`, kept `border` away from the floor's edges. Scene units.
struct Workplane {
    std::vector<std::string> surfaces;
    std::optional<double> height;   ///< default 0.8 m
    std::optional<double> border;   ///< default 0.5 m
    std::optional<double> spacing;  ///< default p = 0.2·5^log10(d), d the longer side in metres
};

/// Where a work plane's points lie: nu × nv cells over the rectangle origin + [0,1]·u + [0,1]·v;
/// points are cell centres inside the floor and outside furniture.
struct SensorGrid {
    int nu = 0, nv = 0;
    double spacing = 0;  ///< the target spacing p (scene units; metres in a result)
    Vec3 origin, u, v;   ///< the area's corner and sides (scene units; metres in a result)
    std::vector<std::array<int, 2>> cells;  ///< (iu, iv) of each point, in the order of points
    std::vector<Vec3> points;               ///< the points (scene units; metres in a result)
};

struct SensorSet {
    std::string name;
    std::vector<Vec3> points;  ///< grids are expanded to their cell centres, row-major, u fastest
    Vec3 normal{0, 0, 1};
    std::optional<Workplane> workplane;  ///< points come from expand_workplanes()
    std::optional<SensorGrid> grid;      ///< set by expand_workplanes()
};

struct Settings {
    double tolerance = 0.01;  ///< target relative error of the solve
    std::optional<double> max_seconds;
    std::string method = "auto";
    bool strict = false;  ///< warnings are errors (SolveOptions::strict)
    /// Significant digits of the values in the JSON result (1–17); the engine ignores it.
    int digits = 4;
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

/// Fills the points and grid of every work-plane sensor set of a scene that passed check_scene().
/// Problems (a floor without an upward-facing horizontal face, no point left, too many points)
/// point at the sensor set. Thread-safe for distinct scenes.
std::vector<Problem> expand_workplanes(Scene& scene, const SceneLimits& limits = {});

}  // namespace radiant
