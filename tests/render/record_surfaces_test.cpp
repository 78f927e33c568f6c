// The record surfaces of examples/ (the most nodes known for their degree: singular points
// crowd the picture, and float rounding is hardest there) traced by the Bernstein method, as
// the app traces them, against the double-precision reference of reference_comparison.hpp:
// no pixel may be drawn where F has no root within the tangent tolerance, and none left
// empty where it has one. Each in its own framing, and Labs septic also in SURFER's: the
// box of half-width 9.55 (the clipping radius of SURFER's gallery scene), whose long rays
// make the ray polynomial's coefficients largest. (The interval method, which traces these
// only when asked, still draws a few pixels where its float forms cannot decide: see
// docs/renderer.md, "The interval method".)
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "app/scene_args.hpp"
#include "reference_comparison.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

struct RecordCase {
  const char* name;
  const char* file;  // under examples/
  std::vector<std::string> sets;
  bool boxOfBall = false;
  int size = 40;
};

class RecordSurfaces : public ::testing::TestWithParam<RecordCase> {};

TEST_P(RecordSurfaces, NoPixelWithoutSurfaceAndNoneMissing) {
  const RecordCase& record = GetParam();
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  std::vector<std::string> sets = record.sets;
  sets.push_back("tracing.method=\"bernstein\"");
  std::optional<Scene> scene =
      app::loadSceneArgs({test::sourceDir() + "/examples/" + record.file, sets});
  ASSERT_TRUE(scene);
  if (record.boxOfBall) scene->domain = test::boxOfBall(scene->domain);
  scene->render.samples = 1;
  auto prepared = prepareSurface(*scene, kWithoutGlslang);
  ASSERT_TRUE(std::holds_alternative<PreparedSurface>(prepared))
      << std::get<std::string>(prepared);
  const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
  ASSERT_EQ(surface.method, TracingMethod::Bernstein) << surface.methodWarning;
  auto tracer = std::make_unique<RayTracer>();
  ASSERT_EQ(loadSurface(*tracer, surface), "");
  const int size = record.size;
  const Frame frame = tracer->render(scene->render, scene->domain, size, size);
  ASSERT_EQ(frame.error, "");

  const test::ReferenceCounts c = test::compareWithReference(*scene, surface, frame, size);
  EXPECT_GT(c.hits, size * size / 10) << "the reference sees the surface";
  EXPECT_EQ(c.ghost, 0) << c.details;
  EXPECT_EQ(c.missed, 0) << c.details;
  std::printf("  %s: %d reference hits, %d left out\n", record.name, c.hits, c.leftOut);
}

INSTANTIATE_TEST_SUITE_P(
    Examples, RecordSurfaces,
    ::testing::Values(
        RecordCase{"LabsSepticInSurfersBox", "labs-septic.surf", {"domain.radius=9.55"}, true},
        RecordCase{"LabsSeptic", "labs-septic.surf", {}},
        RecordCase{"EndrassOctic", "endrass-octic.surf", {}},
        RecordCase{"ChmutovOctic", "chmutov-octic.surf", {}},
        RecordCase{"BarthDecic", "barth-decic.surf", {}},
        RecordCase{"SartiDodecic", "sarti-dodecic.surf", {}, false, 32}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace zs
