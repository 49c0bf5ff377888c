#include "radiant/picture/false_colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "picture/text.h"

namespace radiant::picture {
namespace {

struct Stop {
    double at;
    double r, g, b;  ///< display (sRGB-encoded) values in [0, 1]
};

constexpr std::array<Stop, 7> kRamp{{{0.00, 0.19, 0.07, 0.23},
                                     {0.15, 0.27, 0.42, 0.93},
                                     {0.35, 0.10, 0.82, 0.77},
                                     {0.50, 0.35, 0.98, 0.36},
                                     {0.65, 0.83, 0.93, 0.20},
                                     {0.80, 0.98, 0.60, 0.15},
                                     {1.00, 0.70, 0.05, 0.02}}};

constexpr int kBarWidth = 10;  // legend bar width, per unit of scale
constexpr int kTicks = 5;
constexpr Rgb kInk{20, 20, 20};

std::uint8_t byte(double v) { return static_cast<std::uint8_t>(std::lround(255 * v)); }

/// The label of tick `tick` of [0, max], with as many decimals as the tick step needs, so that
/// all labels of one legend agree ("0.5 1.0 1.5", "0 50 100").
std::string tick_label(double max, int tick) {
    const double step = max / kTicks;
    int decimals = 0;
    while (decimals < 4) {
        const double scaled = step * std::pow(10.0, decimals);
        if (std::abs(scaled - std::round(scaled)) <= 1e-9 * scaled) break;
        ++decimals;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, step * tick);
    return text;
}

}  // namespace

Rgb false_colour(double value, double max) {
    double t = max > 0 && value > 0 ? value / max : 0;  // NaN lands at 0
    t = std::min(t, 1.0);
    std::size_t i = 1;
    while (i + 1 < kRamp.size() && kRamp[i].at < t) ++i;
    const Stop& a = kRamp[i - 1];
    const Stop& b = kRamp[i];
    const double w = (t - a.at) / (b.at - a.at);
    return {byte(a.r + w * (b.r - a.r)), byte(a.g + w * (b.g - a.g)), byte(a.b + w * (b.b - a.b))};
}

double round_scale_max(double value) {
    if (!(value > 0) || !std::isfinite(value)) return 1;
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (const double step : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        // The relative slack keeps 500 at 500 despite rounding in log10/pow.
        if (step * decade >= value * (1 - 1e-12)) return step * decade;
    }
    return 10 * decade;
}

std::string short_number(double value) {
    char text[32];
    const double magnitude = std::abs(value);
    const int decimals = magnitude >= 100 || magnitude == 0 ? 0 : magnitude >= 10 ? 1 : 2;
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

int legend_width(double max, int scale) {
    int widest = 0;
    for (int tick = 0; tick <= kTicks; ++tick) {
        widest = std::max(widest, text_width(tick_label(max, tick), scale));
    }
    return (kBarWidth + 4) * scale + widest + 2 * scale;
}

void draw_legend(Image& image, int x, int y, int height, double max, const std::string& unit,
                 int scale) {
    const int title = 12 * scale;
    const int top = y + title;
    const int bar_height = std::max(height - title - 4 * scale, kTicks);
    const int bar_width = kBarWidth * scale;
    draw_text(image, x, y, unit, kInk, scale);
    for (int row = 0; row < bar_height; ++row) {
        const double value = max * (1 - (row + 0.5) / bar_height);
        image.fill(x, top + row, x + bar_width, top + row + 1, false_colour(value, max));
    }
    image.outline(x, top, x + bar_width, top + bar_height, kInk);
    for (int tick = 0; tick <= kTicks; ++tick) {
        const int row = top + (bar_height - 1) * (kTicks - tick) / kTicks;
        image.fill(x + bar_width, row, x + bar_width + 3 * scale, row + 1, kInk);
        draw_text(image, x + bar_width + 4 * scale, row - 3 * scale, tick_label(max, tick), kInk,
                  scale);
    }
}

}  // namespace radiant::picture
