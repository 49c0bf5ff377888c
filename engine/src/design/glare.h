// Discomfort glare by the CIE unified glare rating (CIE 117:1995):
//   UGR = 8·log10( 0.25/L_b · Σ L²·ω / p² )
// over the luminaires an observer sees: L the luminance of a luminaire's luminous area toward
// the eye (its intensity over its projected area), ω that area's solid angle, p the Guth
// position index of its direction from the line of sight, L_b the background luminance.
#pragma once

#include <cstdint>

#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// CIE 147:2002: a source smaller than this is rated as if it were this large (L²ω becomes
/// 200·I²/r²): the UGR formula overrates small bright sources. Luminaires whose photometric data
/// declare a point source get this form too.
inline constexpr double kSmallSourceAreaM2 = 0.005;

/// The Guth position index of a source `forward` along the line of sight, `lateral` across it
/// and `up` above it (any unit), as CIE 117 fits the Luckiesh–Guth table:
/// ln p = (35.2 − 0.31889α − 1.22e^(−2α/9))·10⁻³β + (21 + 0.26667α − 0.002963α²)·10⁻⁵β²,
/// α the angle (degrees) from the vertical of the plane through the line of sight and the source,
/// β the angle between them. Needs forward > 0 and up ≥ 0.
double guth_position_index(double forward, double lateral, double up);

/// Area (m²) of a luminous shape projected toward the unit direction (c0, c90, nadir) in the
/// luminaire's frame: its downward face × the nadir component, its sides × the horizontal ones.
double projected_area_m2(const LuminousShape& shape, double c0, double c90, double nadir);

/// Σ L²ω/p² (cd²/m⁴·sr) over the luminaires of `component` (all for −1) in front of the eye and
/// above its line of sight that a shadow ray finds unoccluded; a luminaire behind the observer
/// contributes nothing. Counts rays into `rays`.
double glare_sum(const PreparedScene& scene, const PreparedObserver& observer,
                 const Visibility& visibility, int component, std::uint64_t& rays);

/// UGR from the glare sum and the background luminance (cd/m²): 0 when no luminaire is in view,
/// never below 0; a background darker than 10⁻⁶ cd/m² counts as that (the formula has no value
/// for none).
double unified_glare_rating(double glare_sum, double background_luminance);

}  // namespace radiant
