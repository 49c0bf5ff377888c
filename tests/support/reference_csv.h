// Test helpers: the sensor references made outside the solver (`x,y,z,irradiance` CSV, one row
// per point of a scene's first sensor set, perhaps with a fifth column, the standard error:
// RADIANCE runs, see tests/data/radiance/README.md),
// and the error radiant-bench scores against them.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "radiant/vec3.h"

namespace radiant::testing {

struct ReferencePoints {
    std::vector<Vec3> points;         ///< metres
    std::vector<double> illuminance;  ///< lux
};

/// Reads a reference; fails the test when the file is missing or its header is not the CSV's.
inline ReferencePoints read_reference_csv(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_TRUE(line == "x,y,z,irradiance" || line == "x,y,z,irradiance,standard_error") << file;
    ReferencePoints out;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        double v[4];
        std::size_t at = 0;
        for (double& value : v) {
            std::size_t used = 0;
            value = std::stod(line.substr(at), &used);
            at += used + 1;
        }
        out.points.push_back({v[0], v[1], v[2]});
        out.illuminance.push_back(v[3]);
    }
    return out;
}

/// RMS difference over the reference's mean, as radiant-bench measures a work plane's error.
inline double normalised_rms(const std::vector<double>& got, const std::vector<double>& reference) {
    double sum_sq = 0, sum_ref = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        sum_sq += (got[i] - reference[i]) * (got[i] - reference[i]);
        sum_ref += reference[i];
    }
    const double n = static_cast<double>(reference.size());
    return std::sqrt(sum_sq / n) / (sum_ref / n);
}

}  // namespace radiant::testing
