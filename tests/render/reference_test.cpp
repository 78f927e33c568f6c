// Small renders through the real pipeline (parser -> GLSL -> octree -> GPU) compared with
// committed PNGs under tests/render/reference by the tolerance metric of image.hpp.
// ZS_UPDATE_REFERENCE=1 rewrites the references; look at them before committing.
#include <gtest/gtest.h>

#include <functional>
#include <map>

#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 128;

struct Case {
  const char* name;
  const char* formula;
  std::function<void(RenderSettings&)> tweak;
};

// Thesis Table 5.1, surfaces 1-7, seen obliquely so domain borders and silhouettes show.
const Case kCases[] = {
    {"thesis1_paraboloid", "x^2+z^2-y", nullptr},
    {"thesis2_cubic", "x^2*y+x^2*z+y^2*x+y^2*z+z^2*y+z^2*x-(2/5)*(x*y+x*z+y*z)", nullptr},
    {"thesis3_cuboid", "x^4+y^4+z^4-1", nullptr},
    {"thesis4_mixed", "x^2+y^3+z^5-1", nullptr},
    {"thesis5_klein_quartic", "x^3*y+y^3*z+z^3*x", nullptr},
    {"thesis6_quartic", "x^4-z^4-y", nullptr},
    {"thesis7_cross", "x^2*y^2+y^2*z^2+z^2*x^2-1", nullptr},
    {"feature_no_highlights", "x^4+y^4+z^4-1",
     [](RenderSettings& s) { s.silhouette.enabled = s.border.enabled = false; }},
    {"feature_silhouette_wide", "x^4+y^4+z^4-1",
     [](RenderSettings& s) { s.silhouette.threshold = 0.4; }},
    {"feature_border_wide", "x^2+z^2-y", [](RenderSettings& s) { s.border.threshold = 0.06; }},
    {"feature_no_reflection", "x^2*y^2+y^2*z^2+z^2*x^2-1",
     [](RenderSettings& s) { s.reflection.enabled = false; }},
    {"feature_opacity", "x^2*y^2+y^2*z^2+z^2*x^2-1", [](RenderSettings& s) { s.opacity = 0.45; }},
    {"feature_point_light_only", "x^4+y^4+z^4-1",
     [](RenderSettings& s) { s.lights.sources[0].intensity = 0; }},
    {"feature_directional_only", "x^4+y^4+z^4-1",
     [](RenderSettings& s) { s.lights.sources[1].intensity = 0; }},
    {"feature_supersampling", "x^3*y+y^3*z+z^3*x", [](RenderSettings& s) { s.samples = 2; }},
    {"feature_orthographic", "x^4-z^4-y",
     [](RenderSettings& s) {
       s.camera.projection = Projection::Orthographic;
       s.camera.height = 5;
     }},
};

class Reference : public ::testing::TestWithParam<std::tuple<Backend, int>> {};

TEST_P(Reference, MatchesCommittedImage) {
  const auto [backend, index] = GetParam();
  const Case& c = kCases[index];
  std::string error;
  ASSERT_NE(test::context(backend, error), nullptr) << error;
  // One tracer per (backend, formula): shader JIT dominates the cost of these tests.
  static std::map<std::pair<Backend, std::string>, std::unique_ptr<RayTracer>> tracers;
  auto& tracer = tracers[{backend, c.formula}];
  if (!tracer) tracer = test::makeTracer({c.formula, {}, 3}, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings s = test::testSettings({3.9, 3.0, 5.1});  // the whole domain in view
  if (c.tweak) c.tweak(s);
  const Frame frame = tracer->render(s, Domain{}, kSize, kSize);
  ASSERT_EQ(frame.error, "");
  // Both backends are llvmpipe: they share one set of references.
  EXPECT_EQ(test::matchReference(c.name, frame.color), "");
}

std::string caseName(const ::testing::TestParamInfo<std::tuple<Backend, int>>& info) {
  return std::string(std::get<0>(info.param) == Backend::Egl ? "Egl_" : "OsMesa_") +
         kCases[std::get<1>(info.param)].name;
}

INSTANTIATE_TEST_SUITE_P(Egl, Reference,
                         ::testing::Combine(::testing::Values(Backend::Egl),
                                            ::testing::Range(0, int(std::size(kCases)))),
                         caseName);
// OSMesa: the thesis surfaces only (the features exercise shared shader code).
INSTANTIATE_TEST_SUITE_P(OsMesa, Reference,
                         ::testing::Combine(::testing::Values(Backend::OsMesa),
                                            ::testing::Range(0, 7)),
                         caseName);

}  // namespace
}  // namespace zs
