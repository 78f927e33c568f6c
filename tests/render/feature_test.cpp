// Each feature of chapter 4.4 changes the picture the way it should: checked against
// what the feature means (exact blends, analytic outlines), not against stored images.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/camera.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 64;
const Vec3 kBackground{0.2, 0.25, 0.3};

class Feature : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    if (!test::context(Backend::Egl, error)) return;
    sphere_ = test::makeTracer({"x^2+y^2+z^2-1", {}, 2}, error).release();
    torus_ = test::makeTracer({"(x^2+y^2+z^2+0.8^2-0.35^2)^2-4*0.8^2*(x^2+y^2)", {}, 3}, error)
                 .release();
    cylinder_ = test::makeTracer({"x^2+y^2-1", {}, 2}, error).release();
  }
  static void TearDownTestSuite() {
    delete sphere_;
    delete torus_;
    delete cylinder_;
  }
  void SetUp() override {
    std::string error;
    ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
    ASSERT_NE(sphere_, nullptr);
    ASSERT_NE(torus_, nullptr);
    ASSERT_NE(cylinder_, nullptr);
  }
  // Defaults with a dark background (so white-ish highlights stand out), silhouette and
  // reflection off unless a test turns them on.
  static RenderSettings base() {
    RenderSettings s = test::testSettings({0, 0, 3});
    s.background = kBackground;
    s.silhouette.enabled = false;
    s.reflection.enabled = false;
    return s;
  }
  static Image render(RayTracer* tracer, const RenderSettings& s, int size = kSize) {
    Frame f = tracer->render(s, Domain{}, size, size);
    EXPECT_EQ(f.error, "");
    return f.color;
  }
  static std::array<double, 3> at(const Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0] / 255.0, p[1] / 255.0, p[2] / 255.0};
  }
  // Distance in pixels of pixel (i, j)'s center from the image center.
  static double radius(int i, int j, int size = kSize) {
    return std::hypot(i + 0.5 - size / 2.0, j + 0.5 - size / 2.0);
  }
  static std::vector<Vec3> hitPoints(const Frame& f, const Camera& camera) {
    return test::hitPoints(f, camera);
  }
  static inline RayTracer *sphere_ = nullptr, *torus_ = nullptr, *cylinder_ = nullptr;
};

// Radius in pixels of the unit sphere's outline seen from distance 3 with fov 40.
double sphereOutline(int size = kSize) {
  return std::tan(std::asin(1.0 / 3.0)) / std::tan(20.0 * M_PI / 180.0) * size / 2.0;
}

TEST_F(Feature, SilhouetteDarkensTheOutlineOnly) {
  RenderSettings s = base();
  const Image off = render(sphere_, s);
  s.silhouette.enabled = true;
  s.silhouette.threshold = 0.3;
  const Image on = render(sphere_, s);
  EXPECT_EQ(test::fractionNear(off, s.silhouette.color), 0.0);
  int outline = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      if (!test::pixelNear(on, i, j, s.silhouette.color)) continue;
      ++outline;
      // |cos| < 0.3 only happens in the outer ring of the disk.
      EXPECT_GT(radius(i, j), 0.8 * sphereOutline()) << i << "," << j;
      EXPECT_LT(radius(i, j), sphereOutline() + 1.0) << i << "," << j;
    }
  EXPECT_GT(outline, 2 * M_PI * sphereOutline() * 0.5);
}

TEST_F(Feature, BorderMarksWhereTheSurfaceMeetsTheDomainBox) {
  RenderSettings s = base();
  s.camera.eye = {2.5, 3.5, 4.5};
  s.border.enabled = false;
  const Image off = render(cylinder_, s);
  s.border.enabled = true;
  s.border.threshold = 0.05;
  const Image on = render(cylinder_, s);
  EXPECT_EQ(test::fractionNear(off, s.border.color), 0.0);
  EXPECT_GT(test::fractionNear(on, s.border.color), 0.01);
  // The sphere lies inside the domain: no border anywhere.
  EXPECT_EQ(test::fractionNear(render(sphere_, s), s.border.color), 0.0);
}

