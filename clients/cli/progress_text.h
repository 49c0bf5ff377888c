// The progress lines the CLI draws on a terminal — of a local solve and of a service job's
// `progress` events — with the error estimate shown only once the solve has one.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace radiant::cli {

/// The error estimate as progress lines show it: "-" (padded to the same width) until the solve
/// has one.
std::string estimate_text(std::optional<double> estimate);

/// The bar `radiant submit --wait` and `radiant watch` draw from a `progress` event's data, for
/// a terminal line (the caller adds the \r). A member that is missing or null shows as unknown.
std::string service_progress_line(const nlohmann::json& progress);

}  // namespace radiant::cli
