#pragma once
// A tiny rasterizer for benchmark plots, so that no plotting library is needed: takes
// drawing calls in pixel coordinates (y down), puts out an RGBA8 Image (render/image.hpp)
// that writePng saves. Lines are Bresenham with a square pen; text is a built-in 3x5 pixel
// font scaled up, covering digits and the few lower-case letters plot labels use (others
// draw as a hollow box, so a missing glyph is visible rather than silently dropped).
#include <array>
#include <cstdint>
#include <string_view>

#include "render/image.hpp"

namespace zs::bench {

using Rgb = std::array<std::uint8_t, 3>;

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);

  void set(int x, int y, Rgb color);                         // ignores pixels outside the image
  void fillRect(int x0, int y0, int x1, int y1, Rgb color);  // inclusive corners
  // pen: side of the square drawn at each step; dash > 0 leaves gaps of `dash` pixels.
  void line(int x0, int y0, int x1, int y1, Rgb color, int pen = 1, int dash = 0);
  // Top-left corner at (x, y); each font pixel becomes scale x scale pixels.
  void text(int x, int y, std::string_view s, Rgb color, int scale = 2);
  static int textWidth(std::string_view s, int scale = 2) {
    return static_cast<int>(s.size()) * 4 * scale - (s.empty() ? 0 : scale);
  }

  const Image& image() const { return image_; }

 private:
  Image image_;
};

}  // namespace zs::bench
