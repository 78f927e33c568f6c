// render.mode = "volume": F's field by emission and absorption, checked against the same
// transfer function integrated in double precision along the ray (docs/renderer.md, "Volume
// rendering": the midpoint rule's step error).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 16;

// The shader's color map (raytrace_volume.frag.glsl) in double.
std::array<double, 3> volumeColor(double x) {
  const double t = std::clamp(x, -1.0, 1.0);
  const std::array<double, 3> white{0.96, 0.96, 0.96}, blue{0.15, 0.3, 0.85}, red{0.8, 0.1, 0.1};
  std::array<double, 3> c{};
  for (int k = 0; k < 3; ++k)
    c[k] = t < 0 ? white[k] + (blue[k] - white[k]) * -t : white[k] + (red[k] - white[k]) * t;
  return c;
}

// The ray's color over `background` for F = z along z from z0 down to z1, integrated with
// `steps` midpoint steps in double.
std::array<double, 3> reference(const Volume& v, double z0, double z1, int steps,
                                const Vec3& background) {
  std::array<double, 3> color{};
  double through = 1;
  const double h = (z0 - z1) / steps;
  for (int i = 0; i < steps; ++i) {
    const double z = z0 - (i + 0.5) * h, u = z / v.falloff;
    const double alpha = 1 - std::exp(-v.density * std::exp(-u * u) * h);
    const std::array<double, 3> c = volumeColor(z / v.range);
    for (int k = 0; k < 3; ++k) color[k] += through * alpha * c[k];
    through *= 1 - alpha;
  }
  for (int k = 0; k < 3; ++k) color[k] += through * background[k];
  return color;
}

// The volume mode, looking straight down on the box from (0, 0, 3) with parallel rays that
// each cross it from z = 1.5 to z = -1.5.
RenderSettings fromAboveOrthographic(const Vec3& background) {
  RenderSettings s = test::testSettings({0, 0, 3});
  s.camera.projection = Projection::Orthographic;
  s.camera.height = 2;
  s.mode = RenderMode::Volume;
  s.background = background;
  return s;
}

TEST(Volume, ALinearFieldMatchesTheTransferFunctionIntegratedInDouble) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  // F = z seen from above: every ray crosses the band around z = 0 through the whole box.
  auto tracer = test::makeTracer({"z", {}, 1}, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings s = fromAboveOrthographic({0.1, 0.2, 0.3});
  for (const Volume v :
       {Volume{2, 0.2, 4, 256}, Volume{40, 0.05, 0.5, 512}, Volume{0, 0.1, 1, 64}}) {
    s.volume = v;
    const Frame f = tracer->render(s, Domain{}, kSize, kSize);
    ASSERT_EQ(f.error, "");
    // The box [-1.5, 1.5]^3: each ray's span is z from 1.5 to -1.5. Against 65536 steps
    // (the integral) and against the shader's own step count (its arithmetic).
    const std::array<double, 3> exact = reference(v, 1.5, -1.5, 65536, s.background);
    const std::array<double, 3> same = reference(v, 1.5, -1.5, v.steps, s.background);
    for (int j = 0; j < kSize; j += 5) {
      for (int i = 0; i < kSize; i += 5) {
        const std::uint8_t* p = f.color.pixel(i, j);
        EXPECT_TRUE(std::isinf(f.depth.at(i, j)));  // no hits in a volume
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(p[k] / 255.0, same[k], 1.5 / 255)
              << "density " << v.density << " channel " << k;
          EXPECT_NEAR(p[k] / 255.0, exact[k], 3.0 / 255)
              << "density " << v.density << " channel " << k;
        }
      }
    }
  }
}

// The field glows wherever |F - level| is small, also outside the box of the octree's
// leaves (which only bounds where F = level): seen from the side, F = z still shows above
// its zero plane, and a field without any zero (F > 0 everywhere) still shows.
TEST(Volume, TheFieldShowsBeyondWhereTheSurfaceLies) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  RenderSettings s = test::testSettings({3, 0, 0});
  s.camera.up = {0, 0, 1};
  s.camera.projection = Projection::Orthographic;
  s.camera.height = 2.4;
  s.mode = RenderMode::Volume;
  s.background = {0, 0, 0};
  s.volume = {8, 0.5, 1, 128};
  auto plane = test::makeTracer({"z", {}, 2}, error);
  ASSERT_NE(plane, nullptr) << error;
  const Frame side = plane->render(s, Domain{}, kSize, kSize);
  ASSERT_EQ(side.error, "");
  // The top row's rays run at z = 1.125, where the leaves (about z = 0) are far: F = 1.125
  // along them, an optical depth of 8 exp(-(1.125 / 0.5)^2) * 3 = 0.15.
  const std::uint8_t* p = side.color.pixel(kSize / 2, 0);
  EXPECT_GT(p[0] + p[1] + p[2], 3 * 10) << "nothing drawn above the zero plane's leaves";

  auto noZero = test::makeTracer({"x^2 + y^2 + z^2 + 0.02", {}, 2}, error);
  ASSERT_NE(noZero, nullptr) << error;
  s.volume = {8, 0.1, 1, 128};
  const Frame glow = noZero->render(s, Domain{}, kSize, kSize);
  ASSERT_EQ(glow.error, "");
  const std::uint8_t* c = glow.color.pixel(kSize / 2, kSize / 2);
  EXPECT_GT(c[0] + c[1] + c[2], 3 * 40) << "a field without zeros draws nothing";
}

