// Lights and materials (docs/surf-format.md): every light of a list of up to 8 adds its
// own light, a light that is off adds none, the back material colors back faces, and the
// material weights scale the terms they name.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "render/shading_defines.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 48;

double brightness(const Image& image) {
  double sum = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    sum += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
  return sum;
}

class Shading : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    if (!test::context(Backend::Egl, error)) return;
    sphere_ = test::makeTracer({"x^2+y^2+z^2-1", {}, 2}, error).release();
  }
  static void TearDownTestSuite() { delete sphere_; }
  void SetUp() override {
    std::string error;
    ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
    ASSERT_NE(sphere_, nullptr);
  }
  static RenderSettings base() {
    RenderSettings s = test::testSettings({0, 0, 3});
    s.background = {0, 0, 0};
    s.silhouette.enabled = false;
    s.border.enabled = false;
    s.reflection.enabled = false;
    return s;
  }
  static Image render(const RenderSettings& s, const Domain& domain = Domain{}) {
    Frame f = sphere_->render(s, domain, kSize, kSize);
    EXPECT_EQ(f.error, "");
    return f.color;
  }
  static inline RayTracer* sphere_ = nullptr;
};

// Eight lights from eight directions around the view axis, alternating kinds.
std::vector<Light> eightLights() {
  std::vector<Light> lights;
  for (int i = 0; i < kMaxLights; ++i) {
    const double a = 2 * M_PI * i / kMaxLights;
    Light l;
    l.kind = i % 2 ? LightKind::Point : LightKind::Directional;
    l.direction = {-std::cos(a), -std::sin(a), -0.5};
    l.position = {3 * std::cos(a), 3 * std::sin(a), 1.5};
    l.intensity = 0.3;
    l.color = {1, 0.9, 0.8};
    lights.push_back(l);
  }
  return lights;
}

TEST_F(Shading, EachOfEightLightsContributes) {
  RenderSettings s = base();
  s.lights.ambient = 0;
  s.lights.sources = eightLights();
  s.materials.front.specular = 0;
  const double all = brightness(render(s));
  ASSERT_GT(all, 0);
  double sumOfSingles = 0;
  for (int i = 0; i < kMaxLights; ++i) {
    RenderSettings without = s;
    without.lights.sources[i].enabled = false;
    const double rest = brightness(render(without));
    EXPECT_LT(rest, all * 0.97) << "light " << i + 1 << " adds nothing";
    RenderSettings only = s;
    for (int j = 0; j < kMaxLights; ++j) only.lights.sources[j].enabled = j == i;
    const double single = brightness(render(only));
    EXPECT_GT(single, all * 0.03) << "light " << i + 1 << " alone";
    sumOfSingles += single;
  }
  // Diffuse light adds up (up to 8-bit rounding and clamping, which only lower the total).
  EXPECT_NEAR(all, sumOfSingles, 0.03 * all);
}

TEST_F(Shading, NoLightsLeaveTheAmbientTermOnly) {
  RenderSettings s = base();
  s.lights.sources.clear();
  s.lights.ambient = 0.5;
  s.materials.front.ambient = 0.6;
  const Image flat = render(s);
  const std::uint8_t* p = flat.pixel(kSize / 2, kSize / 2);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(p[k] / 255.0, 0.3 * s.materials.front.color[k], 1.0 / 255);
}

TEST_F(Shading, DiffuseWeightScalesTheLights) {
  RenderSettings s = base();
  s.lights.ambient = 0;
  s.materials.front.specular = 0;
  const double full = brightness(render(s));
  s.materials.front.diffuse = 0.5;
  EXPECT_NEAR(brightness(render(s)), 0.5 * full, 0.02 * full);
  s.materials.front.diffuse = 0;
  EXPECT_EQ(brightness(render(s)), 0);
}

TEST_F(Shading, BackFacesTakeTheBackMaterial) {
  // The domain cuts the sphere's near cap off at z = 0.6: the center ray enters the hole
  // and hits the inside of the far cap (a back face); rays between the hole's rim (radius
  // 0.8) and the outline (radius 1) hit the outside (front faces). Orthographic, 3 units
  // high: the rim is at 12.8 pixels from the center, the outline at 16.
  RenderSettings s = base();
  s.camera.projection = Projection::Orthographic;
  s.camera.height = 3;
  s.lights.sources.clear();
  s.lights.ambient = 1;
  s.materials.front.color = {1, 0, 0};
  s.materials.back.color = {0, 1, 0};
  Domain cut;
  cut.max[2] = 0.6;
  const Image image = render(s, cut);
  EXPECT_TRUE(test::pixelNear(image, kSize / 2, kSize / 2, {0, 1, 0})) << "back face";
  EXPECT_TRUE(test::pixelNear(image, kSize / 2 + 14, kSize / 2, {1, 0, 0})) << "front face";
  EXPECT_TRUE(test::pixelNear(image, kSize / 2 - 15, kSize / 2, {1, 0, 0})) << "front face";
}

