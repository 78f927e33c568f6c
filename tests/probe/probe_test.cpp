// The probe against analytic answers: the unit sphere and a torus (its outer and inner
// equators), a miss, a pole that is not a surface, and the centre pixel of a picture.
#include "probe/probe.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <variant>

namespace zs {
namespace {

Formula parse(const char* text) {
  ParseResult parsed = parseFormula(text);
  EXPECT_TRUE(std::holds_alternative<Formula>(parsed)) << text;
  return std::get<Formula>(std::move(parsed));
}

ProbeResult probe(const char* formula, const Ray& ray, Domain domain = {}) {
  const Formula f = parse(formula);
  auto result = probeRay(f, {}, domain, ray);
  EXPECT_TRUE(std::holds_alternative<ProbeResult>(result));
  return std::get<ProbeResult>(result);
}

Domain cube(double half) {
  Domain d;
  d.min = {-half, -half, -half};
  d.max = {half, half, half};
  return d;
}

constexpr double kTol = 1e-4;

TEST(Probe, UnitSphereHasTheAnalyticCurvatures) {
  const ProbeResult r = probe("x^2 + y^2 + z^2 - 1", Ray{{0, 0, 4}, {0, 0, -1}}, cube(2));
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.t, 3, 1e-9);
  EXPECT_NEAR(r.point[2], 1, 1e-9);
  EXPECT_NEAR(r.value, 0, 1e-9);
  EXPECT_NEAR(r.normal[2], 1, 1e-12);
  EXPECT_NEAR(r.gaussian, 1, kTol);
  EXPECT_NEAR(r.mean, 1, kTol);  // grad F points outwards: H = +1/r (docs/curvature.md)
  EXPECT_NEAR(r.k1, 1, kTol);
  EXPECT_NEAR(r.k2, 1, kTol);
}

TEST(Probe, TorusEquatorsHaveTheAnalyticCurvatures) {
  // R = 1, r = 0.4: outer equator (1.4, 0, 0), inner (0.6, 0, 0).
  const char* torus = "(x^2 + y^2 + z^2 + 1 - 0.16)^2 - 4*(x^2 + y^2)";
  const double R = 1, r = 0.4;
  const ProbeResult outer = probe(torus, Ray{{3, 0, 0}, {-1, 0, 0}}, cube(2));
  ASSERT_TRUE(outer.hit);
  EXPECT_NEAR(outer.point[0], R + r, 1e-9);
  EXPECT_NEAR(outer.gaussian, 1 / (r * (R + r)), kTol);
  EXPECT_NEAR(outer.mean, 0.5 * (1 / r + 1 / (R + r)), kTol);
  EXPECT_NEAR(outer.k1, 1 / r, kTol);
  EXPECT_NEAR(outer.k2, 1 / (R + r), kTol);
  const ProbeResult inner = probe(torus, Ray{{0, 0, 0}, {1, 0, 0}}, cube(2));
  ASSERT_TRUE(inner.hit);
  EXPECT_NEAR(inner.point[0], R - r, 1e-9);
  EXPECT_NEAR(inner.gaussian, -1 / (r * (R - r)), kTol);
  EXPECT_NEAR(inner.mean, 0.5 * (1 / r - 1 / (R - r)), kTol);
  EXPECT_NEAR(inner.k1, 1 / r, kTol);
  EXPECT_NEAR(inner.k2, -1 / (R - r), kTol);
}

TEST(Probe, MissesAndPolesAreNoHit) {
  EXPECT_FALSE(probe("x^2 + y^2 + z^2 - 1", Ray{{0, 3, 4}, {0, 0, -1}}, cube(2)).hit);
  // 1/x changes sign at x = 0 without a root.
  EXPECT_FALSE(probe("1/x", Ray{{2, 0.3, 0.2}, {-1, 0, 0}}, cube(3)).hit);
  // Outside the ball domain nothing is found, though the plane continues there.
  Domain ball;
  ball.shape = DomainShape::Sphere;
  ball.center = {0, 0, 0};
  ball.radius = 1;
  EXPECT_FALSE(probe("z", Ray{{3, 0, 1}, {-1, 0, 0}}, ball).hit);
  EXPECT_TRUE(probe("z - 0.5", Ray{{0, 0, 3}, {0, 0, -1}}, ball).hit);
}

TEST(Probe, TangentRayTouchesTheSquaredSphere) {
  // (x^2+y^2+z^2-1)^2 has no sign change at all: still a surface.
  const ProbeResult r = probe("(x^2 + y^2 + z^2 - 1)^2", Ray{{0, 0, 4}, {0, 0, -1}}, cube(2));
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.point[2], 1, 1e-4);
}

