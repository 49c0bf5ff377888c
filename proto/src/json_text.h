// JSON text → DOM, turning syntax errors into contract problems (line and column, or the
// pointer of a number that overflows) instead of exceptions.
#pragma once

#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "radiant/scene.h"

namespace radiant::proto {

/// Parses `text`; object members keep their document order. Never throws for bad input.
std::variant<nlohmann::ordered_json, Problem> parse_json_text(std::string_view text);

}  // namespace radiant::proto
