// surface.level = c draws F = c: the picture of F with level c is the picture of F - c, and
// the probe and the octree see the same surface.
#include <gtest/gtest.h>

#include <memory>
#include <variant>

#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "probe/probe.hpp"
#include "render_support.hpp"
#include "scene/scene_io.hpp"

namespace zs {
namespace {

Frame draw(const Scene& scene, int size) {
  auto prepared = prepareSurface(scene, kWithoutGlslang);
  EXPECT_TRUE(std::holds_alternative<PreparedSurface>(prepared));
  if (!std::holds_alternative<PreparedSurface>(prepared)) return {};
  auto tracer = std::make_unique<RayTracer>();
  EXPECT_EQ(loadSurface(*tracer, std::get<PreparedSurface>(prepared), scene.render), "");
  return tracer->render(scene.render, scene.domain, size, size);
}

TEST(LevelSet, PictureOfFAtLevelCIsThePictureOfFMinusC) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  for (const char* method : {"bernstein", "interval", "sampling"}) {
    SCOPED_TRACE(method);
    Scene level, shifted;
    level.formula = "x^4 + y^4 + z^4 + sin(x y)";
    level.level = 0.8;
    shifted.formula = "x^4 + y^4 + z^4 + sin(x y) - 0.8";
    for (Scene* s : {&level, &shifted}) {
      ASSERT_FALSE(applyOverride(*s, std::string("tracing.method=\"") + method + "\""));
    }
    const Frame a = draw(level, 48), b = draw(shifted, 48);
    ASSERT_EQ(a.error, "");
    ASSERT_EQ(a.color.rgba, b.color.rgba) << "the two pictures differ";
  }
}

TEST(LevelSet, ParsedFormulaAndProbeSeeFMinusC) {
  Scene scene;
  scene.formula = "x^2 + y^2 + z^2";
  scene.level = 4;  // the sphere of radius 2
  ParseResult parsed = parseSceneFormula(scene);
  ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
  const Formula& f = std::get<Formula>(parsed);
  Domain box;
  box.min = {-3, -3, -3};
  box.max = {3, 3, 3};
  auto r = probeRay(f, {}, box, Ray{{0, 0, 5}, {0, 0, -1}});
  ASSERT_TRUE(std::holds_alternative<ProbeResult>(r));
  EXPECT_NEAR(std::get<ProbeResult>(r).point[2], 2, 1e-9);
  EXPECT_NEAR(std::get<ProbeResult>(r).mean, 0.5, 1e-6);
}

}  // namespace
}  // namespace zs