TEST_F(Feature, ReflectionBlendsPrimaryAndReflectedColor) {
  RenderSettings s = base();
  const Image off = render(sphere_, s);
  s.reflection.enabled = true;
  s.reflection.primaryWeight = 0.7;
  const Image on = render(sphere_, s);
  // A convex sphere's reflection rays all escape: exactly 0.7 primary + 0.3 background.
  const auto a = at(off, kSize / 2, kSize / 2), b = at(on, kSize / 2, kSize / 2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], 0.7 * a[c] + 0.3 * kBackground[c], 1.5 / 255);

  // Inside a torus' hole reflection rays meet the torus again: the blend differs there.
  s.camera.eye = {0, -2.2, 1.6};
  const Image torusOn = render(torus_, s);
  s.reflection.enabled = false;
  const Image torusOff = render(torus_, s);
  int seesSurface = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      const auto p = at(torusOff, i, j), q = at(torusOn, i, j);
      if (p == std::array<double, 3>{kBackground[0], kBackground[1], kBackground[2]}) continue;
      double worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(q[c] - (0.7 * p[c] + 0.3 * kBackground[c])));
      seesSurface += worst > 4.0 / 255;
    }
  EXPECT_GT(seesSurface, 20);
}

TEST_F(Feature, OpacityBlendsFrontAndBackHitsFrontToBack) {
  RenderSettings s = base();
  const auto front = at(render(sphere_, s), kSize / 2, kSize / 2);
  s.opacity = 0.5;
  s.tracing.hits = 2;
  const auto half = at(render(sphere_, s), kSize / 2, kSize / 2);
  // half = 0.5 front + 0.25 back + 0.25 background, so the back hit's color is:
  std::array<double, 3> back{};
  for (int c = 0; c < 3; ++c) back[c] = (half[c] - 0.5 * front[c] - 0.25 * kBackground[c]) / 0.25;
  EXPECT_GT(back[2], back[0]) << "the back face takes the blue back material";
  EXPECT_GT(front[0], front[2]) << "the front face takes the orange front material";
  s.tracing.hits = 1;  // only the nearest hit kept: the rest is background
  const auto one = at(render(sphere_, s), kSize / 2, kSize / 2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(one[c], 0.5 * front[c] + 0.5 * kBackground[c], 1.5 / 255);
  s.opacity = 0;
  EXPECT_DOUBLE_EQ(test::fractionNear(render(sphere_, s), kBackground, 1), 1.0);
}

TEST_F(Feature, BothLightsContributeAndAmbientAloneIsFlat) {
  RenderSettings s = base();
  auto brightness = [](const Image& image) {
    double sum = 0;
    for (std::uint8_t v : image.rgba) sum += v;
    return sum;
  };
  const double both = brightness(render(sphere_, s));
  RenderSettings noDir = s;
  noDir.lights.sources[0].intensity = 0;
  RenderSettings noPoint = s;
  noPoint.lights.sources[1].intensity = 0;
  EXPECT_LT(brightness(render(sphere_, noDir)), both * 0.97);
  EXPECT_LT(brightness(render(sphere_, noPoint)), both * 0.97);
  s.lights.sources[0].intensity = 0;
  s.lights.sources[1].intensity = 0;
  const Image flat = render(sphere_, s);
  const auto c = at(flat, kSize / 2, kSize / 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], 0.15 * s.materials.front.color[k], 1.0 / 255);
  const auto other = at(flat, kSize / 2 - 9, kSize / 2 + 6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(other[k], c[k], 1.0 / 255);
}

TEST_F(Feature, SupersamplingSmoothsOnlyTheOutline) {
  RenderSettings s = base();
  const Image one = render(sphere_, s);
  s.samples = 3;
  const Image nine = render(sphere_, s);
  int changed = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      const auto a = at(one, i, j), b = at(nine, i, j);
      double d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a[c] - b[c]));
      if (d <= 8.0 / 255) continue;
      ++changed;
      EXPECT_NEAR(radius(i, j), sphereOutline(), 1.5) << i << "," << j;
    }
  EXPECT_GT(changed, 20);
}

