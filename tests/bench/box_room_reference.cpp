#include "box_room_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

#include "analytic_form_factors.h"

namespace radiant::bench {
namespace {

using FaceFrame = BoxFaceFrame;
constexpr std::array<FaceFrame, kBoxFaces> kFrames{{{2, 0, 1, false},
                                                    {2, 0, 1, true},
                                                    {1, 0, 2, false},
                                                    {1, 0, 2, true},
                                                    {0, 1, 2, false},
                                                    {0, 1, 2, true}}};

struct Patch {
    int face = 0;
    bool in_panel = false;
    std::array<double, 3> lo{}, hi{};  ///< lo[normal] == hi[normal], the face's plane
    double area = 0, reflectance = 0, exitance = 0;
};

bool on_grid(double x, int cells_per_metre) {
    const double n = x * cells_per_metre;
    return std::abs(n - std::round(n)) < 1e-9;
}

int cells(double length, int cells_per_metre) {
    if (!on_grid(length, cells_per_metre) || length <= 0)
        throw std::invalid_argument("a side is not a whole number of cells");
    return static_cast<int>(std::lround(length * cells_per_metre));
}

std::vector<Patch> patches_of(const BoxRoom& room, int cells_per_metre) {
    if (room.panel) {
        for (double edge : {room.panel->u0, room.panel->u1, room.panel->v0, room.panel->v1}) {
            if (!on_grid(edge, cells_per_metre))
                throw std::invalid_argument("a panel edge is not a grid line");
        }
    }
    std::vector<Patch> patches;
    for (int f = 0; f < kBoxFaces; ++f) {
        const FaceFrame& frame = kFrames[f];
        const int nu = cells(room.size[frame.u], cells_per_metre);
        const int nv = cells(room.size[frame.v], cells_per_metre);
        const double h = 1.0 / cells_per_metre;
        const double plane = frame.far ? room.size[frame.normal] : 0.0;
        for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
                Patch p;
                p.face = f;
                p.lo[frame.normal] = p.hi[frame.normal] = plane;
                p.lo[frame.u] = i * h;
                p.hi[frame.u] = (i + 1) * h;
                p.lo[frame.v] = j * h;
                p.hi[frame.v] = (j + 1) * h;
                p.area = h * h;
                const double cu = (i + 0.5) * h, cv = (j + 0.5) * h;
                const auto& panel = room.panel;
                p.in_panel = panel && panel->face == f && cu > panel->u0 && cu < panel->u1 &&
                             cv > panel->v0 && cv < panel->v1;
                const FaceMaterial& m = p.in_panel ? panel->material : room.faces[f];
                p.reflectance = m.reflectance;
                p.exitance = m.exitance;
                patches.push_back(p);
            }
        }
    }
    return patches;
}

/// F from patch a to patch b (§1.3); both lie on the inside of the box.
double form_factor(const Patch& a, const Patch& b) {
    if (a.face == b.face) return 0.0;
    const FaceFrame &fa = kFrames[a.face], &fb = kFrames[b.face];
    if (fa.normal == fb.normal) {
        const int u = fa.u, v = fa.v;
        return analytic::parallel_rectangles(a.lo[u], a.hi[u], a.lo[v], a.hi[v], b.lo[u], b.hi[u],
                                             b.lo[v], b.hi[v],
                                             std::abs(b.lo[fa.normal] - a.lo[fa.normal]));
    }
    // Perpendicular: the planes meet in a line along the third axis; each patch is measured by
    // its distance from that line (a box face lies wholly on one side of the other plane).
    const int along = 3 - fa.normal - fb.normal;
    const double plane_a = a.lo[fa.normal], plane_b = b.lo[fb.normal];
    const double xa = std::abs(a.lo[fb.normal] - plane_b), xb = std::abs(a.hi[fb.normal] - plane_b);
    const double za = std::abs(b.lo[fa.normal] - plane_a), zb = std::abs(b.hi[fa.normal] - plane_a);
    return analytic::perpendicular_rectangles(std::min(xa, xb), std::max(xa, xb), a.lo[along],
                                              a.hi[along], std::min(za, zb), std::max(za, zb),
                                              b.lo[along], b.hi[along]);
}

/// Solid angle of the patch seen from `s`: four signed corner rectangles, each
/// atan(u·v / (h·√(h² + u² + v²))).
double solid_angle(const Patch& p, const std::array<double, 3>& s) {
    const FaceFrame& frame = kFrames[p.face];
    const double h = std::abs(p.lo[frame.normal] - s[frame.normal]);
    const auto corner = [h](double u, double v) {
        return std::atan(u * v / (h * std::sqrt(h * h + u * u + v * v)));
    };
    const double u1 = p.lo[frame.u] - s[frame.u], u2 = p.hi[frame.u] - s[frame.u];
    const double v1 = p.lo[frame.v] - s[frame.v], v2 = p.hi[frame.v] - s[frame.v];
    return corner(u2, v2) - corner(u1, v2) - corner(u2, v1) + corner(u1, v1);
}

}  // namespace

