// Checks a result against expected values in the format of tests/data/scenes/expected.json
// (`surface` means, `energy` balance, `sensor-max` darkness), shared by every test that reads
// such a file.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "radiant/result.h"
#include "scene_files.h"

namespace radiant::testing {

inline nlohmann::json read_json(const std::filesystem::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

/// Expects every check to hold; returns the largest relative error of the surface and energy
/// checks (so a caller can set it beside the solver's own error estimate).
inline double expect_checks(const Result& result, const nlohmann::json& checks,
                            const std::string& label) {
    double largest = 0;
    EXPECT_FALSE(checks.empty()) << "no checks for " << label;
    for (const auto& check : checks) {
        const std::string what = check["what"];
        if (what == "surface") {
            const auto* s = find_surface(result, check["surface"]);
            EXPECT_NE(s, nullptr) << label << ": no surface " << check["surface"];
            if (!s) continue;
            const double got = check["field"] == "average_irradiance" ? s->average_irradiance
                                                                      : s->average_radiosity;
            const double want = check["value"];
            largest = std::max(largest, std::abs(got / want - 1));
            EXPECT_NEAR(got / want, 1.0, check["rel_tol"].get<double>())
                << label << ": " << check["surface"] << " " << check["field"] << ": got " << got
                << ", want " << want << " (" << check["why"] << ")";
        } else if (what == "energy") {
            const double emitted = result.stats.emitted_flux_lm;
            largest = std::max(largest, std::abs(result.stats.absorbed_flux_lm / emitted - 1));
            EXPECT_NEAR(result.stats.absorbed_flux_lm / emitted, 1.0,
                        check["rel_tol"].get<double>())
                << label << ": absorbed " << result.stats.absorbed_flux_lm << " lm, emitted "
                << emitted;
        } else if (what == "sensor-max") {
            const auto* dark = find_sensor(result, check["sensor"]);
            const auto* lit = find_sensor(result, check["max_relative_to"]);
            EXPECT_NE(dark, nullptr) << label;
            EXPECT_NE(lit, nullptr) << label;
            if (!dark || !lit) continue;
            EXPECT_GT(lit->average, 0) << label;
            const double ratio = dark->max / lit->average;
            EXPECT_LE(ratio, check["value"].get<double>())
                << label << ": " << check["sensor"] << " max " << dark->max << " vs lit mean "
                << lit->average;
        } else {
            ADD_FAILURE() << label << ": unknown check kind " << what;
        }
    }
    return largest;
}

}  // namespace radiant::testing
