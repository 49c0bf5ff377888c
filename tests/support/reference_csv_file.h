// The sensor references made outside the solver, as files: `x,y,z,irradiance` CSV, one row per
// point of a scene's first sensor set, with a fifth column `standard_error` (lux) where
// `radiant-bench --radiance-reference` combined several runs. Shared by the tests and the
// benchmark, so it does not depend on GoogleTest.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "radiant/vec3.h"

namespace radiant::testing {

inline constexpr const char* kReferenceCsvHeader = "x,y,z,irradiance";
inline constexpr const char* kReferenceCsvHeaderWithError = "x,y,z,irradiance,standard_error";

struct ReferenceCsv {
    std::string header;                  ///< the file's first line
    std::vector<Vec3> points;            ///< metres
    std::vector<double> illuminance;     ///< lux
    std::vector<double> standard_error;  ///< lux; empty without the fifth column
};

inline ReferenceCsv read_reference_csv_file(const std::filesystem::path& file) {
    std::ifstream in(file);
    ReferenceCsv out;
    std::getline(in, out.header);
    const bool with_error = out.header == kReferenceCsvHeaderWithError;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::vector<double> columns;
        std::istringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) columns.push_back(std::stod(cell));
        out.points.push_back({columns.at(0), columns.at(1), columns.at(2)});
        out.illuminance.push_back(columns.at(3));
        if (with_error) out.standard_error.push_back(columns.at(4));
    }
    return out;
}

}  // namespace radiant::testing
