// What the IES and EULUMDAT targets check of a table read: a table the engine accepts must give
// a finite, non-negative flux and intensities (no NaN may leave the engine).
#pragma once

#include <cmath>
#include <string>
#include <variant>

#include "photometry/intensity_table.h"
#include "radiant/photometry.h"

namespace radiant::fuzz {

inline void check_table(const std::variant<PhotometricTable, std::string>& read) {
    const auto* table = std::get_if<PhotometricTable>(&read);
    if (!table) return;  // refused with a message
    const auto continuous = read_intensity_table(*table);
    const auto* intensity = std::get_if<IntensityTable>(&continuous);
    if (!intensity) return;  // refused with a message
    const double flux_lm = intensity->flux_lm();
    if (!std::isfinite(flux_lm) || flux_lm < 0) __builtin_trap();
    for (double gamma_rad = 0; gamma_rad <= M_PI; gamma_rad += M_PI / 7) {
        for (double c_rad = 0; c_rad < 2 * M_PI; c_rad += M_PI / 5) {
            const double cd = intensity->candela(gamma_rad, c_rad);
            if (!std::isfinite(cd) || cd < 0) __builtin_trap();
        }
    }
}

}  // namespace radiant::fuzz
