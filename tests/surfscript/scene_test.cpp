// surf drawings as zeroset scenes: the same window, orientation and clipping as surf's
// (measured on surf 1.0.6: the shorter side spans -10..10 from the first pixel's centre to
// the last's, +x right, +y up, +z towards the viewer), the formula kept as written.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.hpp"
#include "surfscript/surf_import.hpp"
#include "surfscript/surf_scene.hpp"

namespace zs::surfscript {
namespace {

ImportedScene imported(const std::string& text) {
  auto r = importSurfScript(text, "test.pic");
  if (auto* e = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << formatSceneError(*e);
    return {};
  }
  return std::get<ImportedScene>(std::move(r));
}

// surf's screen point (u, v) at pixel (px, py), counted from the top left.
struct Pixel {
  double px, py;
};
Pixel surfPixel(double u, double v, int w, int h) {
  const double wf = w >= h ? 10.0 * w / h : 10, hf = w >= h ? 10 : 10.0 * h / w;
  return {(u + wf) / (2 * wf) * (w - 1), (hf - v) / (2 * hf) * (h - 1)};
}

// Where zeroset's ray through surf's pixel for screen point (u, v) meets the plane through
// `onPlane` facing the camera.
Vec3 rayPoint(const Scene& s, double u, double v) {
  const Pixel p = surfPixel(u, v, s.width, s.height);
  const Ray ray = primaryRay(s.render.camera, s.width, s.height, p.px, p.py);
  // The ray's point nearest the camera's target plane.
  const Vec3& t = s.render.camera.target;
  double along = 0;
  for (int a = 0; a < 3; ++a) along += (t[a] - ray.origin[a]) * ray.direction[a];
  return {ray.origin[0] + along * ray.direction[0], ray.origin[1] + along * ray.direction[1],
          ray.origin[2] + along * ray.direction[2]};
}

TEST(SurfScene, DefaultWindowIsSurfs) {
  for (auto [w, h] : {std::pair{200, 200}, {300, 200}, {200, 300}}) {
    const ImportedScene r =
        imported("width = " + std::to_string(w) + "; height = " + std::to_string(h) +
                 "; surface = x^2 + y^2 + z^2 - 25; draw_surface;");
    const Scene& s = r.scene;
    EXPECT_EQ(s.formula, "x^2 + y^2 + z^2 - 25");
    EXPECT_EQ(s.render.camera.projection, Projection::Orthographic);
    // zeroset's pixels are square; surf's pitch across is a hair different from its pitch
    // down when w != h (2 wf / (w - 1) against 2 hf / (h - 1)): under a quarter pixel.
    const double pitch = 20.0 / (std::min(w, h) - 1);
    const double tolerance = w == h ? 1e-9 : pitch / 4;
    for (auto [u, v] : {std::pair{0.0, 0.0}, {5.0, 0.0}, {0.0, 5.0}, {-7.0, 3.0}}) {
      const Vec3 q = rayPoint(s, u, v);
      EXPECT_NEAR(q[0], u, tolerance) << w << "x" << h;
      EXPECT_NEAR(q[1], v, tolerance) << w << "x" << h;
    }
    EXPECT_GT(s.render.camera.eye[2], 10) << "+z towards the viewer";
    EXPECT_EQ(s.domain.shape, DomainShape::Sphere);
    EXPECT_DOUBLE_EQ(s.domain.radius, 10);
  }
}

TEST(SurfScene, ACameraTurnAndScaleTurnTheCameraNotTheFormula) {
  // rot_z = 0.5 turns the model +x towards +y on screen; scale 0.5 doubles it.
  const ImportedScene r = imported(
      "rot_z = 0.5; scale_x = 0.5; scale_y = 0.5; scale_z = 0.5;"
      "surface = (x - 2)^2 + y^2 + z^2 - 1; draw_surface;");
  const Scene& s = r.scene;
  EXPECT_EQ(s.formula, "(x - 2)^2 + y^2 + z^2 - 1");
  // The model point (2, 0, 0) is drawn at screen 4 (cos 0.5, sin 0.5).
  const Vec3 q = rayPoint(s, 4 * std::cos(0.5), 4 * std::sin(0.5));
  EXPECT_NEAR(q[0], 2, 1e-9);
  EXPECT_NEAR(q[1], 0, 1e-9);
  EXPECT_NEAR(s.domain.radius, 5, 1e-12) << "surf's clip sphere lives on the screen";
}

TEST(SurfScene, TheScriptsOwnTurnsAreKeptAsideToo) {
  const ImportedScene r = imported(
      "poly f1 = x^4 + y^4 + z^4 - 1; surface = f1; surface = rotate(surface, 0.3, yAxis);"
      "surface = rotate(surface, -0.2, xAxis); draw_surface;");
  EXPECT_EQ(r.scene.formula, "x^4 + y^4 + z^4 - 1");
}

TEST(SurfScene, AStretchedViewWritesTheFormulaOnTheScreen) {
  const ImportedScene r = imported("scale_x = 2; surface = x^2 + y^2 + z^2 - 25; draw_surface;");
  EXPECT_EQ(r.scene.formula, "(2*x)^2 + y^2 + z^2 - 25");
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].message.find("scale"), std::string::npos);
}

