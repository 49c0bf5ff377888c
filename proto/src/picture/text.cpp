#include "picture/text.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace radiant::picture {
namespace {

/// stb_easy_font's vertex layout: position, then an RGBA colour we do not use.
struct FontVertex {
    float x, y, z;
    unsigned char rgba[4];
};
static_assert(sizeof(FontVertex) == 16);

}  // namespace

void draw_text(Image& image, int x, int y, const std::string& text, Rgb colour, int scale) {
    // Each segment takes one quad (4 vertices); no glyph has more than 16 segments.
    std::vector<FontVertex> quads(text.size() * 16 * 4);
    std::string writable = text;
    unsigned char white[4] = {255, 255, 255, 255};
    const int count = stb_easy_font_print(0, 0, writable.data(), white, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(FontVertex)));
    const auto pixel = [scale](float v) {
        return static_cast<int>(std::lround(v * static_cast<float>(scale)));
    };
    for (int q = 0; q < count; ++q) {
        // Segments are axis-aligned quads whose corner order depends on their direction.
        const FontVertex* corner = &quads[static_cast<std::size_t>(4 * q)];
        float x0 = corner[0].x, x1 = corner[0].x, y0 = corner[0].y, y1 = corner[0].y;
        for (int k = 1; k < 4; ++k) {
            x0 = std::min(x0, corner[k].x), x1 = std::max(x1, corner[k].x);
            y0 = std::min(y0, corner[k].y), y1 = std::max(y1, corner[k].y);
        }
        image.fill(x + pixel(x0), y + pixel(y0), x + pixel(x1), y + pixel(y1), colour);
    }
}

int text_width(const std::string& text, int scale) {
    std::string writable = text;
    return stb_easy_font_width(writable.data()) * scale;
}

}  // namespace radiant::picture
