// JSON text → DOM within a JsonBudget, turning syntax errors into contract problems (line and
// column, or the pointer of the value at fault) instead of exceptions.
#pragma once

#include <optional>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "radiant/proto/json_budget.h"
#include "radiant/scene.h"

namespace radiant::proto {

/// Why a text was refused: not JSON (syntax, invalid UTF-8, a duplicate key, a number that
/// overflows), or JSON that asks for more than the budget allows.
struct JsonRefusal {
    Problem problem;
    bool over_budget = false;
};

/// Parses `text`; object members keep their document order. Time is linear in the text's size
/// (object members are appended, and duplicates found by sorting once the object ends). Never
/// throws for bad input.
std::variant<nlohmann::ordered_json, JsonRefusal> parse_json_text(std::string_view text,
                                                                  const JsonBudget& budget = {});

/// Reads `text` against `budget` without building it: for JSON handed to another parser.
std::optional<JsonRefusal> check_json_text(std::string_view text, const JsonBudget& budget = {});

}  // namespace radiant::proto
