#include "app/bench/canvas.hpp"

#include <algorithm>
#include <cstdlib>

namespace zs::bench {

namespace {

// 3x5 glyphs, one row per entry (top first), bit 2 = left column.
struct Glyph {
  char c;
  std::array<std::uint8_t, 5> rows;
};

constexpr Glyph kFont[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 2, 2}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
    {'x', {0, 5, 2, 5, 0}}, {' ', {0, 0, 0, 0, 0}}, {'a', {2, 5, 7, 5, 5}}, {'c', {3, 4, 4, 4, 3}},
    {'e', {7, 4, 6, 4, 7}}, {'f', {3, 4, 6, 4, 4}}, {'g', {7, 4, 5, 5, 7}}, {'l', {4, 4, 4, 4, 7}},
    {'m', {5, 7, 7, 5, 5}}, {'o', {2, 5, 5, 5, 2}}, {'p', {7, 5, 7, 4, 4}}, {'r', {6, 5, 6, 5, 5}},
    {'s', {3, 4, 2, 1, 6}}, {'t', {7, 2, 2, 2, 2}}, {'u', {5, 5, 5, 5, 7}}, {'v', {5, 5, 5, 5, 2}},
};

constexpr std::array<std::uint8_t, 5> kMissing{7, 5, 5, 5, 7};

const std::array<std::uint8_t, 5>& glyph(char c) {
  for (const Glyph& g : kFont)
    if (g.c == c) return g.rows;
  return kMissing;
}

}  // namespace

Canvas::Canvas(int width, int height, Rgb background) {
  image_.width = width;
  image_.height = height;
  image_.rgba.resize(std::size_t(width) * height * 4);
  fillRect(0, 0, width - 1, height - 1, background);
}

void Canvas::set(int x, int y, Rgb color) {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
  std::uint8_t* p = image_.pixel(x, y);
  p[0] = color[0], p[1] = color[1], p[2] = color[2], p[3] = 255;
}

void Canvas::fillRect(int x0, int y0, int x1, int y1, Rgb color) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y)
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) set(x, y, color);
}

void Canvas::line(int x0, int y0, int x1, int y1, Rgb color, int pen, int dash) {
  // Bresenham over all octants; the step counter drives the dash pattern.
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  const int lo = -(pen - 1) / 2, hi = pen / 2;
  for (int step = 0;; ++step) {
    if (dash <= 0 || (step / dash) % 2 == 0) fillRect(x0 + lo, y0 + lo, x0 + hi, y0 + hi, color);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void Canvas::text(int x, int y, std::string_view s, Rgb color, int scale) {
  for (char c : s) {
    const auto& rows = glyph(c);
    for (int row = 0; row < 5; ++row)
      for (int col = 0; col < 3; ++col)
        if (rows[row] & (4 >> col))
          fillRect(x + col * scale, y + row * scale, x + (col + 1) * scale - 1,
                   y + (row + 1) * scale - 1, color);
    x += 4 * scale;
  }
}

}  // namespace zs::bench
