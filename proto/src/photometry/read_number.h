// One number of a photometric file, strictly: the whole token, finite.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace radiant::proto {

/// The token as a finite number, or nothing. EULUMDAT writers in many locales use a decimal
/// comma, so `comma_decimal` reads "0,5" as 0.5.
inline std::optional<double> read_number(std::string_view token, bool comma_decimal = false) {
    std::string text(token);
    if (comma_decimal) {
        for (char& c : text) c = c == ',' ? '.' : c;
    }
    if (!text.empty() && text.front() == '+') text.erase(0, 1);
    double value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

}  // namespace radiant::proto
