#include "photometry/ies_reader.h"

#include <cmath>
#include <vector>

#include "photometry/read_number.h"

namespace radiant::proto {
namespace {

struct Token {
    std::string_view text;
    int line = 0;
};

/// Thrown inside read_ies only, caught at its end: one refusal with its line.
struct Refusal {
    std::string message;
};

[[noreturn]] void refuse(int line, const std::string& message) {
    throw Refusal{"ies: line " + std::to_string(line) + ": " + message};
}

std::string_view trimmed(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string format_number(double x) {
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
}

/// The numbers after TILT=NONE, separated by blanks or commas, each with its line.
class Numbers {
public:
    Numbers(std::vector<Token> tokens, int last_line)
        : tokens_(std::move(tokens)), last_line_(last_line) {}

    bool done() const { return next_ == tokens_.size(); }
    int line() const { return done() ? last_line_ : tokens_[next_].line; }
    const Token& peek() const { return tokens_[next_]; }

    /// The next number; `missing` says what was expected when the file ends.
    double take(const std::string& missing) {
        if (done()) refuse(last_line_, missing);
        const Token& t = tokens_[next_++];
        const auto value = read_number(t.text);
        if (!value) refuse(t.line, "\"" + std::string(t.text) + "\" is not a number");
        return *value;
    }

    int take_whole(const char* what, int min) {
        const int at = line();
        const double x = take(std::string("missing ") + what);
        if (std::floor(x) != x || x < min || x > 1e6) {
            refuse(at, std::string(what) + " must be a whole number >= " + std::to_string(min) +
                           " (found " + format_number(x) + ")");
        }
        return static_cast<int>(x);
    }

private:
    std::vector<Token> tokens_;
    std::size_t next_ = 0;
    int last_line_;
};

/// `count` increasing angles; a value that does not increase starts the next list, so the list
/// was short.
std::vector<double> read_angles(Numbers& numbers, int count, const char* what) {
    std::vector<double> angles;
    for (int k = 0; k < count; ++k) {
        const int at = numbers.line();
        const double a = numbers.take("expected " + std::to_string(count) + " " + what +
                                      ", found " + std::to_string(k));
        if (!angles.empty() && a <= angles.back()) {
            refuse(at, "expected " + std::to_string(count) + " " + what + ", found " +
                           std::to_string(k) + " (" + format_number(a) + " does not increase)");
        }
        angles.push_back(a);
    }
    return angles;
}

/// LM-63's luminous opening (width along C90, length along C0, height up; negative values name
/// round shapes: −d 0 0 or −d −d 0 a disc, −d −d h a vertical cylinder, −d −d −d a sphere).
/// Horizontal cylinders and ellipsoids become the box around them.
LuminousShape opening(double width, double length, double height) {
    LuminousShape s;
    if (width < 0 && height < 0 && (length < 0 || length == 0) &&
        (length == 0 || length == width) && height == width) {
        s.sphere = true;
        s.length = s.width = s.height = -width;
        return s;
    }
    s.round = width < 0 && length <= 0 && height >= 0;
    s.width = std::abs(width);
    s.length = length == 0 && s.round ? s.width : std::abs(length);
    s.height = std::abs(height);
    // A horizontal cylinder (one of width or length 0, height −d): d wide across its axis.
    if (height < 0 && width == 0) s.width = s.height;
    if (height < 0 && length == 0) s.length = s.height;
    return s;
}

PhotometricTable read(std::string_view text) {
    std::vector<std::string_view> lines;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    std::size_t tilt = 0;
    while (tilt < lines.size() && trimmed(lines[tilt]).rfind("TILT=", 0) != 0) ++tilt;
    if (tilt == lines.size()) throw Refusal{"ies: no TILT= line: not an IES LM-63 file"};
    const std::string_view tilt_value = trimmed(lines[tilt]).substr(5);
    if (tilt_value != "NONE") {
        refuse(static_cast<int>(tilt) + 1,
               "TILT=" + std::string(tilt_value) + " is not supported (only TILT=NONE)");
    }
    std::vector<Token> tokens;
    for (std::size_t i = tilt + 1; i < lines.size(); ++i) {
        const std::string_view line = lines[i];
        for (std::size_t p = 0; p < line.size();) {
            p = line.find_first_not_of(" \t\r,", p);
            if (p == std::string_view::npos) break;
            const std::size_t e = std::min(line.find_first_of(" \t\r,", p), line.size());
            tokens.push_back({line.substr(p, e - p), static_cast<int>(i) + 1});
            p = e;
        }
    }
    Numbers numbers(std::move(tokens), static_cast<int>(lines.size()));

    numbers.take_whole("number of lamps", 1);
    const int lumens_line = numbers.line();
    const double lumens = numbers.take("missing lumens per lamp");
    if (!(lumens > 0 || lumens == -1)) {
        refuse(lumens_line, "lumens per lamp must be > 0, or -1 for absolute photometry");
    }
    const int multiplier_line = numbers.line();
    const double multiplier = numbers.take("missing candela multiplier");
    if (!(multiplier > 0)) refuse(multiplier_line, "the candela multiplier must be > 0");
    const int vertical = numbers.take_whole("number of vertical angles", 2);
    const int horizontal = numbers.take_whole("number of horizontal angles", 1);
    const int type_line = numbers.line();
    const int type = numbers.take_whole("photometric type", 1);
    if (type != 1) {
        refuse(type_line, std::string("photometric type ") +
                              (type == 2   ? "B"
                               : type == 3 ? "A"
                                           : "?") +
                              " is not supported (only type C, 1)");
    }
    const int units_line = numbers.line();
    const int units = numbers.take_whole("units type", 1);
    if (units != 1 && units != 2) refuse(units_line, "units type must be 1 (feet) or 2 (metres)");
    // The luminous opening: a point source has none, but the numbers must be there.
    const double to_m = units == 1 ? 0.3048 : 1.0;
    const double width = numbers.take("missing width") * to_m;
    const double length = numbers.take("missing length") * to_m;
    const double height = numbers.take("missing height") * to_m;
    const int ballast_line = numbers.line();
    const double ballast = numbers.take("missing ballast factor");
    if (!(ballast > 0)) refuse(ballast_line, "the ballast factor must be > 0");
    numbers.take("missing ballast-lamp factor");
    numbers.take("missing input watts");

    PhotometricTable table;
    table.luminous = opening(width, length, height);
    table.gamma_deg = read_angles(numbers, vertical, "vertical angles");
    const int c_line = numbers.line();
    table.c_deg = read_angles(numbers, horizontal, "horizontal angles");
    const double first = table.c_deg.front(), last = table.c_deg.back();
    const bool known = (first == 0 && (horizontal == 1 || last == 90 || last == 180 ||
                                       (last > 180 && last <= 360))) ||
                       (first == 90 && last == 270);
    if (!known) {
        refuse(c_line, "horizontal angles must run 0, 0–90, 0–180, 90–270 or 0–360 (found " +
                           format_number(first) + "–" + format_number(last) + ")");
    }
    if (table.gamma_deg.front() < 0 || table.gamma_deg.back() > 180) {
        refuse(c_line, "vertical angles of type C must lie within 0–180");
    }
    for (const double c : table.c_deg) {
        for (int k = 0; k < vertical; ++k) {
            const int at = numbers.line();
            const double cd = numbers.take("expected " + std::to_string(vertical) +
                                           " candela values at horizontal angle " +
                                           format_number(c) + ", found " + std::to_string(k));
            if (cd < 0) refuse(at, "candela value " + format_number(cd) + " is negative");
            table.candela.push_back(cd * multiplier * ballast);
        }
    }
    if (!numbers.done()) {
        refuse(numbers.line(), "unexpected value \"" + std::string(numbers.peek().text) +
                                   "\" after the candela values");
    }
    return table;
}

}  // namespace

std::variant<PhotometricTable, std::string> read_ies(std::string_view text) {
    try {
        return read(text);
    } catch (const Refusal& r) {
        return r.message;
    }
}

}  // namespace radiant::proto
