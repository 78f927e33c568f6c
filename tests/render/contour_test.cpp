// Contour lines (shading.contours): every method colors exactly the hits that lie within
// half the width of a level g = k * spacing, measured along the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 96;

class Contours : public ::testing::TestWithParam<TracingMethod> {};

TEST_P(Contours, LinesLieOnTheLevelsOfTheFunction) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  test::SurfaceSpec spec{"x^2+y^2+z^2-1", {}, 2};
  spec.method = GetParam();
  spec.contours = {true, "z", 0.25, 0.04, {0, 0, 1}};
  auto tracer = test::makeTracer(spec, error);
  ASSERT_NE(tracer, nullptr) << error;
  // The unit sphere from the side, z up: the levels of z are horizontal circles.
  RenderSettings s = test::testSettings({3, 0, 0});
  s.camera.up = {0, 0, 1};
  s.reflection.enabled = false;
  s.silhouette.enabled = false;
  s.border.enabled = false;
  s.shading.contours = spec.contours;
  const Frame f = tracer->render(s, Domain{}, kSize, kSize);
  ASSERT_EQ(f.error, "");
  int lines = 0, checked = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const std::optional<Vec3> hit = test::hitPoint(f, s.camera, i, j);
      if (!hit) continue;
      const double z = (*hit)[2];
      // On the sphere the normal is p, so the slope of z along the surface is sqrt(1 - z^2):
      // a line covers |z - level| < width / 2 * sqrt(1 - z^2).
      const double off = std::abs(z - 0.25 * std::round(z / 0.25));
      const double halfBand = 0.5 * 0.04 * std::sqrt(std::max(0.0, 1 - z * z));
      const bool blue = test::pixelNear(f.color, i, j, {0, 0, 1}, 2);
      lines += blue;
      // Away from the band's edge (rounding of t) the color must say which side it is on.
      if (std::abs(off - halfBand) < 2e-3) continue;
      ++checked;
      EXPECT_EQ(blue, off < halfBand) << i << "," << j << " z " << z;
    }
  }
  EXPECT_GT(lines, 40);
  EXPECT_GT(checked, kSize * kSize / 3);
}

INSTANTIATE_TEST_SUITE_P(Methods, Contours, ::testing::ValuesIn(test::kEveryMethod),
                         test::methodName);

}  // namespace
}  // namespace zs
