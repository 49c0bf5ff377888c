// How far one draw of a sum of squared noises may land above its expectation. A Monte Carlo
// estimate states the expected square of its error; the realised error is one draw, and where a
// few terms hold most of the variance (a few walls, one point beside a lamp) that draw has few
// degrees of freedom and lands far above its expectation more often.
#pragma once

#include <algorithm>
#include <cmath>

namespace radiant {

/// √(q/k) for the upper 1 % quantile q of χ² with k = `degrees` degrees of freedom (at least 1),
/// by Wilson and Hilferty (1931): 2.57 for one, 1.52 for ten, toward 1 for many. For terms of
/// unequal variances v_i, k is their effective number (Σv)²/Σv² (Satterthwaite 1946).
inline double chi_square_margin(double degrees) {
    constexpr double kQuantileDeviate = 2.326;  // a normal's upper 1 %
    const double k = std::max(degrees, 1.0);
    const double c = 1 - 2 / (9 * k) + kQuantileDeviate * std::sqrt(2 / (9 * k));
    return std::sqrt(c * c * c);
}

}  // namespace radiant
