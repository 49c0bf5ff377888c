#include "radiant/picture/image.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace radiant::picture {

Image::Image(int width, int height, Rgb background)
    : width_(width),
      height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), background) {
    if (width < 1 || height < 1) throw std::invalid_argument("image size must be positive");
}

void Image::fill(int x0, int y0, int x1, int y1, Rgb colour) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, width_);
    y1 = std::min(y1, height_);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) set(x, y, colour);
    }
}

void Image::outline(int x0, int y0, int x1, int y1, Rgb colour) {
    fill(x0, y0, x1, y0 + 1, colour);
    fill(x0, y1 - 1, x1, y1, colour);
    fill(x0, y0, x0 + 1, y1, colour);
    fill(x1 - 1, y0, x1, y1, colour);
}

std::string Image::png() const {
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
    };
    static_assert(sizeof(Rgb) == 3);
    if (stbi_write_png_to_func(append, &bytes, width_, height_, 3, pixels_.data(), width_ * 3) ==
        0) {
        throw std::runtime_error("PNG encoding failed");
    }
    return bytes;
}

std::uint8_t srgb_byte(double linear) {
    if (!(linear > 0)) return 0;  // also NaN
    if (linear >= 1) return 255;
    const double encoded =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(255 * encoded));
}

}  // namespace radiant::picture
