#pragma once
// Plane curves f(x, y) = 0 drawn exactly, for surf's draw_curve: a quadtree over the picture
// keeps, by interval arithmetic (src/interval), the blocks of pixels the curve may meet; a
// kept pixel is drawn when a sign change of f certifies a zero in its square, or when the
// finest sub-squares still hold 0 in their intervals (a curve that touches zero without
// crossing it: (x - y)^2 = 0, an isolated point such as x^2 + y^2 = 0). So no pixel the curve
// crosses or touches is missed; a drawn pixel is at most a sub-square's interval error from
// the curve. z is held at 0.
#include <cstdint>
#include <vector>

#include "expr/graph.hpp"

namespace zs::curve {

// Pixel (px, py), counted from the top left, is centred on x = x0 + dx * px,
// y = y0 + dy * py (dy is negative where y points up).
struct PixelMap {
  double x0 = 0, dx = 1;
  double y0 = 0, dy = -1;
};

struct CurveMask {
  int width = 0, height = 0;
  std::vector<std::uint8_t> drawn;  // width * height, top row first: 1 where the curve is
};

struct CurveOptions {
  // A pixel is drawn where the curve meets the square of side 2 * halfWidth pixels about
  // its centre (0.5: the pixel itself).
  double halfWidth = 0.5;
  // Sub-squares per side at the finest level, a power of two.
  int finest = 8;
};

CurveMask rasterizeCurve(const Graph& graph, NodeId root, const PixelMap& map, int width,
                         int height, const CurveOptions& options = {});

}  // namespace zs::curve
