// Checks a result against expected values in the format of tests/data/scenes/expected.json
// (`surface` means, `energy` balance, `sensor-max` darkness), shared by every test that reads
// such a file.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/result.h"
#include "scene_files.h"

namespace radiant::testing {

inline nlohmann::json read_json(const std::filesystem::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

/// The scene names of an expected-values file, in its order: the parameters of a test per scene.
inline std::vector<std::string> scene_names(const nlohmann::json& all) {
    std::vector<std::string> names;
    for (auto it = all.cbegin(); it != all.cend(); ++it) names.push_back(it.key());
    return names;
}

/// A scene name as a test name: every character but letters and digits becomes '_'.
inline std::string test_name(std::string name) {
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

/// Relative error of a `surface` or `energy` check; nullopt for other kinds or a missing surface.
inline std::optional<double> relative_error(const Result& result, const nlohmann::json& check) {
    const std::string what = check["what"];
    if (what == "energy") {
        return std::abs(result.stats.absorbed_flux_lm / result.stats.emitted_flux_lm - 1);
    }
    if (what != "surface") return std::nullopt;
    const auto* s = find_surface(result, check["surface"]);
    if (!s) return std::nullopt;
    const double got =
        check["field"] == "average_irradiance" ? s->average_irradiance : s->average_radiosity;
    return std::abs(got / check["value"].get<double>() - 1);
}

/// The largest relative error of the surface and energy checks.
inline double largest_relative_error(const Result& result, const nlohmann::json& checks) {
    double largest = 0;
    for (const auto& check : checks)
        largest = std::max(largest, relative_error(result, check).value_or(0));
    return largest;
}

/// The RMS of the surface and energy checks' relative errors: the true error as radiant-bench
/// measures it on scenes without a reference sensor set, what the error estimate bounds.
inline double rms_relative_error(const Result& result, const nlohmann::json& checks) {
    double squares = 0;
    std::size_t count = 0;
    for (const auto& check : checks) {
        if (const std::optional<double> e = relative_error(result, check)) {
            squares += *e * *e;
            ++count;
        }
    }
    return count > 0 ? std::sqrt(squares / static_cast<double>(count)) : 0.0;
}

/// Expects every check to hold.
inline void expect_checks(const Result& result, const nlohmann::json& checks,
                          const std::string& label) {
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
            EXPECT_LE(*relative_error(result, check), check["rel_tol"].get<double>())
                << label << ": " << check["surface"] << " " << check["field"] << ": got " << got
                << ", want " << want << " (" << check["why"] << ")";
        } else if (what == "energy") {
            EXPECT_LE(*relative_error(result, check), check["rel_tol"].get<double>())
                << label << ": absorbed " << result.stats.absorbed_flux_lm << " lm, emitted "
                << result.stats.emitted_flux_lm;
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
}

}  // namespace radiant::testing