TEST_F(Shading, NormalColoringShowsTheNormalOfTheSideSeen) {
  RenderSettings s = base();
  s.shading.color = ColorMode::Normal;
  const Image image = render(s);
  EXPECT_TRUE(test::pixelNear(image, kSize / 2, kSize / 2, {0.5, 0.5, 1.0}, 4));
}

int occurrences(const std::string& text, const std::string& word) {
  int n = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

TEST(ShadingDefines, OneConstantEntryPerLightThatIsOn) {
  RenderSettings s;
  std::string d = shadingDefines(s);
  EXPECT_EQ(occurrences(d, "RT_DIRECTIONAL("), 1) << d;
  EXPECT_EQ(occurrences(d, "RT_POINT("), 1) << d;
  // Default directional light: direction (-0.4, -0.6, -1), so towards it is its negation,
  // normalized; color 0.8 = white x intensity.
  EXPECT_NE(
      d.find("RT_DIRECTIONAL(vec3(0.324442842, 0.486664263, 0.811107106), vec3(0.8, 0.8, 0.8))"),
      std::string::npos)
      << d;
  EXPECT_NE(d.find("RT_POINT(vec3(3.0, 3.0, 4.0), vec3(0.6, 0.6, 0.6))"), std::string::npos) << d;
  EXPECT_NE(d.find("#define RT_KEY_LIGHT vec3(0.324442842"), std::string::npos) << d;
  EXPECT_NE(d.find("#define RT_COLOR 0\n"), std::string::npos);
  s.lights.sources[0].enabled = false;
  s.shading.color = ColorMode::Mean;
  d = shadingDefines(s);
  EXPECT_EQ(occurrences(d, "RT_DIRECTIONAL("), 0) << d;
  EXPECT_EQ(d.find("RT_KEY_LIGHT"), std::string::npos) << "no directional light is on";
  EXPECT_NE(d.find("#define RT_COLOR 2\n"), std::string::npos);
  s.lights.sources.clear();
  EXPECT_EQ(shadingDefines(s).rfind("#define RT_LIGHTS\n", 0), 0u);
}

TEST(CurvatureRange, NinetyFifthPercentileOfTheMagnitudesWithAFloor) {
  std::vector<float> values(100, NAN);  // misses do not count
  for (int i = 0; i < 20; ++i) values[i] = (i % 2 ? -1.0f : 1.0f) * float(i + 1);  // |v| 1..20
  EXPECT_EQ(curvatureRangeOf(values, 0.5), 19.0);  // index floor(0.95 * 19) = 18 of 1..20
  EXPECT_EQ(curvatureRangeOf(std::vector<float>(10, 0.0f), 0.25), 0.25);
  EXPECT_EQ(curvatureRangeOf(std::vector<float>(10, NAN), 0.25), 1.0);  // nothing hit
}

}  // namespace
}  // namespace zs