TEST(Volume, IsDeterministic) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  auto tracer = test::makeTracer({"sin(3*x)*cos(2*y) + z^2 - 0.5", {}, 1}, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings s = test::testSettings({1.5, 2, 2.5});
  s.mode = RenderMode::Volume;
  s.background = {0, 0, 0};
  const Frame a = tracer->render(s, Domain{}, 40, 30);
  const Frame b = tracer->render(s, Domain{}, 40, 30);
  ASSERT_EQ(a.error, "");
  EXPECT_EQ(a.color.rgba, b.color.rgba);
  EXPECT_GT(test::fractionNear(a.color, {0, 0, 0}, 2), 0.01);  // the box's outside
  EXPECT_LT(test::fractionNear(a.color, {0, 0, 0}, 2), 0.9);   // and the field inside it
}

// The interval method's program skips the stretches of a ray where the affine form keeps F
// four falloffs from the level, the Bernstein method's (for polynomials) where the control
// points of the ray polynomial do; the sampling program samples every step. Their pictures
// are the same to within one 8-bit level (the skipped extinction is below density * e^-16).
TEST(Volume, SkippingFarFromTheLevelKeepsThePicture) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  RenderSettings s = test::testSettings({3.6, 2.6, 4.6});
  s.mode = RenderMode::Volume;
  s.background = {0.05, 0.05, 0.1};
  struct Case {
    const char* formula;
    bool polynomial;
  };
  // Degree 8: the Bernstein program's windows in double (emit_ray_polynomial.hpp kDoubleDegree).
  for (const Case& c :
       {Case{"x^3*y + y^3*z + z^3*x", true}, Case{"x^4 + y^4 + z^4 - 1", true},
        Case{"x^8 + y^8 + z^8 - 1 + x*y*z", true}, Case{"sin(3*x)*cos(2*y) + z^2 - 0.5", false}}) {
    const Domain box{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};
    auto everyStep =
        test::makeTracer({c.formula, box, 1, {}, Criteria::Thesis, TracingMethod::Sampling}, error);
    ASSERT_NE(everyStep, nullptr) << error;
    const Frame b = everyStep->render(s, box, 48, 36);
    ASSERT_EQ(b.error, "");
    for (TracingMethod method : {TracingMethod::Interval, TracingMethod::Bernstein}) {
      if (method == TracingMethod::Bernstein && !c.polynomial) continue;
      const std::string name = std::string(c.formula) + ", " + tracingMethodName(method);
      auto skipping = test::makeTracer({c.formula, box, 1, {}, Criteria::Thesis, method}, error);
      ASSERT_NE(skipping, nullptr) << error;
      const Frame a = skipping->render(s, box, 48, 36);
      ASSERT_EQ(a.error, "") << name;
      int worst = 0;
      for (std::size_t k = 0; k < a.color.rgba.size(); ++k)
        worst = std::max(worst, std::abs(int(a.color.rgba[k]) - int(b.color.rgba[k])));
      EXPECT_LE(worst, 1) << name;
      EXPECT_LT(test::fractionNear(a.color, {0.05, 0.05, 0.1}, 2), 0.9) << name << ": drawn";
    }
  }
}

TEST(Volume, ClipPlanesAndTheLevelBoundWhatIsIntegrated) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  auto tracer = test::makeTracer({"z", {}, 1}, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings s = fromAboveOrthographic({0, 0, 0});
  s.volume = {20, 0.1, 1, 256};
  // Cutting away z > -0.5 leaves no part of the band around z = 0: only its faint tail.
  s.clipPlanes = {{true, {0, 0, 1}, -0.5}};
  const Frame f = tracer->render(s, Domain{}, kSize, kSize);
  ASSERT_EQ(f.error, "");
  const std::array<double, 3> expected = reference(s.volume, -0.5, -1.5, 256, s.background);
  const std::uint8_t* p = f.color.pixel(kSize / 2, kSize / 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k] / 255.0, expected[k], 1.5 / 255);
  EXPECT_LT(p[0], 10);
}

}  // namespace
}  // namespace zs
