// Converged reference answers for closed, axis-aligned box rooms, computed outside the solver
// (validation README §2.7): piecewise-constant Galerkin on a grid of near-square patches per
// face, exact patch-to-patch form factors (§1.3), a dense direct solve, and Richardson
// extrapolation of the face means, which converge as O(h²).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace radiant::bench {

/// Faces of the box, in the order every array below uses.
enum BoxFace { floor_face, ceiling_face, south_face, north_face, west_face, east_face };
inline constexpr int kBoxFaces = 6;

/// The radiant-scene surface name of each face ("floor", "wall-south" at y = 0, …).
const char* box_face_name(int face);

/// A face's normal axis, whether it lies at the far end of that axis, and the two axes its
/// grid (and a panel's u, v) run along.
struct BoxFaceFrame {
    int normal, u, v;
    bool far;
};
BoxFaceFrame box_face_frame(int face);

struct FaceMaterial {
    double reflectance = 0;
    double exitance = 0;  ///< lm/m², emitted from the whole face
};

/// An emitting rectangle inside one face, [u0,u1] × [v0,v1] in the face's own two axes
/// (floor/ceiling: x, y; south/north: x, z; west/east: y, z). Its edges must be grid lines.
struct BoxPanel {
    int face = ceiling_face;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    FaceMaterial material;
};

struct PointLuminaire {
    std::array<double, 3> position{};
    double flux_lm = 0;  ///< isotropic: intensity Φ/4π
};

struct BoxRoom {
    std::string name;
    std::array<double, 3> size{1, 1, 1};  ///< X × Y × Z, the box is [0,X]×[0,Y]×[0,Z]
    std::array<FaceMaterial, kBoxFaces> faces{};
    std::optional<BoxPanel> panel;
    std::vector<PointLuminaire> luminaires;
};

struct SurfaceMeans {
    double radiosity = 0;
    double irradiance = 0;
};

struct BoxRoomSolution {
    int patches = 0;
    /// Face means without the panel's patches (the panel is its own surface in the scene).
    std::array<SurfaceMeans, kBoxFaces> faces{};
    SurfaceMeans panel;
    double max_row_sum_error = 0;  ///< max |Σ_j F_ij − 1|
    double energy_error = 0;       ///< |absorbed/emitted − 1|
};

/// Solves `room` with `cells_per_metre` patches per metre along every axis (each side length
/// times it must be a whole number, and so must the panel's edges).
BoxRoomSolution solve_box_room(const BoxRoom& room, int cells_per_metre);

struct ExtrapolatedMean {
    double value = 0;
    double uncertainty = 0;  ///< spread between the two Richardson extrapolations
};

struct BoxRoomReference {
    std::array<int, 3> resolutions{};            ///< cells per metre, coarse to fine
    std::array<BoxRoomSolution, 3> solutions{};  ///< one per resolution
    std::array<ExtrapolatedMean, kBoxFaces> radiosity{}, irradiance{};
    ExtrapolatedMean panel_radiosity, panel_irradiance;
};

/// Richardson extrapolation (O(h²), h ∝ 1/n) from three resolutions: the value from the finer
/// pair, the uncertainty its difference from the coarser pair's.
ExtrapolatedMean richardson(const std::array<int, 3>& n, const std::array<double, 3>& value);

/// Solves at the three resolutions and extrapolates every face mean.
BoxRoomReference reference_for(const BoxRoom& room, const std::array<int, 3>& cells_per_metre);

}  // namespace radiant::bench
