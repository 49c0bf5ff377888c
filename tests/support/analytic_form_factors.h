// Closed-form form factors for tests (validation README §1; Howell's catalogue C-11, C-12,
// C-17 and the differential-area cases). Double precision; all verified against the README's
// tabulated [V] values in tests/unit/area_form_factor_test.cpp.
#pragma once

#include <cmath>
#include <numbers>

namespace radiant::analytic {

/// §1.1: parallel, directly opposed a × b rectangles at distance c.
inline double parallel_coaxial_rectangles(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double x2 = 1 + x * x, y2 = 1 + y * y;
    const double sum = std::log(std::sqrt(x2 * y2 / (x2 + y * y))) +
                       x * std::sqrt(y2) * std::atan(x / std::sqrt(y2)) +
                       y * std::sqrt(x2) * std::atan(y / std::sqrt(x2)) - x * std::atan(x) -
                       y * std::atan(y);
    return 2.0 / (std::numbers::pi * x * y) * sum;
}

/// §1.2: perpendicular rectangles sharing an edge of length l; from the one of width w to
/// the one of height h (both measured perpendicular to the edge).
inline double perpendicular_common_edge(double l, double w, double h) {
    const double W = w / l, H = h / l, W2 = W * W, H2 = H * H, S = H2 + W2;
    const double log_arg = std::log((1 + W2) * (1 + H2) / (1 + S)) +
                           W2 * std::log(W2 * (1 + S) / ((1 + W2) * S)) +
                           H2 * std::log(H2 * (1 + S) / ((1 + H2) * S));
    const double sum = W * std::atan(1 / W) + H * std::atan(1 / H) -
                       std::sqrt(S) * std::atan(1 / std::sqrt(S)) + 0.25 * log_arg;
    return sum / (std::numbers::pi * W);
}

namespace detail {

// v·s·atan(v/s) → 0 as s → 0 and t·ln t → 0 as t → 0 (the limits §1.3 asks for).
inline double v_atan(double v, double s) { return s > 0 ? v * s * std::atan(v / s) : 0.0; }
inline double xlog(double a, double t) { return t > 0 ? a * std::log(t) : 0.0; }

inline double g_parallel(double u, double v, double c) {
    const double su = std::sqrt(u * u + c * c), sv = std::sqrt(v * v + c * c);
    return (v_atan(v, su) + v_atan(u, sv) - xlog(0.5 * c * c, u * u + v * v + c * c)) /
           (2 * std::numbers::pi);
}

inline double g_perpendicular(double x, double v, double z) {
    const double r2 = x * x + z * z;
    return (v_atan(v, std::sqrt(r2)) - xlog(0.25 * (r2 - v * v), r2 + v * v)) /
           (2 * std::numbers::pi);
}

}  // namespace detail

/// §1.3 parallel: surface 1 = [x1,x2]×[y1,y2] in z = 0, surface 2 = [xi1,xi2]×[eta1,eta2] in
/// z = c. Returns F12.
inline double parallel_rectangles(double x1, double x2, double y1, double y2, double xi1,
                                  double xi2, double eta1, double eta2, double c) {
    const double xs[] = {x1, x2}, ys[] = {y1, y2}, xis[] = {xi1, xi2}, etas[] = {eta1, eta2};
    double sum = 0.0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
                for (int l = 0; l < 2; ++l) {
                    const double sign = ((i + j + k + l) % 2 == 0) ? 1.0 : -1.0;
                    sum += sign * detail::g_parallel(xs[i] - xis[k], ys[j] - etas[l], c);
                }
    return sum / ((x2 - x1) * (y2 - y1));
}

/// §1.3 perpendicular: planes meeting in a line along y; surface 1 spans [x1,x2] from the line
/// and [y1,y2] along it, surface 2 spans [z1,z2] from the line and [eta1,eta2] along it.
/// Returns F12.
inline double perpendicular_rectangles(double x1, double x2, double y1, double y2, double z1,
                                       double z2, double eta1, double eta2) {
    const double xs[] = {x1, x2}, ys[] = {y1, y2}, zs[] = {z1, z2}, etas[] = {eta1, eta2};
    double sum = 0.0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
                for (int l = 0; l < 2; ++l) {
                    const double sign = ((i + j + k + l) % 2 == 0) ? 1.0 : -1.0;
                    sum += sign * detail::g_perpendicular(xs[i], ys[j] - etas[l], zs[k]);
                }
    return sum / ((x2 - x1) * (y2 - y1));
}

/// §1.4: differential area to a parallel a × b rectangle at height c, normal through a corner.
inline double point_to_corner_rectangle(double a, double b, double c) {
    const double A = a / c, B = b / c, sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * std::numbers::pi);
}

/// §1.6: differential area to a coaxial parallel disc of radius r at height h.
inline double point_to_coaxial_disc(double r, double h) { return r * r / (h * h + r * r); }

/// §1.6: differential area to a parallel disc (radius r, height h) whose axis is offset by a.
inline double point_to_offset_disc(double r, double h, double a) {
    const double H = h / a, R = r / a, s = 1 + H * H + R * R;
    return 0.5 * (1 - (1 + H * H - R * R) / std::sqrt(s * s - 4 * R * R));
}

/// §1.7: coaxial parallel discs of radii r1 (source) and r2 at distance h.
inline double coaxial_discs(double r1, double r2, double h) {
    const double R1 = r1 / h, R2 = r2 / h, X = 1 + (1 + R2 * R2) / (R1 * R1);
    return 0.5 * (X - std::sqrt(X * X - 4 * (R2 / R1) * (R2 / R1)));
}

}  // namespace radiant::analytic
