#include "radiant/proto/sensors_csv.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <system_error>

namespace radiant::proto {
namespace {

/// RFC 4180: a field with a comma, quote or line break is quoted, its quotes doubled.
void append_field(std::string& out, const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        out += text;
        return;
    }
    out += '"';
    for (const char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
}

/// The shortest text that reads back as `value` (already rounded, so it is short).
void append_number(std::string& out, double value) {
    std::array<char, 32> text{};
    const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc{}) out.append(text.data(), end);
}

}  // namespace

std::string sensors_csv(const std::vector<SensorResult>& sensors, int digits) {
    digits = std::clamp(digits, 1, kMaxDigits);
    std::string out = "set,index,x,y,z,nx,ny,nz,lux\r\n";
    for (const SensorResult& set : sensors) {
        std::string name;
        append_field(name, set.name);
        const std::size_t rows = std::min(set.points.size(), set.illuminance.size());
        for (std::size_t i = 0; i < rows; ++i) {
            out += name;
            out += ',';
            out += std::to_string(i);
            for (const Vec3& v : {set.points[i], set.normal}) {
                for (const double c : {v.x, v.y, v.z}) {
                    out += ',';
                    append_number(out, round_decimals(c, kLengthDecimals));
                }
            }
            out += ',';
            append_number(out, round_significant(set.illuminance[i], digits));
            out += "\r\n";
        }
    }
    return out;
}

}  // namespace radiant::proto