TEST(Probe, CentrePixelOfThePicture) {
  Scene scene;  // the unit sphere, the default camera looking at the origin
  const Formula f = parse(scene.formula.c_str());
  auto result = probePixel(f, {}, scene, 101, 101, 50, 50);
  ASSERT_TRUE(std::holds_alternative<ProbeResult>(result));
  const ProbeResult& r = std::get<ProbeResult>(result);
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(std::hypot(r.point[0], r.point[1], r.point[2]), 1, 1e-9);
  EXPECT_NEAR(r.gaussian, 1, kTol);
  EXPECT_TRUE(std::holds_alternative<std::string>(probePixel(f, {}, scene, 10, 10, 10, 3)));
  EXPECT_NE(probeText(r).find("k2: "), std::string::npos);
  EXPECT_NE(probeJson(r).find("\"K\": "), std::string::npos);
  EXPECT_EQ(probeText(ProbeResult{}), "hit: false\n");
}

TEST(Probe, ClipPlanesCutTheRayAsTheTracerDoes) {
  Scene scene;  // the unit sphere seen along the view direction from the default eye
  const Formula f = parse(scene.formula.c_str());
  // The plane through the origin facing the eye cuts away the near half: the centre ray
  // meets the sphere's far side, on the inside.
  const Vec3& e = scene.render.camera.eye;
  scene.render.clipPlanes = {{true, e, 0}};
  auto result = probePixel(f, {}, scene, 101, 101, 50, 50);
  ASSERT_TRUE(std::holds_alternative<ProbeResult>(result));
  const ProbeResult& r = std::get<ProbeResult>(result);
  ASSERT_TRUE(r.hit);
  EXPECT_LE(r.point[0] * e[0] + r.point[1] * e[1] + r.point[2] * e[2], 1e-9);
  EXPECT_NEAR(std::hypot(r.point[0], r.point[1], r.point[2]), 1, 1e-9);
  // Switched off it cuts nothing; a plane that keeps nothing leaves no hit.
  scene.render.clipPlanes[0].enabled = false;
  const ProbeResult near = std::get<ProbeResult>(probePixel(f, {}, scene, 101, 101, 50, 50));
  EXPECT_GT(near.point[0] * e[0] + near.point[1] * e[1] + near.point[2] * e[2], 0);
  scene.render.clipPlanes = {{true, {0, 0, 1}, -5}};
  EXPECT_FALSE(std::get<ProbeResult>(probePixel(f, {}, scene, 101, 101, 50, 50)).hit);
}

TEST(Probe, SeveralSurfacesReportTheNearestHitWithItsOwnCurvatures) {
  // The unit sphere, and in front of it on the centre ray a ball of radius r = 0.2 (a
  // parameter of the scene) centred at 1.25 along the eye's direction, inside the domain.
  Scene scene;
  const Vec3& e = scene.render.camera.eye;
  const double d = std::hypot(e[0], e[1], e[2]);
  const Vec3 c{1.25 * e[0] / d, 1.25 * e[1] / d, 1.25 * e[2] / d};
  char formula[200];
  std::snprintf(formula, sizeof formula, "(x-(%.17g))^2 + (y-(%.17g))^2 + (z-(%.17g))^2 - r^2",
                c[0], c[1], c[2]);
  scene.moreSurfaces = {SurfaceEntry{formula, 0, {}}};
  scene.params = {{"r", 0.2}};
  SceneProbe probe(scene);
  ASSERT_EQ(probe.error(), "");
  const ProbeResult centre = std::get<ProbeResult>(probe.pixel(scene, 101, 101, 50, 50));
  ASSERT_TRUE(centre.hit);
  EXPECT_EQ(centre.surface, 1);
  EXPECT_EQ(centre.surfaces, 2);
  EXPECT_NEAR(centre.t, d - 1.25 - 0.2, 1e-9);
  EXPECT_NEAR(centre.gaussian, 1 / 0.04, 1e-3);
  EXPECT_NEAR(centre.mean, 1 / 0.2, 1e-4);
  EXPECT_EQ(probeText(centre).rfind("surface: 2\npoint: ", 0), 0u) << probeText(centre);
  EXPECT_NE(probeJson(centre).find("\"surface\": 2"), std::string::npos);
  // Off the small ball, the unit sphere, with its own curvatures.
  const ProbeResult side = std::get<ProbeResult>(probe.pixel(scene, 101, 101, 50, 80));
  ASSERT_TRUE(side.hit);
  EXPECT_EQ(side.surface, 0);
  EXPECT_NEAR(side.gaussian, 1, kTol);
  EXPECT_NEAR(std::hypot(side.point[0], side.point[1], side.point[2]), 1, 1e-9);
  // A formula that does not parse is said, naming its surface.
  scene.moreSurfaces[0].formula = "x +";
  EXPECT_NE(SceneProbe(scene).error().find("surface 2:"), std::string::npos);
}

}  // namespace
}  // namespace zs