TEST(SurfScene, ClipSlabsBecomeTheDomainBox) {
  // SURFER-2008's plane: x = 0 inside |x|, |y|, |z| <= 1, turned with its clip polynomials.
  const ImportedScene r = imported(
      "surface = x; poly f2 = 1-1*x^2; poly f3 = 1-1*y^2; poly f4 = 1-1*z^2;"
      "clip_surface = f2; clip_surface2 = f3; clip_surface3 = f4; clip = 7;"
      "surface = rotate(surface, 1.1, xAxis); clip_surface = rotate(clip_surface, 1.1, xAxis);"
      "clip_surface2 = rotate(clip_surface2, 1.1, xAxis); clip_surface3 = rotate(clip_surface3, "
      "1.1, xAxis);"
      "draw_surface;");
  const Domain& d = r.scene.domain;
  EXPECT_EQ(d.shape, DomainShape::Box);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(d.min[a], -1, 1e-12);
    EXPECT_NEAR(d.max[a], 1, 1e-12);
  }
  EXPECT_EQ(r.scene.formula, "x");
}

TEST(SurfScene, CubeClipLivesInModelSpace) {
  const ImportedScene r = imported(
      "clip = cube; radius = 3; scale_x = 0.5; scale_y = 0.5; scale_z = 0.5;"
      "surface = x*y*z - 0.1; draw_surface;");
  EXPECT_EQ(r.scene.domain.shape, DomainShape::Box);
  EXPECT_DOUBLE_EQ(r.scene.domain.max[0], 3);
}

TEST(SurfScene, LightsColorsAndSurfaces) {
  const ImportedScene r = imported(
      "surface = x^2 + y^2 + z^2 - 25; surface2 = z; surface2_red = 0; inside_red = 10;"
      "background_red = 255; ambient = 40; light2_vol = 20; draw_surface;");
  const Scene& s = r.scene;
  ASSERT_EQ(s.moreSurfaces.size(), 1u);
  EXPECT_EQ(s.moreSurfaces[0].formula, "z");
  EXPECT_DOUBLE_EQ(s.moreSurfaces[0].materials.front.color[0], 0);
  EXPECT_DOUBLE_EQ(s.render.materials.front.color[0], 123.0 / 255);
  EXPECT_DOUBLE_EQ(s.render.materials.back.color[0], 10.0 / 255);
  EXPECT_DOUBLE_EQ(s.render.background[0], 1);
  EXPECT_DOUBLE_EQ(s.render.lights.ambient, 0.4);
  ASSERT_EQ(s.render.lights.sources.size(), 4u) << "lights 1, 2, 3 and 8";
  EXPECT_EQ(s.render.lights.sources[0].kind, LightKind::Point);
  EXPECT_DOUBLE_EQ(s.render.lights.sources[0].position[0], -100);
  EXPECT_DOUBLE_EQ(s.render.lights.sources[1].intensity, 0.2);
}

TEST(SurfScene, ImportErrorsShowTheLine) {
  auto r = importSurfScript("width = 100;\nsurface = x^2 +* y;\n", "bad.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  const std::string text = formatSceneError(std::get<SceneError>(r));
  EXPECT_NE(text.find("bad.pic:2:16: error:"), std::string::npos) << text;
  EXPECT_NE(text.find("  surface = x^2 +* y;\n                 ^"), std::string::npos) << text;

  r = importSurfScript("curve = x^2 - y^3; draw_curve;", "curve.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_NE(std::get<SceneError>(r).hint.find("zeroset surf"), std::string::npos);

  r = importSurfScript("width = 100;", "empty.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_NE(std::get<SceneError>(r).message.find("draws no surface"), std::string::npos);
}

TEST(SurfScene, PicturesOfAScript) {
  auto r = runSurfScript(
      "surface = x^2 + y^2 + z^2 - 25; draw_surface; width = 64; height = 48;"
      "filename = \"/tmp/one.jpg\"; color_file_format = jpg; save_color_image;",
      "p.pic");
  ASSERT_TRUE(std::holds_alternative<ScriptPictures>(r));
  const auto& p = std::get<ScriptPictures>(r);
  ASSERT_EQ(p.pictures.size(), 1u);
  EXPECT_EQ(p.pictures[0].fileName, "/tmp/one.jpg");
  EXPECT_EQ(p.pictures[0].scene.width, 64) << "the size at save time, as surf's buffer";
}

}  // namespace
}  // namespace zs::surfscript