namespace zs {
namespace {

// shading.shadows: a ball above the floor z = -0.6 under one directional light. Where the
// ball blocks the light the floor keeps only its ambient term; elsewhere the picture is the
// one without shadows. Every tracing method traces the shadow rays itself.
class Shadows : public ::testing::TestWithParam<TracingMethod> {};

TEST_P(Shadows, TheBallDarkensTheFloorExactlyWhereItBlocksTheLight) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  const Vec3 centre{0, 0, 0.4};
  const double radius = 0.4, floorZ = -0.6;
  test::SurfaceSpec spec{"(x^2+y^2+(z-0.4)^2-0.16)*(z+0.6)", {}, 2};
  spec.method = GetParam();
  auto tracer = test::makeTracer(spec, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings s = test::testSettings({2.2, 1.4, 2.4});
  s.reflection.enabled = false;
  s.silhouette.enabled = false;
  s.border.enabled = false;
  Light sun;
  sun.direction = {-0.5, -0.3, -1};  // travelling down and a little sideways
  s.lights.sources = {sun};
  constexpr int size = 72;
  const Image lit = tracer->render(s, spec.domain, size, size).color;
  s.shading.shadows = true;
  const Frame shadowed = tracer->render(s, spec.domain, size, size);
  ASSERT_EQ(shadowed.error, "");

  // Does the line from p towards the light pass through the ball, and how clearly (the
  // closest approach's distance from the ball's surface; negative inside)?
  const double len = std::sqrt(0.25 + 0.09 + 1);
  const Vec3 towards{0.5 / len, 0.3 / len, 1 / len};
  auto clearance = [&](const Vec3& p) {
    Vec3 oc{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
    const double b = oc[0] * towards[0] + oc[1] * towards[1] + oc[2] * towards[2];
    const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2];
    if (b > 0) return std::sqrt(c) - radius;  // the ball is behind: never blocks
    return std::sqrt(std::max(c - b * b, 0.0)) - radius;
  };
  int inShadow = 0, inLight = 0;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const Ray r = primaryRay(s.camera, size, size, i, j);
      if (std::abs(r.direction[2]) < 1e-9) continue;
      const double t = (floorZ - r.origin[2]) / r.direction[2];
      const Vec3 p{r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1], floorZ};
      // Only pixels whose first hit is the floor, well inside the domain.
      if (t <= 0 || std::abs(p[0]) > 1.4 || std::abs(p[1]) > 1.4) continue;
      if (std::abs(shadowed.depth.at(i, j) - t) > 1e-3) continue;  // the ball is in front
      const double c = clearance(p);
      const std::uint8_t* a = lit.pixel(i, j);
      const std::uint8_t* b = shadowed.color.pixel(i, j);
      const int before = a[0] + a[1] + a[2], after = b[0] + b[1] + b[2];
      if (c < -0.02) {
        ++inShadow;
        EXPECT_LT(after, before - 60) << "pixel " << i << "," << j << " should be in shadow";
      } else if (c > 0.02) {
        ++inLight;
        EXPECT_EQ(after, before) << "pixel " << i << "," << j << " should be lit";
      }
    }
  }
  EXPECT_GT(inShadow, 40);
  EXPECT_GT(inLight, 400);
  std::printf("  %d floor pixels in shadow, %d lit\n", inShadow, inLight);
}

INSTANTIATE_TEST_SUITE_P(Methods, Shadows,
                         ::testing::Values(TracingMethod::Sampling, TracingMethod::Bernstein,
                                           TracingMethod::Interval),
                         [](const auto& info) {
                           return std::string(tracingMethodName(info.param));
                         });

TEST(ShadingDefines, ShadowsNumberTheLightsAndSayWhereTheirRaysGo) {
  RenderSettings s;
  s.shading.shadows = true;
  const std::string d = shadingDefines(s);
  EXPECT_NE(d.find("#define RT_SHADOWS 2\n"), std::string::npos) << d;
  EXPECT_NE(d.find("RT_DIRECTIONAL_SHADOWED(0, "), std::string::npos) << d;
  EXPECT_NE(d.find("RT_POINT_SHADOWED(1, "), std::string::npos) << d;
  EXPECT_NE(d.find("RT_SHADOW_POINT(1, vec3(3.0, 3.0, 4.0))"), std::string::npos) << d;
  s.shading.shadows = false;
  EXPECT_EQ(shadingDefines(s).find("SHADOW"), std::string::npos);
}

}  // namespace
}  // namespace zs

namespace zs {
namespace {

// lights.space = "camera": the lights turn with the view, so the unit sphere, which looks the
// same from everywhere, gives the same picture from every side; lights fixed in the world
// light it from elsewhere once the camera has moved.
TEST(LightSpace, CameraLightsTurnWithTheView) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  auto tracer = test::makeTracer({"x^2+y^2+z^2-1", {}, 2}, error);
  ASSERT_NE(tracer, nullptr) << error;
  auto picture = [&](LightSpace space, Vec3 eye) {
    RenderSettings s = test::testSettings(eye);
    s.reflection.enabled = false;
    s.lights.space = space;
    s.camera.up = {0, 1, 0};
    Light l;
    l.kind = LightKind::Point;
    l.position = {1.5, 1.0, 0.5};  // right of and above the eye
    s.lights.sources = {l};
    return tracer->render(s, Domain{}, 48, 48).color;
  };
  const Vec3 front{0, 0, 3}, side{3, 0, 0};
  const ImageDiff camera =
      compareImages(picture(LightSpace::Camera, front), picture(LightSpace::Camera, side), 2);
  EXPECT_LT(camera.fractionOver, 0.002) << "the same lighting seen from the side";
  const ImageDiff world =
      compareImages(picture(LightSpace::World, front), picture(LightSpace::World, side), 2);
  EXPECT_GT(world.fractionOver, 0.2) << "world lights light the sphere from elsewhere";
}

}  // namespace
}  // namespace zs
