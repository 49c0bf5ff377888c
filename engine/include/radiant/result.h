// What a solve returns: radiant-result/1 without JSON. All quantities SI (m, m², lm, lux).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radiant/scene.h"
#include "radiant/vec3.h"
#include "radiant/warnings.h"

namespace radiant {

enum class SolveStatus { converged, stopped, failed };

/// Where a solve's time went: one named stage (prepare, meshing, photons, gather, …).
struct StageStats {
    std::string name;
    double seconds = 0;
    std::uint64_t rays = 0;
    std::size_t memory_bytes = 0;  ///< the most the stage's own data held (the memory ledger)
};

/// The error estimate's parts, each relative like the estimate; the estimate combines them.
/// A method fills those it has and leaves the others 0.
struct ErrorParts {
    double residual = 0;        ///< the linear system's algebraic residual bound
    double discretisation = 0;  ///< mesh and links (a coarser level's answer against this one)
    double gather_noise = 0;    ///< the sensors' sampled rays and visibility
    double photon_noise = 0;    ///< the Monte Carlo light field's noise
    double completion = 0;      ///< light the links did not carry, restored by completion
    /// In cluttered rooms: the radiosity answer's distance to a Monte Carlo solve plus that
    /// solve's own estimate (Pipeline::cross_check)
    double cross_check = 0;
};

/// Statistics every solver reports, so methods can be compared on the same scene.
struct SolveStats {
    std::string method;
    std::size_t patches = 0;
    std::size_t elements = 0;
    std::size_t links = 0;       ///< stored patch-to-patch couplings (form factors)
    std::size_t iterations = 0;  ///< sweeps (gathering) or shots (shooting)
    std::uint64_t rays = 0;      ///< visibility rays cast, form factors and sensors together
    double seconds = 0;
    double unshot_fraction = 0;  ///< unshot power / emitted power (0 for non-shooting solvers)
    /// Relative error the answer is estimated not to exceed: the sensors' RMS error relative to
    /// their mean (worst sensor set; without sensors, the RMS of the surfaces' relative errors),
    /// measured so by every method's checks; for the radiosity methods at least the bound on the
    /// linear system's area-weighted L1 error, ‖r‖/(1−q) / Σ A·B (docs/accuracy.md).
    double error_estimate = 0;
    double emitted_flux_lm = 0;  ///< from emitting surfaces and luminaires
    /// Σ A (1−ρ) H over the surfaces' reflecting sides (not the black backs of one-sided ones).
    double absorbed_flux_lm = 0;
    int channels = 1;  ///< 1 for gray scenes, 3 for RGB
    int threads = 1;
    ErrorParts error_parts;
    std::vector<StageStats> stages;
};

/// A sensor set's values before maintenance (the light of new lamps and clean luminaires).
struct InitialValues {
    std::vector<double> illuminance;  ///< lux, in the order of the points
    double min = 0, max = 0, average = 0, u0 = 0;
};

/// One criterion of a requirement, checked: `value` against `required`.
struct Check {
    enum class Status { pass, fail, unknown };
    std::string criterion;  ///< "em_lx", "u0", "ugr_l" or "ra"
    double required = 0;
    double value = 0;  ///< Ē (maintained), U₀, the largest UGR, the smallest Ra
    Status status = Status::unknown;
    std::string observer;  ///< ugr_l: the observer with the largest UGR
    std::string note;      ///< why a check is `unknown`
};

/// A requirement as applied: the values in force and where they came from.
struct AppliedRequirement {
    std::string source;    ///< "scene", "table" (an activity) or "surrounding" (EN 12464-1 Table 1)
    std::string activity;  ///< reference number and name, when from the table
    std::optional<double> em_lx, u0, ugr_l, ra;
};

struct Compliance {
    Check::Status status = Check::Status::unknown;  ///< fail if any fails, else unknown if any is
    AppliedRequirement requirement;
    std::vector<Check> checks;
};

struct SensorResult {
    std::string name;
    std::vector<Vec3> points;  ///< metres, world frame; grids expanded (row-major, u fastest)
    Vec3 normal{0, 0, 1};      ///< unit; the direction every point faces
    std::vector<double> illuminance;  ///< lux, in the order of the points; maintained values
    double min = 0, max = 0, average = 0, uniformity = 0;  ///< uniformity = min / average
    double u0 = 0;                   ///< EN 12464-1 U₀ = min / average (the same as `uniformity`)
    double ud = 0;                   ///< U_d = min / max
    std::optional<SensorGrid> grid;  ///< work planes: the grid, in metres
    SensorKind kind = SensorKind::planar;
    /// The values without maintenance; set when a maintenance factor below 1 applies.
    std::optional<InitialValues> initial;
    std::optional<std::string> surrounding_of;  ///< a band: the name of its task area
    std::optional<Compliance> compliance;       ///< sets with a requirement
    double error_estimate = 0;  ///< this set's relative RMS error (light scenes; 0 if unknown)
};

/// A UGR observer's result (CIE 117), for the light of new lamps (initial values).
struct ObserverResult {
    std::string name;
    Vec3 position;  ///< the eye, metres
    Vec3 view;      ///< unit line of sight
    std::optional<std::string> task;
    bool standard = false;
    /// 8·log10(0.25/L_b · Σ L²ω/p²); 0 when no luminaire is in view, never below 0.
    double ugr = 0;
    double background_luminance = 0;  ///< L_b = E_ind / π, cd/m²
    double glare_sum = 0;             ///< Σ L²ω/p² over the luminaires in view, cd²/m⁴·sr
    /// How far the UGR may be off through its background's estimated error, UGR units.
    double ugr_error_estimate = 0;
};

/// Which maintenance factor applied to how many sources.
struct MaintenanceUse {
    double factor = 1;
    std::string from;  ///< "luminaire", "material", "settings" or "default"
    std::size_t luminaires = 0, materials = 0;
};

/// One group's contribution at full output: what light scenes are sums of.
struct GroupContribution {
    struct Sensors {
        std::string name;
        std::vector<double> illuminance;          ///< maintained, lux
        std::vector<double> initial_illuminance;  ///< lux
        double error_lx = 0;  ///< estimated RMS error of the maintained values, lux
    };
    struct Glare {
        std::string name;
        double background_luminance = 0;  ///< cd/m², initial
        double glare_sum = 0;             ///< Σ L²ω/p² of its luminaires, initial
        double background_error = 0;      ///< estimated error of the background luminance
    };
    std::string name;
    std::vector<Sensors> sensors;  ///< in the order of Result::sensors
    std::vector<Glare> observers;  ///< in the order of Result::observers
    std::optional<double> ra;      ///< the smallest Ra of its sources; none if one lacks it
};

struct LightSceneResult {
    std::string name;
    std::vector<std::pair<std::string, double>> dimming;
    std::vector<SensorResult> sensors;
    std::vector<ObserverResult> observers;
    double error_estimate = 0;  ///< worst sensor set, from the groups' estimates
};

struct SurfaceResult {
    std::string name;
    double area_m2 = 0;
    double average_irradiance = 0;  ///< lux arriving on the front side (luminance for RGB)
    double average_radiosity = 0;   ///< lm/m² leaving the front side (emitted + reflected)
};

/// The solved patch mesh for display: triangles, shaded with per-vertex radiosity (Gouraud).
/// Vertices are never shared between surfaces or across creases.
struct SolvedMesh {
    std::vector<Vec3> vertices;  ///< metres
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> triangle_surface;       ///< index into Result::surfaces
    std::vector<double> triangle_radiosity;  ///< lm/m² (luminance for RGB)
    std::vector<double> vertex_radiosity;    ///< lm/m², interpolated/extrapolated, ≥ 0
};

struct Result {
    std::string scene;
    SolveStatus status = SolveStatus::failed;
    std::string error;  ///< set when status == failed
    /// Set when status == stopped: what ended the solve before its estimate met the tolerance
    /// (the time limit, a cancel, the memory budget, or the finest mesh within the limits).
    std::string stop_reason;
    SolveStats stats;
    std::vector<SensorResult> sensors;
    std::vector<SurfaceResult> surfaces;
    std::optional<SolvedMesh> mesh;
    std::vector<MaintenanceUse> maintenance;
    std::vector<ObserverResult> observers;
    /// Every group's contribution, when the scene names groups or light scenes.
    std::vector<GroupContribution> groups;
    std::vector<LightSceneResult> light_scenes;
    /// What looks like a modelling mistake (docs/warnings.md); empty when nothing does.
    std::vector<Warning> warnings;
};

const char* to_string(SolveStatus status);
const char* to_string(Check::Status status);
const char* to_string(SensorKind kind);
/// The inverses of to_string: nothing for a name that is not one.
std::optional<Check::Status> check_status_named(std::string_view name);
std::optional<SensorKind> sensor_kind_named(std::string_view name);

}  // namespace radiant
