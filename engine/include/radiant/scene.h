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

/// What a lighting designer attaches to every light source (luminaire or emitting material).
struct SourceDesign {
    /// The light scene group it switches and dims with; sources without one are in "default".
    std::optional<std::string> group;
    /// Light output at the end of the maintenance cycle over the initial output, in (0, 1];
    /// `settings.maintenance_factor`, else 1, when not given.
    std::optional<double> maintenance_factor;
    std::optional<double> ra;  ///< colour rendering index of its lamps, [0, 100]
};

struct Emission {
    enum class Kind { exitance, flux };
    Kind kind = Kind::exitance;
    double value = 0;  ///< lm/m² for `exitance`, lm for `flux` (spread over all area using it)
    std::optional<Rgb> color;  ///< relative colour; normalised so that its luminance is 1
    SourceDesign design;
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
    SourceDesign design;
    /// The luminous opening for glare (scene units); overrides the photometric file's.
    std::optional<LuminousShape> luminous_area;
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

/// What a sensor measures at its point (z is up): illuminance on a tiny disc facing `normal`
/// (planar), on a vertical disc facing the horizontal part of `normal` (vertical), or averaged
/// over the curved side of a tiny upright cylinder (cylindrical) or of its half facing the
/// horizontal part of `normal` (semi-cylindrical).
enum class SensorKind { planar, vertical, cylindrical, semi_cylindrical };

/// An EN 12464-1 requirement of a task area. `activity` names a row of the built-in table
/// (reference numbers such as "5.26.2"), whose values fill the criteria not given here.
struct Requirement {
    std::optional<std::string> activity;
    std::optional<double> em_lx;  ///< maintained average illuminance Ēm at least this (lux)
    std::optional<double> u0;     ///< uniformity U₀ = E_min / Ē at least this
    std::optional<double> ugr_l;  ///< unified glare rating at most this (UGR_L)
    std::optional<double> ra;     ///< colour rendering index of the lamps at least this
};

/// The parallelogram origin + [0,1]·u + [0,1]·v a `grid` covers (scene units).
struct GridArea {
    Vec3 origin, u, v;
};

struct SensorSet {
    std::string name;
    std::vector<Vec3> points;  ///< grids are expanded to their cell centres, row-major, u fastest
    Vec3 normal{0, 0, 1};
    std::optional<Workplane> workplane;  ///< points come from expand_workplanes()
    std::optional<SensorGrid> grid;      ///< set by expand_workplanes()
    SensorKind kind = SensorKind::planar;
    std::optional<GridArea> grid_area;  ///< a `grid` set's area (set by the JSON reader)
    std::optional<Requirement> requirement;
    /// Set by expand_task_areas() on the immediate surrounding band it adds: the task area's
    /// index among the sensor sets.
    std::optional<std::size_t> surrounding_of;
};

/// A UGR observer: the eye's position (scene units) and the line of sight.
struct Observer {
    std::string name;
    Vec3 position;
    Vec3 view{1, 0, 0};
    /// The task area whose `ugr_l` this observer checks (a sensor set name); none: every one
    /// that has no observer of its own.
    std::optional<std::string> task;
    bool standard = false;  ///< placed by expand_task_areas() at the standard positions
};

/// A light scene: every group's dimming in [0, 1]; groups it does not name are off.
struct LightScene {
    std::string name;
    std::vector<std::pair<std::string, double>> dimming;
};

struct Settings {
    double tolerance = 0.01;  ///< target relative error of the solve
    std::optional<double> max_seconds;
    std::string method = "auto";
    std::optional<double> maintenance_factor;  ///< of every source that sets none; default 1
    bool strict = false;                       ///< warnings are errors (SolveOptions::strict)
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
    std::vector<Observer> observers;
    std::vector<LightScene> light_scenes;
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
    /// Of one polygon or mesh face: triangulating one takes time in the square of its vertices.
    std::size_t max_polygon_vertices = 10000;
    /// Of all polygons and faces of over `large_polygon_vertices` each, together: ten of the
    /// largest take about 1.5 s to triangulate.
    std::size_t large_polygon_vertices = 1000;
    std::size_t max_large_polygon_vertices = 100000;
    std::size_t max_sensor_points = 1000000;
    std::size_t max_luminaires = 100000;
    /// Light components (group × maintenance factor): each is a photon field and a gather.
    std::size_t max_light_components = 32;
    std::size_t max_light_scenes = 256;
    std::size_t max_observers = 1000;
    /// Sensor values a result keeps: each point once, and once more per group and per light
    /// scene when the scene has them (see check_sensor_totals()).
    std::size_t max_kept_sensor_values = 20000000;
    /// Sensor points × luminaires: each point takes a shadow ray to every luminaire, exactly,
    /// whatever the method, and a time limit cannot cut that gather short (10⁹: about 45 s on
    /// two cores).
    std::size_t max_luminaire_sensor_pairs = 1000000000;
};

/// Semantic checks the JSON schema cannot express (geometry, references, ranges, finiteness).
/// Returns an empty list when the scene can be solved. Thread-safe; pure.
std::vector<Problem> check_scene(const Scene& scene, const SceneLimits& limits = {});

/// Fills the points and grid of every work-plane sensor set of a scene that passed check_scene().
/// Problems (a floor without an upward-facing horizontal face, no point left, too many points)
/// point at the sensor set. Thread-safe for distinct scenes.
std::vector<Problem> expand_workplanes(Scene& scene, const SceneLimits& limits = {});

/// Whether the totals that grow with the sensor points stay within SceneLimits: the values a
/// result keeps per point (every group's contribution and every light scene beside the main
/// values, max_kept_sensor_values) and the points' shadow rays to the luminaires
/// (max_luminaire_sensor_pairs). check_scene() calls it; call it again after
/// expand_task_areas(), which adds points. Thread-safe; pure.
std::vector<Problem> check_sensor_totals(const Scene& scene, const SceneLimits& limits = {});

/// For every sensor set with a requirement (after expand_workplanes()): appends its immediate
/// surrounding band (EN 12464-1: 0.5 m wide, its own grid, the standard's lower requirement) as
/// a sensor set, and, where a requirement limits UGR and no observer checks it, the standard
/// observers at the middle of each side of the band's outline (eye 1.2 m above the floor,
/// looking across the area). Problems point at the sensor set. Thread-safe for distinct scenes.
std::vector<Problem> expand_task_areas(Scene& scene, const SceneLimits& limits = {});

}  // namespace radiant
