// The false-colour scale of lux pictures: a blue → green → yellow → red ramp over [0, max] and
// its legend (a bar with labelled ticks), so a picture can be read without the numbers.
#pragma once

#include <string>

#include "radiant/picture/image.h"

namespace radiant::picture {

/// Colour of `value` on a linear scale [0, max]; values outside are clamped to the ends.
Rgb false_colour(double value, double max);

/// The smallest 1, 2, 2.5 or 5 × 10^k at or above `value` (> 0), so legend ticks are round.
double round_scale_max(double value);

/// Width in pixels `draw_legend` needs for labels up to `max`.
int legend_width(double max, int scale);

/// A vertical bar [0, max] with five intervals, its tick labels and `unit` above it, drawn in the
/// box whose top-left corner is (x, y) and which is `height` pixels tall.
void draw_legend(Image& image, int x, int y, int height, double max, const std::string& unit,
                 int scale);

/// `value` with about three significant digits and no exponent ("512", "0.78", "12.5").
std::string short_number(double value);

}  // namespace radiant::picture