TEST_F(Feature, OrthographicShowsTheTrueRadius) {
  RenderSettings s = base();
  s.camera.projection = Projection::Orthographic;
  s.camera.height = 3;
  const Image image = render(sphere_, s);
  const double r = 1.0 / 1.5 * kSize / 2;  // unit radius over half the height
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      if (std::abs(radius(i, j) - r) < 0.75) continue;
      const bool covered = !test::pixelNear(image, i, j, kBackground);
      EXPECT_EQ(covered, radius(i, j) < r) << i << "," << j;
    }
}

TEST_F(Feature, FrontAndBackFacesUseTheirMaterials) {
  RenderSettings s = base();
  s.lights.sources[0].intensity = 0;
  s.lights.sources[1].intensity = 0;
  s.camera.eye = {0, 0, 0.2};  // inside the sphere: the gradient points away, a back face
  const auto inside = at(render(sphere_, s), kSize / 2, kSize / 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(inside[k], 0.15 * s.materials.back.color[k], 1.0 / 255);
}

TEST_F(Feature, HitsCountOnlyInsideTheClosedDomain) {
  RenderSettings s = base();
  Domain box{{-0.7, -0.7, -0.7}, {0.7, 0.7, 0.7}};
  const Frame f = sphere_->render(s, box, kSize, kSize);
  ASSERT_EQ(f.error, "");
  EXPECT_TRUE(std::isinf(f.depth.at(kSize / 2, kSize / 2)));  // (0,0,+-1) is outside
  const std::vector<Vec3> points = hitPoints(f, s.camera);
  for (const Vec3& p : points)
    for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(p[a]), 0.7 + 1e-4);
  EXPECT_GT(points.size(), 10u);  // the patches around the diagonals
}

TEST_F(Feature, ASphereDomainClipsToTheBallAndMarksItsRim) {
  // The cylinder x^2 + y^2 = 1 seen from the side, in the ball of radius 1.2: hits only
  // where |p| <= 1.2, i.e. |z| <= sqrt(1.2^2 - 1), and the border color along that rim.
  RenderSettings s = base();
  s.camera.eye = {0, 4, 0};
  s.camera.up = {0, 0, 1};
  Domain ball;
  ball.shape = DomainShape::Sphere;
  ball.radius = 1.2;
  s.border.enabled = false;
  const Frame f = cylinder_->render(s, ball, kSize, kSize);
  ASSERT_EQ(f.error, "");
  const std::vector<Vec3> points = hitPoints(f, s.camera);
  for (const Vec3& p : points) EXPECT_LE(std::hypot(p[0], p[1], p[2]), 1.2 + 1e-4);
  const std::size_t covered = points.size();
  EXPECT_GT(covered, 40u);
  // The middle row meets the cylinder at y = 1; a row far above the band does not.
  EXPECT_NEAR(f.depth.at(kSize / 2, kSize / 2), 3.0, 1e-3);
  EXPECT_TRUE(std::isinf(f.depth.at(kSize / 2, 2)));
  // The same box domain shows the cylinder up to the box's faces (|z| <= 1.2).
  Domain box{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}};
  const Frame boxed = cylinder_->render(s, box, kSize, kSize);
  EXPECT_GT(hitPoints(boxed, s.camera).size(), covered);
  s.border.enabled = true;
  s.border.threshold = 0.05;
  const Frame rim = cylinder_->render(s, ball, kSize, kSize);
  EXPECT_GT(test::fractionNear(rim.color, s.border.color), 0.005);
}

