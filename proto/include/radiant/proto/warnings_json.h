// Warnings (radiant/warnings.h) as JSON and as the command line prints them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/warnings.h"

namespace radiant::proto {

/// The `warnings` array of a radiant-result/1 document and of a job: {code, message, pointer}.
nlohmann::json warnings_to_json(const std::vector<Warning>& warnings);

/// "message [code]": a warning as a refusal's message.
std::string message_with_code(const Warning& warning);

/// "FILE: /pointer: message [code]": one line, as `radiant solve` and `validate` print them.
std::string format_warning(const std::string& file, const Warning& warning);

}  // namespace radiant::proto
