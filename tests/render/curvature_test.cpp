// Curvature colorings, checked on the values the GPU computed: the render's value output
// (Frame::value, the curvature at each pixel's first hit) against the closed forms of
// docs/curvature.md. Orientation: by grad F, so F = |p|^2 - r^2 has mean curvature +1/r.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 48;

struct Values {
  int hits = 0;
  double min = INFINITY, max = -INFINITY;
};

Values valuesOf(const Frame& f) {
  Values v;
  for (float x : f.value.values) {
    if (std::isnan(x)) continue;
    ++v.hits;
    v.min = std::min(v.min, double(x));
    v.max = std::max(v.max, double(x));
  }
  return v;
}

class Curvature : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  }
  // Renders `formula` with shading.color = mode from `eye`, every pixel's curvature read back.
  static Frame render(const std::string& formula, ColorMode mode, Vec3 eye, double range = 1) {
    std::string error;
    test::SurfaceSpec spec{formula, {}, 2};
    spec.hessian = true;
    const std::unique_ptr<RayTracer> tracer = test::makeTracer(spec, error);
    EXPECT_NE(tracer, nullptr) << error;
    if (!tracer) return {};
    RenderSettings s = test::testSettings(eye);
    s.shading.color = mode;
    s.shading.curvatureRange = range;
    Frame f = tracer->render(s, Domain{}, kSize, kSize);
    EXPECT_EQ(f.error, "");
    EXPECT_EQ(f.value.values.size(), std::size_t(kSize) * kSize);
    return f;
  }
};

TEST_F(Curvature, SphereHasGaussianCurvatureOneOverRSquared) {
  const double r = 0.8;
  const Values v = valuesOf(render("x^2 + y^2 + z^2 - 0.64", ColorMode::Gauss, {0, 0, 3}));
  EXPECT_GT(v.hits, kSize * kSize / 4);
  EXPECT_NEAR(v.min, 1 / (r * r), 1e-3);
  EXPECT_NEAR(v.max, 1 / (r * r), 1e-3);
}

TEST_F(Curvature, SphereHasMeanCurvatureOneOverRSignedByTheGradient) {
  const double r = 0.8;
  const Values out = valuesOf(render("x^2 + y^2 + z^2 - 0.64", ColorMode::Mean, {0, 0, 3}));
  EXPECT_GT(out.hits, kSize * kSize / 4);
  EXPECT_NEAR(out.min, 1 / r, 1e-4);
  EXPECT_NEAR(out.max, 1 / r, 1e-4);
  // The same sphere with the gradient pointing inwards: the sign flips, K does not.
  const Values in = valuesOf(render("0.64 - x^2 - y^2 - z^2", ColorMode::Mean, {0, 0, 3}));
  EXPECT_NEAR(in.min, -1 / r, 1e-4);
  EXPECT_NEAR(in.max, -1 / r, 1e-4);
  const Values k = valuesOf(render("0.64 - x^2 - y^2 - z^2", ColorMode::Gauss, {0, 0, 3}));
  EXPECT_NEAR(k.min, 1 / (r * r), 1e-3);
}

TEST_F(Curvature, CylinderHasGaussianZeroAndMeanOneOverTwoR) {
  const double r = 0.7;
  // Seen from the side (its axis is z).
  const Values k = valuesOf(render("x^2 + y^2 - 0.49", ColorMode::Gauss, {3, 0.2, 0.1}));
  EXPECT_GT(k.hits, kSize * kSize / 4);
  EXPECT_NEAR(k.min, 0, 1e-5);
  EXPECT_NEAR(k.max, 0, 1e-5);
  const Values h = valuesOf(render("x^2 + y^2 - 0.49", ColorMode::Mean, {3, 0.2, 0.1}));
  EXPECT_NEAR(h.min, 1 / (2 * r), 1e-4);
  EXPECT_NEAR(h.max, 1 / (2 * r), 1e-4);
}

TEST_F(Curvature, SaddleHasNegativeGaussianCurvature) {
  // z = x^2 - y^2 at the origin: K = -4, H = 0 (principal curvatures +-2).
  const Frame f = render("x^2 - y^2 - z", ColorMode::Gauss, {0, 0, 3});
  const float center = f.value.at(kSize / 2, kSize / 2);
  EXPECT_NEAR(center, -4, 0.1);  // the center ray passes within half a pixel of the origin
}

TEST_F(Curvature, AutomaticRangeIsThePercentileOfTheVisibleValues) {
  const Frame f = render("x^2 + y^2 + z^2 - 0.64", ColorMode::Mean, {0, 0, 3}, 0);
  EXPECT_NEAR(f.curvatureRange, 1 / 0.8, 1e-3);
  const Frame fixed = render("x^2 + y^2 + z^2 - 0.64", ColorMode::Mean, {0, 0, 3}, 2.5);
  EXPECT_EQ(fixed.curvatureRange, 2.5);
  // A cylinder's Gaussian curvature is 0: the range stays at its floor, not at float noise.
  const Frame flat = render("x^2 + y^2 - 0.49", ColorMode::Gauss, {3, 0.2, 0.1}, 0);
  EXPECT_GT(flat.curvatureRange, 1e-5);
}

TEST_F(Curvature, TheColorMapIsWhiteAtZeroAndSaturatesAtTheRange) {
  // Only ambient light of weight 1, so the pixel shows the map's color itself.
  std::string error;
  test::SurfaceSpec spec{"x^2 + y^2 + z^2 - 0.64", {}, 2};
  spec.hessian = true;
  const std::unique_ptr<RayTracer> tracer = test::makeTracer(spec, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings s = test::testSettings({0, 0, 3});
  s.reflection.enabled = false;
  s.silhouette.enabled = false;
  s.lights.sources.clear();
  s.lights.ambient = 1;
  s.shading.color = ColorMode::Mean;
  s.shading.curvatureRange = 1 / 0.8;  // the sphere's own value: the red end
  const Frame red = tracer->render(s, Domain{}, kSize, kSize);
  const std::uint8_t* p = red.color.pixel(kSize / 2, kSize / 2);
  EXPECT_GT(p[0], 190);
  EXPECT_LT(p[1], 40);
  s.shading.curvatureRange = 1e6;  // the value is ~0 of the range: white
  const Frame white = tracer->render(s, Domain{}, kSize, kSize);
  p = white.color.pixel(kSize / 2, kSize / 2);
  EXPECT_GT(p[0], 235);
  EXPECT_GT(p[1], 235);
  EXPECT_GT(p[2], 235);
}

TEST_F(Curvature, MaterialColoringHasNoValueOutput) {
  std::string error;
  const std::unique_ptr<RayTracer> tracer = test::makeTracer({"x^2 + y^2 + z^2 - 1", {}, 2}, error);
  ASSERT_NE(tracer, nullptr) << error;
  const Frame f = tracer->render(test::testSettings(), Domain{}, kSize, kSize);
  EXPECT_TRUE(f.value.values.empty());
}

}  // namespace
}  // namespace zs