TEST_F(Feature, SingularPointMarkersAreDrawnInFrontOfTheSurface) {
  // The Cayley cubic's four nodes (docs/singular.md), marked; both methods draw the marks.
  const std::vector<std::array<double, 3>> nodes{
      {-0.5, -0.5, -0.5}, {-0.5, 0.5, 0.5}, {0.5, -0.5, 0.5}, {0.5, 0.5, -0.5}};
  for (TracingMethod method : {TracingMethod::Bernstein, TracingMethod::Sampling}) {
    std::string error;
    test::SurfaceSpec spec{"4*(x^2 + y^2 + z^2) + 16*x*y*z - 1", {}, 1};
    spec.method = method;
    spec.markers = nodes;
    auto marked = test::makeTracer(spec, error);
    ASSERT_NE(marked, nullptr) << error;
    RenderSettings s = base();
    s.camera.eye = {2.4, 1.8, 3.2};
    const Vec3 pink{0.9, 0.15, 0.55};
    const Frame f = marked->render(s, Domain{}, kSize, kSize);
    ASSERT_EQ(f.error, "");
    // A node in view: the pixel whose ray passes through it shows the marker, in front.
    const CameraBasis basis = cameraBasis(s.camera);
    int seen = 0;
    for (const auto& n : nodes) {
      // Project the node onto the image plane (docs/camera.md) and look at that pixel.
      Vec3 v{n[0] - basis.eye[0], n[1] - basis.eye[1], n[2] - basis.eye[2]};
      const double z = v[0] * basis.forward[0] + v[1] * basis.forward[1] + v[2] * basis.forward[2];
      const double x = (v[0] * basis.right[0] + v[1] * basis.right[1] + v[2] * basis.right[2]) / z;
      const double y = (v[0] * basis.up[0] + v[1] * basis.up[1] + v[2] * basis.up[2]) / z;
      const double half = std::tan(20.0 * M_PI / 180.0);
      const int i = int((x / half + 1) * kSize / 2), j = int((1 - y / half) * kSize / 2);
      if (i < 0 || j < 0 || i >= kSize || j >= kSize) continue;
      const float t = f.depth.at(i, j);
      const double distance = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (std::abs(t - distance) < 0.1) {  // the marker, not a sheet in front of it
        ++seen;
        const auto c = at(f.color, i, j);
        // Pink, shaded: red and blue well above green (the materials are orange and blue).
        EXPECT_GT(c[0], c[1] + 0.2) << "node " << n[0] << " " << n[1] << " " << n[2];
        EXPECT_GT(c[2], c[1] + 0.1) << "node " << n[0] << " " << n[1] << " " << n[2];
      }
    }
    EXPECT_GE(seen, 2);
    spec.markers.clear();
    auto plain = test::makeTracer(spec, error);
    ASSERT_NE(plain, nullptr) << error;
    EXPECT_EQ(test::fractionNear(plain->render(s, Domain{}, kSize, kSize).color, pink, 12), 0.0);
  }
}

TEST_F(Feature, BoxProxyAndFullScreenTrianglesGiveTheSamePicture) {
  RenderSettings s = base();
  s.camera.eye = {1.0, 3.2, 3.9};
  s.samples = 2;  // subsample rays reach past the pixel centers the box is rasterized at
  s.reflection.enabled = true;
  for (RayTracer* tracer : {sphere_, torus_, cylinder_}) {
    tracer->setProxy(Proxy::FullScreen);
    const Frame full = tracer->render(s, Domain{}, kSize, kSize);
    tracer->setProxy(Proxy::Box);
    const Frame box = tracer->render(s, Domain{}, kSize, kSize);
    ASSERT_EQ(full.error, "");
    EXPECT_EQ(full.color.rgba, box.color.rgba);
    for (std::size_t p = 0; p < full.depth.values.size(); ++p)
      EXPECT_EQ(full.depth.values[p], box.depth.values[p]);
  }
}

TEST_F(Feature, TilesProgressAndCancel) {
  RenderSettings s = base();
  int calls = 0, lastTotal = 0;
  const Frame tiled = sphere_->render(
      s, Domain{}, 100, 70,
      [&](int done, int total) {
        EXPECT_EQ(done, ++calls);
        lastTotal = total;
        return true;
      },
      32);
  ASSERT_EQ(tiled.error, "");
  EXPECT_EQ(calls, 4 * 3);
  EXPECT_EQ(lastTotal, 12);
  const Frame whole = sphere_->render(s, Domain{}, 100, 70, {}, 4096);
  EXPECT_EQ(tiled.color.rgba, whole.color.rgba);
  const Frame cancelled = sphere_->render(
      s, Domain{}, 100, 70, [](int, int) { return false; }, 32);
  EXPECT_EQ(cancelled.error, "cancelled");
}

}  // namespace
}  // namespace zs
