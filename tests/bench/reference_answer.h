// What a benchmark case is compared with, and how far a result is from it.
//
// Validation scenes have exact answers (the checks of tests/data/scenes/expected.json); the
// RADIANCE room and the generated offices have per-point work-plane illuminances (RADIANCE, or
// a converged hierarchical solve). Errors are relative: for checks, each check's |got/want − 1|
// (energy balance |absorbed/emitted − 1|, a dark sensor its max / the lit mean); for sensors,
// |E − Eref| / mean(Eref) per point, so dark points (inside a shelf) do not divide by zero.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/result.h"

namespace radiant::bench {

struct ReferenceAnswer {
    std::string source;     ///< "exact", "RADIANCE", "hierarchical 0.0005", …
    nlohmann::json checks;  ///< expected.json checks; null when comparing sensors
    std::string sensor;     ///< the sensor set compared point by point
    std::vector<double> illuminance;
};

struct RelativeError {
    double rms = std::numeric_limits<double>::quiet_NaN();
    double max = std::numeric_limits<double>::quiet_NaN();
};

/// RMS and largest relative error of `result` against `reference`; NaN when a check or the
/// sensor set is missing from the result.
RelativeError relative_error(const Result& result, const ReferenceAnswer& reference);

}  // namespace radiant::bench
