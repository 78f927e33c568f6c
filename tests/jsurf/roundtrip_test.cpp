// .surf -> .jsurf -> .surf is the identity on every key SURFER has: the formula and its
// parameters, the clipping sphere's radius, the camera (projection, field of view, height,
// eye, the point looked at, up), the background, the materials and the lights. What SURFER
// cannot hold comes back canonical: up unit and orthogonal to the view, the target where
// the line of sight passes the sphere's centre.
#include <gtest/gtest.h>

#include <cmath>

#include "jsurf/jsurf.hpp"
#include "render/camera.hpp"

namespace zs::jsurf {
namespace {

Scene roundTrip(const Scene& s) {
  auto exported = exportJsurf(s);
  if (auto* err = std::get_if<std::string>(&exported)) {
    ADD_FAILURE() << *err;
    return {};
  }
  ImportResult r = importJsurf(std::get<Exported>(exported).text, "round.jsurf");
  if (auto* err = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << formatSceneError(*err) << std::get<Exported>(exported).text;
    return {};
  }
  return std::get<Imported>(r).scene;
}

void expectNear(const Vec3& a, const Vec3& b, const char* what) {
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(a[i], b[i], 1e-9 * (1 + std::abs(b[i]))) << what << "[" << i << "]";
}

// Where a light stands in the world, whether the scene fixes it there or to its camera.
Vec3 inWorld(const Scene& s, const Light& l) {
  return s.render.lights.space == LightSpace::Camera
             ? cameraPointToWorld(s.render.camera, l.position)
             : l.position;
}

void expectSurferKeysEqual(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.formula, b.formula);
  EXPECT_EQ(a.params, b.params);
  EXPECT_EQ(a.domain.shape, b.domain.shape);
  EXPECT_NEAR(a.domain.radius, b.domain.radius, 1e-12 * b.domain.radius);
  const Camera& ca = a.render.camera;
  const Camera& cb = b.render.camera;
  EXPECT_EQ(ca.projection, cb.projection);
  EXPECT_NEAR(ca.fovY, cb.fovY, 1e-12);
  EXPECT_NEAR(ca.height, cb.height, 1e-12 * cb.height);
  expectNear(ca.eye, cb.eye, "camera.eye");
  expectNear(ca.target, cb.target, "camera.target");
  expectNear(ca.up, cb.up, "camera.up");
  expectNear(a.render.background, b.render.background, "background");
  const Materials& ma = a.render.materials;
  const Materials& mb = b.render.materials;
  for (const auto& [x, y] : {std::pair{&ma.front, &mb.front}, std::pair{&ma.back, &mb.back}}) {
    expectNear(x->color, y->color, "material color");
    EXPECT_DOUBLE_EQ(x->ambient, y->ambient);
    EXPECT_DOUBLE_EQ(x->diffuse, y->diffuse);
    EXPECT_DOUBLE_EQ(x->specular, y->specular);
    EXPECT_DOUBLE_EQ(x->shininess, y->shininess);
  }
  const Lights& la = a.render.lights;
  const Lights& lb = b.render.lights;
  EXPECT_DOUBLE_EQ(la.ambient, lb.ambient);
  ASSERT_EQ(la.sources.size(), lb.sources.size());
  for (std::size_t i = 0; i < la.sources.size(); ++i) {
    EXPECT_EQ(la.sources[i].kind, lb.sources[i].kind);
    EXPECT_EQ(la.sources[i].enabled, lb.sources[i].enabled);
    expectNear(inWorld(a, la.sources[i]), inWorld(b, lb.sources[i]), "light position");
    EXPECT_DOUBLE_EQ(la.sources[i].intensity, lb.sources[i].intensity);
    expectNear(la.sources[i].color, lb.sources[i].color, "light color");
  }
}

Light pointLight(Vec3 position, double intensity, Vec3 color, bool enabled = true) {
  Light l;
  l.kind = LightKind::Point;
  l.position = position;
  l.intensity = intensity;
  l.color = color;
  l.enabled = enabled;
  return l;
}

Scene sphereScene() {
  Scene s;
  s.formula = "x^4 + y^4 + z^4 - a*(x^2 + y^2 + z^2) + b";
  s.params = {{"a", 1.25}, {"b", 0.3}};
  s.domain.shape = DomainShape::Sphere;
  s.domain.radius = 1.7;
  s.render.background = {0.1, 0.2, 0.3};
  s.render.materials.front = {{0.9, 0.4, 0.1}, 0.6, 25.0, 0.3, 0.8};
  s.render.materials.back = {{0.1, 0.4, 0.9}, 0.2, 80.0, 0.25, 0.7};
  // SURFER has no ambient light apart from the materials' weights: 1 keeps them as they are.
  s.render.lights.ambient = 1.0;
  s.render.lights.sources = {pointLight({4, -2, 6}, 0.7, {1, 0.9, 0.8}),
                             pointLight({-30, 50, 20}, 0.4, {0.8, 0.9, 1}),
                             pointLight({0, 0, -9}, 1.5, {1, 1, 1}, false)};
  return s;
}

TEST(JsurfRoundTrip, PerspectiveCameraSeenFromAnAngle) {
  Scene s = sphereScene();
  s.render.camera.eye = {3, 2.5, 4};
  s.render.camera.target = {0, 0, 0};
  // up as SURFER keeps it: unit and orthogonal to the view.
  const Vec3 f{-3, -2.5, -4};
  const Vec3 upHint{0, 1, 0};
  Vec3 right{f[1] * upHint[2] - f[2] * upHint[1], f[2] * upHint[0] - f[0] * upHint[2],
             f[0] * upHint[1] - f[1] * upHint[0]};
  Vec3 up{right[1] * f[2] - right[2] * f[1], right[2] * f[0] - right[0] * f[2],
          right[0] * f[1] - right[1] * f[0]};
  const double l = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  for (double& c : up) c /= l;
  s.render.camera.up = up;
  s.render.camera.fovY = 35;
  expectSurferKeysEqual(roundTrip(s), s);
}

TEST(JsurfRoundTrip, OrthographicCameraLookingDownZ) {
  Scene s = sphereScene();
  s.render.camera.projection = Projection::Orthographic;
  s.render.camera.height = 5.5;
  s.render.camera.eye = {0, 0, 1.7};
  s.render.camera.up = {1, 0, 0};
  expectSurferKeysEqual(roundTrip(s), s);
}

TEST(JsurfRoundTrip, RoundTripOfAnImportedFileIsStable) {
  // .jsurf -> .surf -> .jsurf -> .surf: the second import equals the first.
  const Scene first = roundTrip(sphereScene());
  expectSurferKeysEqual(roundTrip(first), first);
}

TEST(JsurfRoundTrip, AmbientLightGoesIntoTheMaterialsWeights) {
  Scene s = sphereScene();
  s.render.lights.ambient = 0.5;
  const Scene back = roundTrip(s);
  EXPECT_DOUBLE_EQ(back.render.lights.ambient, 1.0);
  EXPECT_DOUBLE_EQ(back.render.materials.front.ambient, 0.15);
  EXPECT_DOUBLE_EQ(back.render.materials.back.ambient, 0.125);
}

TEST(JsurfRoundTrip, DirectionalLightBecomesAFarPointLightInItsDirection) {
  Scene s = sphereScene();
  Light sun;  // directional, travelling down -y
  sun.direction = {0, -2, 0};
  s.render.lights.sources = {sun};
  const Scene back = roundTrip(s);
  ASSERT_EQ(back.render.lights.sources.size(), 1u);
  const Light& l = back.render.lights.sources[0];
  EXPECT_EQ(l.kind, LightKind::Point);
  const Vec3 world = inWorld(back, l);
  EXPECT_NEAR(world[0], 0, 1e-9);
  EXPECT_NEAR(world[1], 1000 * 1.7, 1e-6);  // a thousand clipping radii up
  EXPECT_NEAR(world[2], 0, 1e-9);
}

TEST(JsurfRoundTrip, UpAndTargetComeBackCanonical) {
  Scene s = sphereScene();
  s.render.camera.eye = {0, 0, 4};
  s.render.camera.target = {0, 0, -3};  // beyond the centre, on the same line of sight
  s.render.camera.up = {0, 2, 1};       // not unit, not orthogonal
  const Scene back = roundTrip(s);
  expectNear(back.render.camera.target, {0, 0, 0}, "target");
  expectNear(back.render.camera.up, {0, 1, 0}, "up");
  expectNear(back.render.camera.eye, {0, 0, 4}, "eye");
}

}  // namespace
}  // namespace zs::jsurf
