#include "radiant/proto/significant_digits.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace radiant::proto {
namespace {

/// Room for any double in fixed notation (DBL_MAX has 309 digits) and its sign.
using Text = std::array<char, 400>;

/// `value` in scientific notation with `digits` significant digits ("1.235e+02"); empty when
/// to_chars fails (it does not for a finite double and this buffer).
std::string_view scientific(double value, int digits, Text& text) {
    const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value,
                                         std::chars_format::scientific, std::max(digits, 1) - 1);
    return ec == std::errc{} ? std::string_view(text.data(), end) : std::string_view();
}

/// The double that `text` spells, or `fallback`.
double read_back(std::string_view text, double fallback) {
    double out = fallback;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    if (text.empty() || ec != std::errc{} || ptr != text.data() + text.size()) return fallback;
    return out == 0 ? 0.0 : out;  // −0 is written as 0: every reader takes it so anyway
}

}  // namespace

double round_significant(double value, int digits) {
    if (!std::isfinite(value) || digits >= kMaxDigits) return value == 0 ? 0.0 : value;
    // Decimal rounding through text: scaling by powers of ten would add binary error.
    Text text{};
    return read_back(scientific(value, digits, text), value);
}

double round_up_significant(double value, int digits) {
    const double nearest = round_significant(value, digits);
    if (!std::isfinite(value) || std::abs(nearest) >= std::abs(value)) return nearest;
    // One unit of the last kept digit further from zero; its place comes from the exponent.
    Text text{};
    const std::string_view s = scientific(nearest, digits, text);
    const std::size_t e = s.find('e');
    if (e == std::string_view::npos) return nearest;
    const int exponent = std::atoi(std::string(s.substr(e + 1)).c_str());
    const double step = std::pow(10.0, exponent - (std::max(digits, 1) - 1));
    return round_significant(nearest + std::copysign(step, value), digits);
}

double round_decimals(double value, int decimals) {
    if (!std::isfinite(value)) return value;
    Text text{};
    const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value,
                                         std::chars_format::fixed, decimals);
    if (ec != std::errc{}) return value;
    return read_back(std::string_view(text.data(), end), value);
}

}  // namespace radiant::proto