const char* box_face_name(int face) {
    static constexpr std::array<const char*, kBoxFaces> kNames{
        "floor", "ceiling", "wall-south", "wall-north", "wall-west", "wall-east"};
    return kNames.at(face);
}

BoxFaceFrame box_face_frame(int face) { return kFrames.at(face); }

BoxRoomSolution solve_box_room(const BoxRoom& room, int cells_per_metre) {
    const std::vector<Patch> patches = patches_of(room, cells_per_metre);
    const auto n = static_cast<Eigen::Index>(patches.size());

    // Upper triangle by the closed forms, lower by reciprocity A_i F_ij = A_j F_ji.
    Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = i + 1; j < n; ++j) {
            const Patch &a = patches[i], &b = patches[j];
            F(i, j) = form_factor(a, b);
            F(j, i) = F(i, j) * a.area / b.area;
        }
    }

    Eigen::VectorXd area(n), rho(n), direct(n), source(n);
    double emitted = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const Patch& p = patches[i];
        area[i] = p.area;
        rho[i] = p.reflectance;
        // Every patch sees a point inside a convex room unoccluded, so its mean direct
        // irradiance is exactly I·Ω/A.
        direct[i] = 0;
        for (const auto& l : room.luminaires)
            direct[i] += l.flux_lm / (4 * std::numbers::pi) * solid_angle(p, l.position) / p.area;
        source[i] = p.exitance + p.reflectance * direct[i];
        emitted += p.area * p.exitance;
    }
    for (const auto& l : room.luminaires) emitted += l.flux_lm;

    BoxRoomSolution out;
    out.patches = static_cast<int>(n);
    out.max_row_sum_error = (F.rowwise().sum().array() - 1.0).abs().maxCoeff();

    // B = E + ρ (H_direct + F B), solved densely.
    Eigen::MatrixXd system = -(rho.asDiagonal() * F);
    system.diagonal().array() += 1.0;
    const Eigen::VectorXd B = Eigen::PartialPivLU<Eigen::MatrixXd>(std::move(system)).solve(source);
    const Eigen::VectorXd H = direct + F * B;

    const double absorbed = (area.array() * (1 - rho.array()) * H.array()).sum();
    out.energy_error = std::abs(absorbed / emitted - 1);

    std::array<double, kBoxFaces> face_area{};
    double panel_area = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const Patch& p = patches[i];
        SurfaceMeans& m = p.in_panel ? out.panel : out.faces[p.face];
        m.radiosity += p.area * B[i];
        m.irradiance += p.area * H[i];
        (p.in_panel ? panel_area : face_area[p.face]) += p.area;
    }
    for (int f = 0; f < kBoxFaces; ++f) {
        out.faces[f].radiosity /= face_area[f];
        out.faces[f].irradiance /= face_area[f];
    }
    if (panel_area > 0) {
        out.panel.radiosity /= panel_area;
        out.panel.irradiance /= panel_area;
    }
    return out;
}

ExtrapolatedMean richardson(const std::array<int, 3>& n, const std::array<double, 3>& value) {
    const auto extrapolate = [&](int a, int b) {
        const double na = double(n[a]) * n[a], nb = double(n[b]) * n[b];
        return (nb * value[b] - na * value[a]) / (nb - na);
    };
    const double fine = extrapolate(1, 2), coarse = extrapolate(0, 1);
    return {fine, std::abs(fine - coarse)};
}

BoxRoomReference reference_for(const BoxRoom& room, const std::array<int, 3>& cells_per_metre) {
    BoxRoomReference ref;
    ref.resolutions = cells_per_metre;
    for (int k = 0; k < 3; ++k) ref.solutions[k] = solve_box_room(room, cells_per_metre[k]);
    const auto extrapolated = [&](auto field) {
        std::array<double, 3> v{};
        for (int k = 0; k < 3; ++k) v[k] = field(ref.solutions[k]);
        return richardson(cells_per_metre, v);
    };
    for (int f = 0; f < kBoxFaces; ++f) {
        ref.radiosity[f] = extrapolated([f](const auto& s) { return s.faces[f].radiosity; });
        ref.irradiance[f] = extrapolated([f](const auto& s) { return s.faces[f].irradiance; });
    }
    if (room.panel) {
        ref.panel_radiosity = extrapolated([](const auto& s) { return s.panel.radiosity; });
        ref.panel_irradiance = extrapolated([](const auto& s) { return s.panel.irradiance; });
    }
    return ref;
}

}  // namespace radiant::bench
