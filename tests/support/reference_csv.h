// Test helpers: the sensor references made outside the solver (read by reference_csv_file.h;
// RADIANCE runs, see tests/data/radiance/README.md), and the error radiant-bench scores against
// them.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

#include "radiant/vec3.h"
#include "reference_csv_file.h"

namespace radiant::testing {

struct ReferencePoints {
    std::vector<Vec3> points;         ///< metres
    std::vector<double> illuminance;  ///< lux
};

/// Reads a reference; fails the test when the file is missing or its header is not the CSV's.
inline ReferencePoints read_reference_csv(const std::filesystem::path& file) {
    ReferenceCsv csv = read_reference_csv_file(file);
    EXPECT_TRUE(csv.header == kReferenceCsvHeader || csv.header == kReferenceCsvHeaderWithError)
        << file;
    return {std::move(csv.points), std::move(csv.illuminance)};
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
