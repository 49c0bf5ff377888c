// Labels on pictures: stb_easy_font's segment glyphs, scaled by whole pixels.
#pragma once

#include <string>

#include "radiant/picture/image.h"

namespace radiant::picture {

/// Draws `text` with its top-left corner at (x, y); glyphs are about 7·scale pixels tall.
void draw_text(Image& image, int x, int y, const std::string& text, Rgb colour, int scale);

/// The width in pixels `draw_text` uses for `text`.
int text_width(const std::string& text, int scale);

}  // namespace radiant::picture
