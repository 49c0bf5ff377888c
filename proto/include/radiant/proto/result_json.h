// radiant::Result → radiant-result/1 JSON (proto/schema/result.schema.json).
#pragma once

#include <nlohmann/json.hpp>

#include "radiant/result.h"

namespace radiant::proto {

/// The radiant-result/1 document of `result`. The engine guarantees finite values; should one
/// slip through anyway, the answer is a `failed` document saying where, never a NaN or null.
/// Thread-safe.
nlohmann::json result_to_json(const Result& result);

/// The `sensors` array of a radiant-result/1 document.
nlohmann::json sensors_to_json(const std::vector<SensorResult>& sensors);

}  // namespace radiant::proto
