// Cross-sections ([[clip.plane]]): every method keeps only the hits on the kept side of every
// plane, shows what lies behind the cut (the inside, in the back material), and draws the
// curve where the surface meets a plane in the cut color.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 64;

class ClipPlanes : public ::testing::TestWithParam<TracingMethod> {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
    test::SurfaceSpec spec{"x^2+y^2+z^2-1", {}, 2};
    spec.method = GetParam();
    tracer_ = test::makeTracer(spec, error);
    ASSERT_NE(tracer_, nullptr) << error;
  }
  // From above, reflection off: the plane z <= 0.3 takes the cap the eye would see first.
  static RenderSettings fromAbove() {
    RenderSettings s = test::testSettings({0, 0, 3});
    s.reflection.enabled = false;
    s.silhouette.enabled = false;
    s.background = {0, 0, 0};
    return s;
  }
  Frame render(const RenderSettings& s) {
    Frame f = tracer_->render(s, Domain{}, kSize, kSize);
    EXPECT_EQ(f.error, "");
    return f;
  }
  std::unique_ptr<RayTracer> tracer_;
};

TEST_P(ClipPlanes, HitsLieOnTheKeptSideAndTheCutShowsTheInside) {
  RenderSettings s = fromAbove();
  s.clipPlanes = {{true, {0, 0, 2}, 0.6}};  // z <= 0.3, the normal not of unit length
  const Frame f = render(s);
  const std::vector<Vec3> points = test::hitPoints(f, s.camera);
  ASSERT_GT(points.size(), 200u);
  for (const Vec3& p : points) EXPECT_LE(p[2], 0.3 + 1e-4);
  // The center ray passes the removed cap and meets the sphere's inside at z = -1.
  EXPECT_NEAR(f.depth.at(kSize / 2, kSize / 2), 4.0, 2e-3);
  const std::uint8_t* c = f.color.pixel(kSize / 2, kSize / 2);
  const Vec3 back = s.materials.back.color;
  EXPECT_GT(c[2], c[0]) << "the inside takes the back material (blue), not the front (orange)";
  EXPECT_GT(back[2], back[0]);

  // A second plane cuts the rest too: x <= -0.2 keeps only the far side.
  s.clipPlanes.push_back({true, {1, 0, 0}, -0.2});
  const Frame two = render(s);
  const std::vector<Vec3> kept = test::hitPoints(two, s.camera);
  ASSERT_FALSE(kept.empty());
  for (const Vec3& p : kept) {
    EXPECT_LE(p[2], 0.3 + 1e-4);
    EXPECT_LE(p[0], -0.2 + 1e-4);
  }
  EXPECT_LT(kept.size(), points.size());
}

TEST_P(ClipPlanes, TheCutCurveTakesTheCutColorAndADisabledPlaneCutsNothing) {
  RenderSettings s = fromAbove();
  s.camera.eye = {1.6, 1.2, 2.4};  // the rim seen from the side
  const Frame whole = render(s);
  s.clipPlanes = {{true, {0, 0, 1}, 0.3}};
  s.cut.threshold = 0.05;
  const Frame cut = render(s);
  EXPECT_GT(test::fractionNear(cut.color, s.cut.color, 6), 0.005);
  EXPECT_EQ(test::fractionNear(whole.color, s.cut.color, 6), 0.0);
  // The cut curve lies on the plane and on the surface: every pixel in the cut color is a
  // hit of the unit sphere within the tolerance of z = 0.3.
  int marked = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      if (!test::pixelNear(cut.color, i, j, s.cut.color, 6)) continue;
      ++marked;
      const std::optional<Vec3> hit = test::hitPoint(cut, s.camera, i, j);
      ASSERT_TRUE(hit) << i << "," << j;
      const Vec3& p = *hit;
      EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 2e-3) << i << "," << j;
      EXPECT_GE(p[2], 0.3 - s.cut.threshold - 1e-3) << i << "," << j;
      EXPECT_LE(p[2], 0.3 + 1e-4) << i << "," << j;
    }
  }
  EXPECT_GT(marked, 10);

  s.cut.enabled = false;
  EXPECT_EQ(test::fractionNear(render(s).color, s.cut.color, 6), 0.0);
  s.cut.enabled = true;
  s.clipPlanes.front().enabled = false;
  const ImageDiff diff = compareImages(render(s).color, whole.color, 1);
  EXPECT_LE(diff.maxDifference, 1);
}

INSTANTIATE_TEST_SUITE_P(Methods, ClipPlanes, ::testing::ValuesIn(test::kEveryMethod),
                         test::methodName);

}  // namespace
}  // namespace zs
