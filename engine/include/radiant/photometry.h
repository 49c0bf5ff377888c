// A luminaire's luminous intensity table (photometric type C), as IES LM-63 and EULUMDAT files
// give it. The file readers live in proto/; the engine interpolates and integrates the table.
#pragma once

#include <cstddef>
#include <vector>

namespace radiant {

/// The luminous opening of a luminaire (metres in a table, scene units on a luminaire): a
/// rectangle `length` along the C0 axis by `width` along C90 facing the nadir, or an ellipse of
/// those diameters (`round`), with luminous sides of `height`; or a sphere of diameter `length`.
/// All zero: a point source.
struct LuminousShape {
    double length = 0, width = 0, height = 0;
    bool round = false;
    bool sphere = false;
    bool point() const { return length <= 0 && width <= 0 && height <= 0; }
};

/// Intensities on C-planes × γ angles. γ is measured from the luminaire's nadir (its `aim`), C
/// counter-clockwise about the upward axis seen from above, from the C0 plane. The range of
/// `c_deg` says which symmetry the file uses: {0} rotational, [0, 90] both planes C0–C180 and
/// C90–C270, [0, 180] the C0–C180 plane, [90, 270] the C90–C270 plane, [0, 360) none.
struct PhotometricTable {
    std::vector<double> gamma_deg;  ///< ascending, within [0, 180]
    std::vector<double> c_deg;      ///< ascending, within [0, 360]
    std::vector<double> candela;    ///< absolute cd, [c * gamma_deg.size() + g]
    LuminousShape luminous;         ///< metres; all zero when the file gives none

    double at(std::size_t c, std::size_t g) const { return candela[c * gamma_deg.size() + g]; }
};

}  // namespace radiant
