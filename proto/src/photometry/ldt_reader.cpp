#include "photometry/ldt_reader.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "photometry/read_number.h"

namespace radiant::proto {
namespace {

/// Thrown inside read_ldt only, caught at its end: one refusal with its line.
struct Refusal {
    std::string message;
};

[[noreturn]] void refuse(std::size_t line, const std::string& message) {
    throw Refusal{"ldt: line " + std::to_string(line) + ": " + message};
}

/// EULUMDAT is one value per line at fixed positions; lines count from 1.
class Lines {
public:
    explicit Lines(std::string_view text) {
        for (std::size_t start = 0; start < text.size();) {
            const std::size_t end = std::min(text.find('\n', start), text.size());
            std::string_view line = text.substr(start, end - start);
            const auto first = line.find_first_not_of(" \t\r");
            line = first == std::string_view::npos
                       ? std::string_view{}
                       : line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
            lines_.push_back(line);
            start = end + 1;
        }
    }

    double number(std::size_t line, const char* what) const {
        if (line > lines_.size()) {
            refuse(lines_.size(), std::string("the file ends before line ") + std::to_string(line) +
                                      " (" + what + ")");
        }
        const std::string_view text = lines_[line - 1];
        const auto value = read_number(text, true);
        if (!value) {
            refuse(line, std::string(what) + ": \"" + std::string(text) + "\" is not a number");
        }
        return *value;
    }

    int whole(std::size_t line, const char* what, int min, int max) const {
        const double x = number(line, what);
        if (std::floor(x) != x || x < min || x > max) {
            refuse(line, std::string(what) + " must be a whole number in " + std::to_string(min) +
                             "–" + std::to_string(max));
        }
        return static_cast<int>(x);
    }

