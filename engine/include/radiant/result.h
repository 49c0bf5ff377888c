// What a solve returns: radiant-result/1 without JSON. All quantities SI (m, m², lm, lux).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "radiant/scene.h"
#include "radiant/vec3.h"

namespace radiant {

enum class SolveStatus { converged, stopped, failed };

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
    /// Sound bound on the relative, area-weighted L1 error of the radiosity solution with respect
    /// to the discrete system: ‖r‖/(1−q) / Σ A·B, r the residual, q the norm of diag(ρ)F.
    double error_estimate = 0;
    double emitted_flux_lm = 0;   ///< from emitting surfaces and luminaires
    double absorbed_flux_lm = 0;  ///< Σ A (1−ρ) H over all surface sides
    int channels = 1;             ///< 1 for gray scenes, 3 for RGB
    int threads = 1;
};

struct SensorResult {
    std::string name;
    std::vector<double> illuminance;                       ///< lux, in the order of the points
    double min = 0, max = 0, average = 0, uniformity = 0;  ///< uniformity = min / average
    double u0 = 0;                   ///< EN 12464-1 U₀ = min / average (the same as `uniformity`)
    double ud = 0;                   ///< U_d = min / max
    std::optional<SensorGrid> grid;  ///< work planes: the grid, in metres
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
    SolveStats stats;
    std::vector<SensorResult> sensors;
    std::vector<SurfaceResult> surfaces;
    std::optional<SolvedMesh> mesh;
};

const char* to_string(SolveStatus status);

}  // namespace radiant
