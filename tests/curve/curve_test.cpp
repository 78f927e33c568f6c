// Plane curves as pixel masks: no pixel the curve crosses or touches is missed (against a
// double-precision reference that samples each pixel's square finely), and none is drawn
// far from the curve; singular points, touching zeros and isolated points included.
#include "curve/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "parser/parser.hpp"

namespace zs::curve {
namespace {

constexpr int kSize = 160;
// The window of surf's pictures: -10..10 over the pixel centres.
const PixelMap kMap{-10, 20.0 / (kSize - 1), 10, -20.0 / (kSize - 1)};

CurveMask draw(const std::string& formula, double halfWidth = 0.5) {
  const ParseResult parsed = parseFormula(formula);
  EXPECT_TRUE(std::holds_alternative<Formula>(parsed)) << formula;
  const Formula& f = std::get<Formula>(parsed);
  CurveOptions options;
  options.halfWidth = halfWidth;
  return rasterizeCurve(f.graph, f.root, kMap, kSize, kSize, options);
}

// Whether f changes sign (or is 0) on a 17 x 17 grid over pixel (px, py)'s square.
bool referenceCrosses(const std::function<double(double, double)>& f, int px, int py,
                      double halfWidth) {
  bool neg = false, pos = false;
  for (int i = 0; i <= 16; ++i) {
    for (int j = 0; j <= 16; ++j) {
      const double qx = px - halfWidth + 2 * halfWidth * i / 16,
                   qy = py - halfWidth + 2 * halfWidth * j / 16;
      const double v = f(kMap.x0 + kMap.dx * qx, kMap.y0 + kMap.dy * qy);
      if (v == 0) return true;
      (v < 0 ? neg : pos) = true;
    }
  }
  return neg && pos;
}

struct Counts {
  int missed = 0, drawn = 0, far = 0;
};

// Missed: the reference sees a crossing the mask lacks. Far: drawn, yet `distance` (the
// distance to the curve in plane units) is more than the square's half diagonal plus a
// pixel.
Counts check(const std::string& formula, const std::function<double(double, double)>& f,
             const std::function<double(double, double)>& distance, double halfWidth = 0.5) {
  const CurveMask m = draw(formula, halfWidth);
  Counts c;
  const double pixel = kMap.dx;
  for (int py = 0; py < kSize; ++py) {
    for (int px = 0; px < kSize; ++px) {
      const bool drawn = m.drawn[std::size_t(py) * kSize + px] != 0;
      c.drawn += drawn;
      if (!drawn && referenceCrosses(f, px, py, halfWidth)) ++c.missed;
      const double x = kMap.x0 + kMap.dx * px, y = kMap.y0 + kMap.dy * py;
      if (drawn && distance(x, y) > (halfWidth * std::sqrt(2.0) + 1) * pixel) ++c.far;
    }
  }
  return c;
}

TEST(Curve, CircleNoPixelMissedNoneFar) {
  for (double halfWidth : {0.5, 0.75, 1.5}) {
    const Counts c = check(
        "x^2 + y^2 - 25", [](double x, double y) { return x * x + y * y - 25; },
        [](double x, double y) { return std::abs(std::hypot(x, y) - 5); }, halfWidth);
    EXPECT_EQ(c.missed, 0) << halfWidth;
    EXPECT_EQ(c.far, 0) << halfWidth;
    EXPECT_GT(c.drawn, 2 * M_PI * 5 / kMap.dx) << halfWidth;
  }
}

TEST(Curve, ACuspAndANodeHaveNoGap) {
  // y^2 = x^3 (cusp at 0) and the lemniscate (x^2 + y^2)^2 = 32 (x^2 - y^2) (node at 0).
  const Counts cusp = check(
      "y^2 - x^3", [](double x, double y) { return y * y - x * x * x; },
      [](double x, double y) {
        // distance to the two branches y = +-x^(3/2), sampled
        double best = 1e9;
        for (double t = 0; t <= 5; t += 0.0005)
          best = std::min({best, std::hypot(x - t, y - std::pow(t, 1.5)),
                           std::hypot(x - t, y + std::pow(t, 1.5))});
        return best;
      });
  EXPECT_EQ(cusp.missed, 0);
  EXPECT_EQ(cusp.far, 0);
  const auto lemniscate = [](double x, double y) {
    const double r2 = x * x + y * y;
    return r2 * r2 - 32 * (x * x - y * y);
  };
  const CurveMask m = draw("(x^2 + y^2)^2 - 32*(x^2 - y^2)");
  int missed = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px)
      if (!m.drawn[std::size_t(py) * kSize + px] && referenceCrosses(lemniscate, px, py, 0.5))
        ++missed;
  EXPECT_EQ(missed, 0);
  // The pixels about the node (the picture's centre, between pixels 79 and 80) are drawn.
  EXPECT_TRUE(m.drawn[79 * kSize + 79] || m.drawn[80 * kSize + 80]);
}

TEST(Curve, ZerosTheCurveTouchesWithoutCrossingAreDrawn) {
  // (x - y)^2 = 0 never changes sign; x^2 + y^2 = 0 is one point.
  const CurveMask line = draw("(x - y)^2");
  int diagonal = 0;
  for (int i = 0; i < kSize; ++i) diagonal += line.drawn[std::size_t(i) * kSize + (kSize - 1 - i)];
  EXPECT_EQ(diagonal, kSize);
  const CurveMask point = draw("x^2 + y^2", 0.75);
  int drawn = 0;
  for (auto d : point.drawn) drawn += d;
  EXPECT_GE(drawn, 1);
  EXPECT_LE(drawn, 4) << "a point, not a blot";
  EXPECT_TRUE(point.drawn[79 * kSize + 79] && point.drawn[80 * kSize + 80]);
}

TEST(Curve, SmallOvalsAreFound) {
  // Ovals far smaller than a pixel: (x - 3)^2 + y^2 = 1e-6, and one between pixel centres.
  const CurveMask m = draw("((x - 3)^2 + y^2 - 1e-6)*((x + 2.03)^2 + (y - 4.01)^2 - 1e-8)");
  int drawn = 0;
  for (auto d : m.drawn) drawn += d;
  EXPECT_GE(drawn, 2);
  EXPECT_LE(drawn, 8);
}

}  // namespace
}  // namespace zs::curve
