// Several surfaces in one scene ([[surface]]): every method draws the nearer of two spheres
// at every pixel, each in its own material, and marks the circle where they meet, against
// the analytic spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "render_support.hpp"
#include "scene/scene_io.hpp"

namespace zs {
namespace {

constexpr int kSize = 64;

// Sphere A: the unit sphere; sphere B: centre (0.7, 0, 0), radius 0.6. They meet in the
// circle x = kCircleX, y^2 + z^2 = kCircleR^2.
constexpr double kCentreB = 0.7, kRadiusB = 0.6;
const double kCircleX = (1 - kRadiusB * kRadiusB + kCentreB * kCentreB) / (2 * kCentreB);
const double kCircleR = std::sqrt(1 - kCircleX * kCircleX);

// The first t >= 0 at which the ray meets the sphere (centre (cx, 0, 0), radius r); NaN if
// it misses.
double sphereHit(const Ray& ray, double cx, double r) {
  const Vec3 o{ray.origin[0] - cx, ray.origin[1], ray.origin[2]};
  const Vec3& d = ray.direction;
  const double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const double c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - r * r;
  const double disc = b * b - c;
  if (disc < 0) return NAN;
  const double t = -b - std::sqrt(disc);
  return t >= 0 ? t : NAN;
}

// Distance from p to the circle where the spheres meet.
double circleDistance(const Vec3& p) {
  const double rho = std::hypot(p[1], p[2]);
  return std::hypot(p[0] - kCircleX, rho - kCircleR);
}

class SeveralSurfaces : public ::testing::TestWithParam<TracingMethod> {
 protected:
  // The unit sphere and the surface `second`, traced by the method under test.
  std::unique_ptr<RayTracer> tracer(bool highlight,
                                    const std::string& second = "(x-0.7)^2+y^2+z^2-0.36") {
    std::string error;
    EXPECT_NE(test::context(Backend::Egl, error), nullptr) << error;
    test::SurfaceSpec spec{"x^2+y^2+z^2-1", {}, 3};
    spec.method = GetParam();
    SurfaceEntry b;
    b.formula = second;
    b.materials = surfaceMaterials(1);
    b.materials.front.specular = 0;  // no white highlight where the colors are compared
    spec.moreSurfaces = {b};
    Highlight intersection = RenderSettings{}.intersection;
    intersection.enabled = highlight;
    intersection.threshold = 0.04;  // below a pixel's width (3 / 64 at the spheres)
    spec.intersection = intersection;
    auto t = test::makeTracer(spec, error);
    EXPECT_NE(t, nullptr) << error;
    return t;
  }
  static RenderSettings settings() {
    RenderSettings s = test::testSettings({0.6, 0.8, 5.5});
    s.reflection.enabled = false;
    s.silhouette.enabled = false;
    s.border.enabled = false;
    s.background = {0, 0, 0};
    s.materials.front.specular = 0;
    return s;
  }
  // Whether pixel (i, j)'s corners lie on both sides of the sphere's outline: a ray there
  // grazes it within a small fraction of a pixel.
  static bool grazes(const Camera& camera, int i, int j, double cx, double r) {
    const Ray o = primaryRay(camera, kSize, kSize, i + 0.5, j + 0.5);
    const Ray m = primaryRay(camera, kSize, kSize, i - 0.5, j - 0.5);
    return std::isnan(sphereHit(o, cx, r)) != std::isnan(sphereHit(m, cx, r));
  }
  // Both spheres in settings(), the intersection curves drawn or not.
  void render(bool highlight, Frame& frame) {
    std::unique_ptr<RayTracer> t = tracer(highlight);
    ASSERT_NE(t, nullptr);
    frame = t->render(settings(), Domain{}, kSize, kSize);
    ASSERT_EQ(frame.error, "");
  }
};

TEST_P(SeveralSurfaces, EveryPixelShowsTheNearerSphereInItsOwnMaterial) {
  const RenderSettings s = settings();
  Frame f;
  ASSERT_NO_FATAL_FAILURE(render(false, f));
  int onA = 0, onB = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const Ray ray = primaryRay(s.camera, kSize, kSize, i, j);
      const double ta = sphereHit(ray, 0, 1), tb = sphereHit(ray, kCentreB, kRadiusB);
      const double t0 = std::isnan(ta) ? tb : std::isnan(tb) ? ta : std::min(ta, tb);
      // Pixels whose ray grazes a sphere within a small fraction of a pixel are left out.
      if (grazes(s.camera, i, j, 0, 1) || grazes(s.camera, i, j, kCentreB, kRadiusB)) continue;
      const std::optional<Vec3> hit = test::hitPoint(f, s.camera, i, j);
      if (std::isnan(t0)) {
        EXPECT_FALSE(hit) << "a hit where neither sphere is, at " << i << "," << j;
        continue;
      }
      ASSERT_TRUE(hit) << "no hit at " << i << "," << j;
      const Vec3 expected{ray.origin[0] + t0 * ray.direction[0],
                          ray.origin[1] + t0 * ray.direction[1],
                          ray.origin[2] + t0 * ray.direction[2]};
      EXPECT_NEAR(
          std::hypot((*hit)[0] - expected[0], (*hit)[1] - expected[1], (*hit)[2] - expected[2]),
          0.0, 2e-3)
          << "not the nearer sphere's depth at " << i << "," << j;
      // Away from the circle, the hit takes its sphere's front color: A orange (red above
      // green), B green (green above red).
      if (circleDistance(expected) < 0.15) continue;
      const std::uint8_t* c = f.color.pixel(i, j);
      if (t0 == ta) {
        EXPECT_GT(c[0], c[1]) << "sphere A's material at " << i << "," << j;
        ++onA;
      } else {
        EXPECT_GT(c[1], c[0]) << "sphere B's material at " << i << "," << j;
        ++onB;
      }
    }
  }
  EXPECT_GT(onA, 300);
  EXPECT_GT(onB, 30);
  // No intersection curve was asked for.
  EXPECT_EQ(test::fractionNear(f.color, s.intersection.color, 6), 0.0);
}

