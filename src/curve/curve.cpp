#include "curve/curve.hpp"

#include <algorithm>
#include <cmath>

#include "expr/tape.hpp"
#include "interval/tape_eval.hpp"

namespace zs::curve {

namespace {

class Rasterizer {
 public:
  Rasterizer(const Graph& graph, NodeId root, const PixelMap& map, int width, int height,
             const CurveOptions& options)
      : tape_(compileTape(graph, {root})),
        intervals_(tape_),
        points_(tape_),
        map_(map),
        options_(options),
        mask_{width, height, std::vector<std::uint8_t>(std::size_t(width) * height, 0)} {}

  CurveMask run() {
    if (mask_.width > 0 && mask_.height > 0) block(0, 0, mask_.width, mask_.height);
    return std::move(mask_);
  }

 private:
  // The plane square of pixel coordinates [px0, px1] x [py0, py1] (pixel centres at
  // integers), as an interval box.
  Box planeBox(double px0, double px1, double py0, double py1) const {
    const double xa = map_.x0 + map_.dx * px0, xb = map_.x0 + map_.dx * px1;
    const double ya = map_.y0 + map_.dy * py0, yb = map_.y0 + map_.dy * py1;
    Box b;
    b.min = {std::min(xa, xb), std::min(ya, yb), 0};
    b.max = {std::max(xa, xb), std::max(ya, yb), 0};
    return b;
  }

  bool mayVanish(const Box& b) {
    const Interval v = intervals_.eval1(b);
    return v.containsZero() || std::isnan(v.lo) || std::isnan(v.hi);
  }

  double at(double px, double py) {
    return points_.eval1(map_.x0 + map_.dx * px, map_.y0 + map_.dy * py, 0);
  }

  // Pixels [x0, x1) x [y0, y1), with their squares widened by halfWidth.
  void block(int x0, int y0, int x1, int y1) {
    const double r = options_.halfWidth;
    if (!mayVanish(planeBox(x0 - r, x1 - 1 + r, y0 - r, y1 - 1 + r))) return;
    if (x1 - x0 == 1 && y1 - y0 == 1) {
      if (pixelMeets(x0, y0)) mask_.drawn[std::size_t(y0) * mask_.width + x0] = 1;
      return;
    }
    const int xm = x0 + std::max(1, (x1 - x0) / 2), ym = y0 + std::max(1, (y1 - y0) / 2);
    block(x0, y0, xm, ym);
    if (xm < x1) block(xm, y0, x1, ym);
    if (ym < y1) block(x0, ym, xm, y1);
    if (xm < x1 && ym < y1) block(xm, ym, x1, y1);
  }

  // Whether the curve meets pixel (px, py)'s widened square: a sign change among sample
  // corners certifies it; otherwise the sub-squares whose intervals hold 0 are refined down
  // to the finest level, where holding 0 counts as meeting.
  bool pixelMeets(int px, int py) {
    const double r = options_.halfWidth;
    return square(px - r, py - r, 2 * r, 1);
  }

  bool square(double px, double py, double side, int level) {
    const double a = at(px, py), b = at(px + side, py), c = at(px, py + side),
                 d = at(px + side, py + side);
    const double lo = std::min({a, b, c, d}), hi = std::max({a, b, c, d});
    if (lo <= 0 && hi >= 0) return true;  // a sign change, or a zero at a corner
    if (!mayVanish(planeBox(px, px + side, py, py + side))) return false;
    if (level >= options_.finest) return true;
    const double h = side / 2;
    return square(px, py, h, level * 2) || square(px + h, py, h, level * 2) ||
           square(px, py + h, h, level * 2) || square(px + h, py + h, h, level * 2);
  }

  Tape tape_;
  IntervalEvaluator intervals_;
  PointEvaluator points_;
  PixelMap map_;
  CurveOptions options_;
  CurveMask mask_;
};

}  // namespace

CurveMask rasterizeCurve(const Graph& graph, NodeId root, const PixelMap& map, int width,
                         int height, const CurveOptions& options) {
  return Rasterizer(graph, root, map, width, height, options).run();
}

}  // namespace zs::curve
