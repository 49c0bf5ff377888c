#include "progress_text.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>

namespace radiant::cli {
namespace {

/// `json[key]` when it is a number (an estimate is null until the solve has one).
std::optional<double> number(const nlohmann::json& json, const char* key) {
    const auto it = json.find(key);
    if (it == json.end() || !it->is_number()) return std::nullopt;
    return it->get<double>();
}

}  // namespace

std::string estimate_text(std::optional<double> estimate) {
    if (!estimate) return "    -    ";
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", *estimate);
    return text;
}

std::string service_progress_line(const nlohmann::json& progress) {
    constexpr int kWidth = 30;
    const double fraction = std::clamp(number(progress, "fraction").value_or(0.0), 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kWidth + 0.5);
    const auto stage = progress.find("stage");
    char line[256];
    std::snprintf(
        line, sizeof line, "[%s%s] %5.1f%%  %-12s it %-6.0f err %s  %.1fs ",
        std::string(static_cast<std::size_t>(filled), '#').c_str(),
        std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(), 100 * fraction,
        stage != progress.end() && stage->is_string() ? stage->get_ref<const std::string&>().c_str()
                                                      : "",
        number(progress, "iterations").value_or(0.0),
        estimate_text(number(progress, "error_estimate")).c_str(),
        number(progress, "elapsed_seconds").value_or(0.0));
    return line;
}

}  // namespace radiant::cli
