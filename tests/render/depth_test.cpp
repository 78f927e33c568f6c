// Depth of the unit sphere against the analytic ray-sphere distance of the camera
// contract, perspective and orthographic, on both backends.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

// Distance along the unit ray to the unit sphere, or NaN; `clearance` = how far the ray's
// closest approach is from the sphere surface (near 0: grazing).
double sphereDistance(const Ray& r, double& clearance) {
  double b = 0, c = -1;
  for (int k = 0; k < 3; ++k) {
    b += r.origin[k] * r.direction[k];
    c += r.origin[k] * r.origin[k];
  }
  const double closest2 = c + 1 - b * b;  // squared distance of the line from the center
  clearance = std::sqrt(std::max(closest2, 0.0)) - 1;
  const double disc = b * b - c;
  return disc < 0 ? std::nan("") : -b - std::sqrt(disc);
}

void checkSphereDepth(Backend backend, const RenderSettings& settings, int size, int level = 3,
                      Criteria criteria = Criteria::Thesis,
                      TracingMethod method = TracingMethod::Auto, double tolerance = 1e-4) {
  std::string error;
  ASSERT_NE(test::context(backend, error), nullptr) << error;
  test::SurfaceSpec spec{"x^2+y^2+z^2-1", {}, level, {}, criteria};
  spec.method = method;
  auto tracer = test::makeTracer(spec, error);
  ASSERT_NE(tracer, nullptr) << error;
  const Frame frame = tracer->render(settings, spec.domain, size, size);
  ASSERT_EQ(frame.error, "");
  int covered = 0, grazing = 0;
  double worst = 0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      double clearance = 0;
      const double expected =
          sphereDistance(primaryRay(settings.camera, size, size, i, j), clearance);
      const float depth = frame.depth.at(i, j);
      // Rays passing within 1e-4 of the sphere are decided by float rounding either way.
      if (std::abs(clearance) < 1e-4) {
        ++grazing;
        continue;
      }
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isinf(depth)) << "pixel " << i << "," << j << " covered, should not be";
        continue;
      }
      ++covered;
      ASSERT_TRUE(std::isfinite(depth)) << "pixel " << i << "," << j << " missed";
      worst = std::max(worst, std::abs(depth - expected));
      EXPECT_NEAR(depth, expected, tolerance) << "pixel " << i << "," << j;
    }
  EXPECT_GT(covered, size * size / 8);
  EXPECT_LT(grazing, size);
  ::testing::Test::RecordProperty("worst_depth_error", std::to_string(worst));
  std::printf("  worst depth error %.3g\n", worst);
}

TEST(Depth, UnitSphereFromZ3MatchesAnalyticDistanceEgl) {
  checkSphereDepth(Backend::Egl, test::testSettings({0, 0, 3}), 96);
}

TEST(Depth, UnitSphereFromZ3MatchesAnalyticDistanceOsMesa) {
  checkSphereDepth(Backend::OsMesa, test::testSettings({0, 0, 3}), 64);
}

TEST(Depth, OrthographicAndOffAxisCamera) {
  RenderSettings s = test::testSettings({1.2, -0.7, 2.5});
  s.camera.projection = Projection::Orthographic;
  s.camera.height = 2.6;
  checkSphereDepth(Backend::Egl, s, 64);
}

// Many small leaves per ray (more than the shader's 8 segment slots): no holes, no misses.
TEST(Depth, DeepUniformOctreeLosesNoPixel) {
  checkSphereDepth(Backend::Egl, test::testSettings({0.4, 0.9, 2.8}), 64, 5, Criteria::Uniform);
}

TEST(Depth, SupersamplingKeepsThePixelCenterDepth) {
  RenderSettings s = test::testSettings({0, 0, 3});
  s.samples = 2;  // an even grid has no center sample: the depth ray is extra
  checkSphereDepth(Backend::Egl, s, 48);
}

// The same sphere through each tracing method, perspective and orthographic. Bernstein and
// sampling place a simple root far below tracing.epsilon; the interval method refines it to
// within epsilon (docs/renderer.md, "The interval method").
class DepthOfEveryMethod : public ::testing::TestWithParam<TracingMethod> {};

TEST_P(DepthOfEveryMethod, UnitSphere) {
  RenderSettings s = test::testSettings({0.3, -0.2, 3});
  const double tolerance = GetParam() == TracingMethod::Interval ? s.tracing.epsilon : 1e-4;
  checkSphereDepth(Backend::Egl, s, 64, 3, Criteria::Thesis, GetParam(), tolerance);
  s = test::testSettings({1.2, -0.7, 2.5});
  s.camera.projection = Projection::Orthographic;
  s.camera.height = 2.6;
  checkSphereDepth(Backend::Egl, s, 48, 3, Criteria::Thesis, GetParam(), tolerance);
}

INSTANTIATE_TEST_SUITE_P(Methods, DepthOfEveryMethod, ::testing::ValuesIn(test::kEveryMethod),
                         test::methodName);

}  // namespace
}  // namespace zs
