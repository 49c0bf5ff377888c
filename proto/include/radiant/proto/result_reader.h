// radiant-result/1 JSON → radiant::Result, for drawing and exporting a stored result without
// solving again (`radiant render/plan --result`, the service's pictures and CSV).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::proto {

struct ResultReadOutcome {
    std::optional<Result> result;   ///< set only when `problems` is empty
    std::vector<Problem> problems;  ///< each with the JSON pointer of the offending value
    bool ok() const { return problems.empty(); }
};

/// Reads what a result's pictures and CSV need: the scene name, status and error, the sensor
/// sets (name, normal, points, illuminance and their statistics), the surfaces and, when
/// present, the mesh. Checks types, finiteness and every index and length the pictures rely on
/// (points and illuminance of a set agree; triangles name existing vertices and surfaces), so a
/// damaged file is refused, never drawn out of bounds. Keys it does not need are ignored, so
/// newer results still read. "running" documents read as status `stopped`. Never throws for bad
/// input. Thread-safe.
ResultReadOutcome read_result(std::string_view json_text);

}  // namespace radiant::proto
