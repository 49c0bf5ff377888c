// §2.7a of the validation notes: the unit cube with an emitting ceiling (E = 1, ρ = 0.5 on every
// face), whose converged face means are known; checked for the dense, matrix-free and
// hierarchical solvers alike.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "radiant/result.h"
#include "scene_files.h"

namespace radiant::testing {

/// Every face's mean radiosity within 0.5 % of the converged value.
inline void expect_cube_ceiling_face_means(const Result& r, const std::string& label) {
    const std::vector<std::pair<std::string, double>> faces{
        {"floor", 0.171216},      {"ceiling", 1.10436},    {"wall-south", 0.181107},
        {"wall-north", 0.181107}, {"wall-west", 0.181107}, {"wall-east", 0.181107}};
    for (const auto& [name, exact] : faces) {
        const auto* s = find_surface(r, name);
        ASSERT_NE(s, nullptr) << label << " " << name;
        EXPECT_NEAR(s->average_radiosity / exact, 1.0, 0.005)
            << label << " " << name << ": B " << s->average_radiosity << ", exact " << exact;
    }
}

}  // namespace radiant::testing
