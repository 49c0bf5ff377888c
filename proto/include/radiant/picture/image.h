// An 8-bit sRGB raster and its PNG encoding (stb_image_write from Debian's libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radiant::picture {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

class Image {
public:
    Image(int width, int height, Rgb background);

    int width() const { return width_; }
    int height() const { return height_; }
    Rgb at(int x, int y) const { return pixels_[index(x, y)]; }
    void set(int x, int y, Rgb colour) { pixels_[index(x, y)] = colour; }
    /// Fills [x0, x1) × [y0, y1), clipped to the image.
    void fill(int x0, int y0, int x1, int y1, Rgb colour);
    /// A one-pixel rectangle outline, clipped.
    void outline(int x0, int y0, int x1, int y1, Rgb colour);

    /// The image as a PNG file's bytes.
    std::string png() const;

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }

    int width_, height_;
    std::vector<Rgb> pixels_;
};

/// Linear [0, 1] → 8-bit sRGB (IEC 61966-2-1 transfer curve), clamped.
std::uint8_t srgb_byte(double linear);

}  // namespace radiant::picture
