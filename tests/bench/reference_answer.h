// What a benchmark case is compared with, and how far a result is from it.
//
// Validation scenes have exact answers (the checks of tests/data/scenes/expected.json); the
// RADIANCE room and the generated offices have per-point work-plane illuminances (RADIANCE, or
// a converged hierarchical solve). Errors are relative: for checks, each check's |got/want − 1|
// (energy balance |absorbed/emitted − 1|, a dark sensor its max / the lit mean); for sensors,
// |E − Eref| / mean(Eref) per point, so dark points (inside a shelf) do not divide by zero.
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/result.h"

namespace radiant::bench {

struct ReferenceAnswer {
    std::string source;               ///< "exact", "RADIANCE", "hierarchical 0.0005", …
    nlohmann::json checks;            ///< expected.json checks; null when comparing sensors
    std::string sensor;               ///< the sensor set compared point by point
    std::vector<double> illuminance;  ///< new lamps (no maintenance factor)
    /// The reference's own error estimate: a reference solve's, a RADIANCE reference's standard
    /// error (RMS over the mean) where its CSV gives one, else 0 (exact answers, and RADIANCE
    /// references without it); a row's measured error is the true one only within it.
    double error_estimate = 0;
};

struct RelativeError {
    double rms = std::numeric_limits<double>::quiet_NaN();
    double max = std::numeric_limits<double>::quiet_NaN();
};

/// A reference CSV (`x,y,z,irradiance`, perhaps with a fifth column `standard_error`, as
/// --radiance-reference writes them) as the reference of sensor set `sensor`; its error estimate
/// is the standard error's RMS over the mean illuminance where the file gives one, else 0.
ReferenceAnswer read_reference_csv(const std::filesystem::path& csv, const std::string& source,
                                   const std::string& sensor);

/// A sensor set's values for new lamps: its initial values where a maintenance factor applies.
/// References and results are compared on these, as RADIANCE knows no maintenance factor.
const std::vector<double>& new_lamp_illuminance(const SensorResult& set);

/// The error estimate of what `reference` scores: the sensor set's own where it has one (the
/// result's is the worst of its sets', which a darker band beside the work plane may set), else
/// the result's.
double scored_estimate(const Result& result, const ReferenceAnswer& reference);

/// RMS and largest relative error of `result` against `reference` (sensors: new-lamp values);
/// NaN when a check or the sensor set is missing from the result.
RelativeError relative_error(const Result& result, const ReferenceAnswer& reference);

}  // namespace radiant::bench
