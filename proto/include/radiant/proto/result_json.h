// radiant::Result → radiant-result/1 JSON (proto/schema/result.schema.json).
#pragma once

#include <nlohmann/json.hpp>

#include "radiant/proto/significant_digits.h"
#include "radiant/result.h"

namespace radiant::proto {

/// The radiant-result/1 document of `result`. The engine guarantees finite values; should one
/// slip through anyway, the answer is a `failed` document saying where, never a NaN or null.
/// Values carry `digits` significant digits (kMaxDigits: unrounded); error estimates, lengths and
/// counts are rounded as significant_digits.h says. Thread-safe.
nlohmann::json result_to_json(const Result& result, int digits = kDefaultDigits);

/// The `sensors` array of a radiant-result/1 document.
nlohmann::json sensors_to_json(const std::vector<SensorResult>& sensors,
                               int digits = kDefaultDigits);

/// The `units` object of every radiant-result/1 document: the unit of each kind of quantity.
nlohmann::json result_units_json();

}  // namespace radiant::proto