TEST_P(SeveralSurfaces, TheCircleWhereTheyMeetIsMarkedWhereItProjects) {
  const RenderSettings s = settings();
  Frame f;
  ASSERT_NO_FATAL_FAILURE(render(true, f));
  int marked = 0, onCircle = 0, markedOnCircle = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const std::optional<Vec3> hit = test::hitPoint(f, s.camera, i, j);
      const bool isMarked = test::pixelNear(f.color, i, j, s.intersection.color, 6);
      if (isMarked) {
        ++marked;
        ASSERT_TRUE(hit) << i << "," << j;
        // Within the tolerance of both spheres, which meet at 44 degrees: within
        // 0.04 / sin(44 degrees) = 0.058 of their circle.
        EXPECT_LT(circleDistance(*hit), 0.06) << i << "," << j;
      }
      // Within half the tolerance of the circle: within the tolerance of the other sphere.
      if (hit && circleDistance(*hit) < 0.02) {
        ++onCircle;
        markedOnCircle += isMarked;
      }
    }
  }
  EXPECT_GT(marked, 10);
  EXPECT_GT(onCircle, 3);
  EXPECT_EQ(markedOnCircle, onCircle) << "a pixel on the circle is not marked";
}

// A surface undefined in places (sqrt(0.3 - x) - 0.2: the plane x = 0.26, undefined for
// x > 0.3) hides no other surface there: the product takes 1 for it where it is undefined
// (scene/surfaces.cpp). Every method draws the unit sphere's part x > 0.3 at its depth, and
// no hit lies off both surfaces: the product's jump at x = 0.3 is no surface.
TEST_P(SeveralSurfaces, ASurfaceUndefinedInPlacesHidesNoOtherThere) {
  std::unique_ptr<RayTracer> t = tracer(false, "sqrt(0.3 - x) - 0.2");
  ASSERT_NE(t, nullptr);
  const RenderSettings s = settings();
  const Frame f = t->render(s, Domain{}, kSize, kSize);
  ASSERT_EQ(f.error, "");
  int sphereRight = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const std::optional<Vec3> hit = test::hitPoint(f, s.camera, i, j);
      if (hit) {
        const Vec3& p = *hit;
        const double offSphere = std::abs(std::hypot(p[0], p[1], p[2]) - 1);
        EXPECT_LT(std::min(offSphere, std::abs(p[0] - 0.26)), 0.02)
            << "a hit on neither surface at " << i << "," << j << ": " << p[0] << ", " << p[1]
            << ", " << p[2];
      }
      // From x = 0.6 a ray reaches the sphere's points with x > 0.3 before x = 0.26.
      const Ray ray = primaryRay(s.camera, kSize, kSize, i, j);
      const double ts = sphereHit(ray, 0, 1);
      if (std::isnan(ts) || grazes(s.camera, i, j, 0, 1)) continue;
      if (ray.origin[0] + ts * ray.direction[0] < 0.32) continue;
      ASSERT_TRUE(hit) << "the sphere is missing at " << i << "," << j;
      EXPECT_LT(std::abs(std::hypot((*hit)[0], (*hit)[1], (*hit)[2]) - 1), 2e-3) << i << "," << j;
      ++sphereRight;
    }
  }
  EXPECT_GT(sphereRight, 200);
}

INSTANTIATE_TEST_SUITE_P(Methods, SeveralSurfaces, ::testing::ValuesIn(test::kEveryMethod),
                         test::methodName);

}  // namespace
}  // namespace zs
