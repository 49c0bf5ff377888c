// A photometric table made continuous: intensity at any direction, smooth and exact at the
// table's angles, never negative, and the flux it emits.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "radiant/photometry.h"

namespace radiant {

/// Interpolates a valid table (read_intensity_table() gives one) with monotone piecewise cubic
/// Hermite curves (Fritsch & Carlson 1980), first across C then across γ. Monotone pieces never
/// overshoot, so the intensity stays between neighbouring table values (never negative). The
/// table's symmetry is unfolded to a full turn of C-planes; across the poles γ = 0 and 180° the
/// curve continues into the opposite plane. Immutable; thread-safe.
class IntensityTable {
public:
    explicit IntensityTable(const PhotometricTable& table);

    /// Intensity (cd) at γ (radians from nadir) in the C-plane c (radians).
    double candela(double gamma_rad, double c_rad) const;

    /// ∫ I dω over the sphere (lm), by Gauss–Legendre quadrature on the table's cells.
    double flux_lm() const { return flux_lm_; }

    /// The largest intensity in any direction (cd): the table's largest value, which the
    /// interpolation (monotone between samples) never exceeds.
    double peak_candela() const;

    /// The widest γ (radians from nadir) with light in any C-plane: past the last row of the
    /// table with an intensity above 0 the curve is 0 from the next row on.
    double widest_lit_gamma_rad() const;

    /// Whether every C-plane holds the same curve: a luminaire alike all round its axis.
    bool alike_all_round() const;

private:
    double row(std::size_t g, double c_deg) const;
    /// The curve across γ (degrees) through the rows `row_at(u, opposite)` of one C direction
    /// (`opposite`: the plane C + 180°, read beyond a pole).
    template <class RowAt>
    double along_gamma(double g, const RowAt& row_at) const;
    double integrate() const;

    std::vector<double> gamma_;  ///< degrees
    std::vector<double> c_;      ///< degrees, a full turn [0, 360)
    std::vector<double> cd_;     ///< [c * gamma_.size() + g]
    double flux_lm_ = 0;
};

/// The table made continuous, or why it cannot be used: angle ranges, order, values, no flux.
std::variant<IntensityTable, std::string> read_intensity_table(const PhotometricTable& table);

/// Why a table cannot be used (empty string when it can), as read_intensity_table() says.
std::string photometric_table_problem(const PhotometricTable& table);

}  // namespace radiant