    std::size_t size() const { return lines_.size(); }

private:
    std::vector<std::string_view> lines_;
};

// Line numbers of the fixed header (EULUMDAT, Stockmar 1990).
constexpr std::size_t kTypeLine = 2, kSymmetryLine = 3, kPlaneCountLine = 4, kGammaCountLine = 6,
                      kLuminousLengthLine = 16, kLuminousWidthLine = 17, kLuminousHeightLine = 18,
                      kConversionLine = 24, kLampSetsLine = 26;

/// The luminous area (lines 16–21, mm): its length runs along the C90 plane (a linear
/// luminaire's axis), its width b1 along C0 (0 for a disc of diameter `length`); the four
/// heights of luminous sides (C0, C90, C180, C270) are averaged.
LuminousShape luminous_area(const Lines& lines) {
    const double mm = 1e-3;
    const double length = lines.number(kLuminousLengthLine, "length of luminous area") * mm;
    const double width = lines.number(kLuminousWidthLine, "width of luminous area") * mm;
    double height = 0;
    for (std::size_t k = 0; k < 4; ++k)
        height += lines.number(kLuminousHeightLine + k, "height of luminous area") * mm / 4;
    for (const auto& [line, value] :
         {std::pair{kLuminousLengthLine, length}, {kLuminousWidthLine, width}}) {
        if (value < 0) refuse(line, "luminous area dimensions must be >= 0");
    }
    if (height < 0) refuse(kLuminousHeightLine, "luminous area heights must be >= 0");
    LuminousShape s;
    s.round = width == 0;
    s.length = s.round ? length : width;
    s.width = length;
    s.height = height;
    return s;
}

PhotometricTable read(std::string_view text) {
    const Lines lines(text);
    lines.whole(kTypeLine, "type indicator Ityp", 0, 3);
    const int isym = lines.whole(kSymmetryLine, "symmetry indicator Isym", 0, 4);
    const int mc = lines.whole(kPlaneCountLine, "number of C-planes Mc", 1, 3600);
    const int ng = lines.whole(kGammaCountLine, "number of intensities per C-plane Ng", 2, 3600);
    const double conversion = lines.number(kConversionLine, "conversion factor");
    if (!(conversion > 0)) refuse(kConversionLine, "the conversion factor must be > 0");
    const auto sets =
        static_cast<std::size_t>(lines.whole(kLampSetsLine, "number of lamp sets", 1, 20));
    const std::size_t flux_line = kLampSetsLine + 1 + 2 * sets;
    const double lamp_flux = lines.number(flux_line, "total luminous flux of lamps");
    if (!(lamp_flux > 0)) refuse(flux_line, "the lamps' total luminous flux must be > 0");
    const std::size_t c_line = kLampSetsLine + 1 + 6 * sets + 10;
    const std::size_t gamma_line = c_line + static_cast<std::size_t>(mc);
    const std::size_t data_line = gamma_line + static_cast<std::size_t>(ng);

    // Which stored planes the symmetry keeps: first index and count (0-based, wrapping).
    if ((isym == 2 && mc % 2 != 0) || ((isym == 3 || isym == 4) && mc % 4 != 0)) {
        refuse(kPlaneCountLine, "Mc = " + std::to_string(mc) + " does not divide as Isym = " +
                                    std::to_string(isym) + " needs");
    }
    int first = 0, count = mc;
    if (isym == 1) count = 1;
    if (isym == 2) count = mc / 2 + 1;
    if (isym == 3) first = 3 * mc / 4, count = mc / 2 + 1;
    if (isym == 4) count = mc / 4 + 1;

    std::vector<double> c_all;
    for (int k = 0; k < mc; ++k) {
        c_all.push_back(lines.number(c_line + static_cast<std::size_t>(k), "C-plane angle"));
    }
    PhotometricTable table;
    table.luminous = luminous_area(lines);
    for (int k = 0; k < ng; ++k) {
        const std::size_t at = gamma_line + static_cast<std::size_t>(k);
        const double g = lines.number(at, "gamma angle");
        if (!table.gamma_deg.empty() && g <= table.gamma_deg.back()) {
            refuse(at, "gamma angles must increase");
        }
        table.gamma_deg.push_back(g);
    }
    const std::size_t expected = static_cast<std::size_t>(count) * static_cast<std::size_t>(ng);
    if (lines.size() < data_line + expected - 1) {
        refuse(lines.size(),
               "expected " + std::to_string(expected) + " luminous intensities, found " +
                   std::to_string(lines.size() >= data_line ? lines.size() - data_line + 1 : 0));
    }
    std::vector<std::pair<double, std::vector<double>>> planes;
    for (int p = 0; p < count; ++p) {
        double c = c_all[static_cast<std::size_t>((first + p) % mc)];
        // Isym 3 stores C270 → C0 → C90; the table holds the mirror half C90 → C270.
        if (isym == 3) c = std::fmod(540 - c, 360.0);
        if (isym == 1) c = 0;
        auto& plane = planes.emplace_back(c, std::vector<double>{});
        for (int k = 0; k < ng; ++k) {
            const std::size_t at = data_line +
                                   static_cast<std::size_t>(p) * static_cast<std::size_t>(ng) +
                                   static_cast<std::size_t>(k);
            const double v = lines.number(at, "luminous intensity");
            if (v < 0) refuse(at, "luminous intensity must be >= 0");
            plane.second.push_back(v * lamp_flux / 1000 * conversion);
        }
    }
    std::sort(planes.begin(), planes.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [c, values] : planes) {
        if (!table.c_deg.empty() && c <= table.c_deg.back()) {
            refuse(c_line, "C-plane angles must increase from 0 (or fit Isym = " +
                               std::to_string(isym) + ")");
        }
        table.c_deg.push_back(c);
        table.candela.insert(table.candela.end(), values.begin(), values.end());
    }
    return table;
}

}  // namespace

std::variant<PhotometricTable, std::string> read_ldt(std::string_view text) {
    try {
        return read(text);
    } catch (const Refusal& r) {
        return r.message;
    }
}

}  // namespace radiant::proto
