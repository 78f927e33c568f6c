// Importing .jsurf files written for these tests: every key lands where SURFER puts it
// (formula, parameters, zoom and clipping radius, orientation, camera, lights, materials,
// background), and bad files give positioned errors or warnings.
#include <gtest/gtest.h>

#include <cmath>

#include "jsurf/jsurf.hpp"
#include "render/camera.hpp"

namespace zs::jsurf {
namespace {

const std::string kData = ZS_JSURF_TEST_DATA;

Imported load(const std::string& name) {
  ImportResult r = loadJsurf(kData + "/" + name);
  if (auto* err = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << formatSceneError(*err);
    return {};
  }
  return std::get<Imported>(std::move(r));
}

SceneError loadError(const std::string& name) {
  ImportResult r = loadJsurf(kData + "/" + name);
  if (std::holds_alternative<Imported>(r)) {
    ADD_FAILURE() << name << " was accepted";
    return {};
  }
  return std::get<SceneError>(r);
}

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

TEST(JsurfImport, FormulaAndParameters) {
  const Scene s = load("turned-quartic.jsurf").scene;
  EXPECT_EQ(s.formula, "x^4 + y^4 + z^4 - a*(x^2 + y^2 + z^2) + b");
  ASSERT_EQ(s.params.size(), 2u);
  EXPECT_EQ(s.params[0], (std::pair<std::string, double>{"a", 1.25}));
  EXPECT_EQ(s.params[1], (std::pair<std::string, double>{"b", 0.125}));
}

TEST(JsurfImport, ZoomIsTheClippingSphereRadius) {
  const Scene s = load("turned-quartic.jsurf").scene;
  EXPECT_EQ(s.domain.shape, DomainShape::Sphere);
  expectNear(s.domain.center, {0, 0, 0});
  EXPECT_NEAR(s.domain.radius, 2.0, 1e-12);  // 10^0.30103
  // camera_height 2 covers the sphere's diameter in SURFER's units: 4 in F's.
  EXPECT_EQ(s.render.camera.projection, Projection::Orthographic);
  EXPECT_NEAR(s.render.camera.height, 4.0, 1e-12);
}

TEST(JsurfImport, RotationTurnsTheCameraAroundTheSurface) {
  // rotation_matrix turns camera space's +z (towards the viewer) into the world's +x: the
  // camera looks down -x from 1 clipping radius out, with +y still up.
  const Camera c = load("turned-quartic.jsurf").scene.render.camera;
  expectNear(c.eye, {2, 0, 0});
  expectNear(c.target, {0, 0, 0});
  expectNear(c.up, {0, 1, 0});
}

TEST(JsurfImport, LightsStayFixedToTheCameraAsSurfersDo) {
  const Scene s = load("turned-quartic.jsurf").scene;
  const Lights& l = s.render.lights;
  EXPECT_EQ(l.space, LightSpace::Camera);
  // Where they stand in the world for the imported view.
  auto world = [&](const Light& light) {
    return cameraPointToWorld(s.render.camera, light.position);
  };
  // Lights 0, 1 (off) and 2; the five slots the file leaves out are not kept.
  ASSERT_EQ(l.sources.size(), 3u);
  for (const Light& light : l.sources) EXPECT_EQ(light.kind, LightKind::Point);
  // light 0 at camera (0, 0, 10): 11 units behind the sphere's centre, turned to +x, scaled 2.
  expectNear(world(l.sources[0]), {22, 0, 0}, 1e-9);
  EXPECT_TRUE(l.sources[0].enabled);
  EXPECT_DOUBLE_EQ(l.sources[0].intensity, 0.75);
  expectNear(l.sources[0].color, {1, 0.5, 0.25});
  // light 1 at camera (5, 5, 5) is off but kept, so that it comes back on export.
  EXPECT_FALSE(l.sources[1].enabled);
  expectNear(world(l.sources[1]), {12, 10, -10}, 1e-9);
  // light 2, far above the camera: above the surface.
  expectNear(world(l.sources[2]), {2, 200, 0}, 1e-9);
  EXPECT_DOUBLE_EQ(l.sources[2].intensity, 0.5);
  expectNear(l.sources[2].color, {0.5, 0.5, 1.0});
  // SURFER's ambient term is the material's weight alone.
  EXPECT_DOUBLE_EQ(l.ambient, 1.0);
}

TEST(JsurfImport, MaterialsAndBackground) {
  const Scene s = load("turned-quartic.jsurf").scene;
  const Materials& m = s.render.materials;
  expectNear(m.front.color, {0.75, 0.5, 0.25});
  EXPECT_DOUBLE_EQ(m.front.ambient, 0.25);
  EXPECT_DOUBLE_EQ(m.front.diffuse, 1.0);
  EXPECT_DOUBLE_EQ(m.front.specular, 0.5);
  EXPECT_DOUBLE_EQ(m.front.shininess, 30.0);
  expectNear(m.back.color, {0.25, 0.5, 0.75});
  EXPECT_DOUBLE_EQ(m.back.specular, 0.25);
  EXPECT_DOUBLE_EQ(m.back.shininess, 20.0);
  expectNear(s.render.background, {0, 0, 0.125});
}

TEST(JsurfImport, LooksLikeSurfer) {
  const Scene s = load("turned-quartic.jsurf").scene;
  EXPECT_FALSE(s.render.silhouette.enabled);
  EXPECT_FALSE(s.render.border.enabled);
  EXPECT_FALSE(s.render.reflection.enabled);
  EXPECT_EQ(s.width, s.height);
}

TEST(JsurfImport, PerspectiveCameraWithoutTransformSitsWhereTheSphereFits) {
  const ImportResult r = importJsurf(
      "surface_equation=x^2+y^2-z^2-0.25\ncamera_type=PERSPECTIVE_CAMERA\ncamera_fov_y=60\n",
      "p.jsurf");
  ASSERT_TRUE(std::holds_alternative<Imported>(r));
  const Camera c = std::get<Imported>(r).scene.render.camera;
  EXPECT_EQ(c.projection, Projection::Perspective);
  EXPECT_DOUBLE_EQ(c.fovY, 60.0);
  expectNear(c.eye, {0, 0, 2}, 1e-12);  // 1 / sin(30 degrees)
}

TEST(JsurfImport, UnknownKeyIsAWarningWithItsPlaceAndAHint) {
  const Imported imported = load("misspelled-key.jsurf");
  ASSERT_EQ(imported.warnings.size(), 1u);
  const SceneError& w = imported.warnings[0];
  EXPECT_EQ(w.line, 2);
  EXPECT_EQ(w.column, 1);
  EXPECT_NE(w.message.find("camera_heigth"), std::string::npos);
  EXPECT_NE(w.hint.find("camera_height"), std::string::npos);
  EXPECT_NE(formatWarning(w).find("misspelled-key.jsurf:2:1: warning: unknown key"),
            std::string::npos);
}

TEST(JsurfImport, ShortMatrixIsAnErrorAtItsEnd) {
  const SceneError e = loadError("bad-matrix.jsurf");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 49);  // just past the 15th number, the end of the line
  EXPECT_NE(e.message.find("16 numbers, found 15"), std::string::npos);
}

TEST(JsurfImport, FormulaErrorPointsIntoTheContinuedLine) {
  const SceneError e = loadError("bad-formula.jsurf");
  EXPECT_EQ(e.line, 3);
  EXPECT_GE(e.column, 4);
  EXPECT_NE(e.message.find("surface_equation"), std::string::npos);
  EXPECT_EQ(e.sourceLine, "   + z^2 - (1");
}

struct BadValue {
  const char* text;
  int line;
  int column;
  const char* message;
};

TEST(JsurfImport, BadValuesAreErrorsAtTheValue) {
  const BadValue cases[] = {
      {"surface_equation=x\nscale_factor=big\n", 2, 14, "not a finite number"},
      {"surface_equation=x\ncamera_type=FISHEYE\n", 2, 13, "ORTHOGRAPHIC_CAMERA"},
      {"surface_equation=x\nlight_status_3=on\n", 2, 16, "ON and OFF"},
      {"surface_equation=x\nbackground_color=1 1\n", 2, 21, "3 numbers, found 2"},
      {"surface_equation=x\ncamera_fov_y=180\n", 2, 14, "(0, 180)"},
      {"surface_equation=x\ncamera_transform=0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1\n", 2, 18, "inverted"},
      {"surface_equation=x\nrotation_matrix=1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1\n", 2, 17, "affine"},
      {"surface_parameter_a=1\n", 0, 0, "no surface_equation"},
      {"surface_equation=x^2 + sinn(y)\n", 1, 24, "unknown function"},
  };
  for (const BadValue& c : cases) {
    const ImportResult r = importJsurf(c.text, "t.jsurf");
    ASSERT_TRUE(std::holds_alternative<SceneError>(r)) << c.text;
    const SceneError& e = std::get<SceneError>(r);
    EXPECT_EQ(e.line, c.line) << c.text;
    EXPECT_EQ(e.column, c.column) << c.text;
    EXPECT_NE(e.message.find(c.message), std::string::npos) << c.text << e.message;
  }
}

TEST(JsurfImport, OddButReadableValuesAreWarnings) {
  const ImportResult r = importJsurf(
      "surface_equation=x\nfront_material_color=2 0 0\nlight_intensity_0=-1\n"
      "surface_parameter_e=1\nsurface_transform_matrix=1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n"
      "surface_equation=y\n",
      "w.jsurf");
  ASSERT_TRUE(std::holds_alternative<Imported>(r));
  const Imported& imported = std::get<Imported>(r);
  EXPECT_EQ(imported.scene.formula, "y");  // the later value counts, as in Java
  EXPECT_DOUBLE_EQ(imported.scene.render.materials.front.color[0], 1.0);
  std::vector<int> lines;
  for (const SceneError& w : imported.warnings) lines.push_back(w.line);
  EXPECT_EQ(lines, (std::vector<int>{6, 2, 3, 4, 5}));
}

TEST(JsurfImport, MissingFileIsAnError) {
  const SceneError e = loadError("no-such-file.jsurf");
  EXPECT_EQ(e.line, 0);
  EXPECT_NE(e.message.find("cannot open"), std::string::npos);
}

TEST(JsurfImport, IsJsurfPath) {
  EXPECT_TRUE(isJsurfPath("a/b.jsurf"));
  EXPECT_TRUE(isJsurfPath("B.JSURF"));
  EXPECT_FALSE(isJsurfPath("b.surf"));
  EXPECT_FALSE(isJsurfPath("x^2+y^2-1"));
}

}  // namespace
}  // namespace zs::jsurf
