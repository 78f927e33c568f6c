// Every formula the parser accepts renders with every tracing method: random formulas of
// the language (tests/support, fixed seed) and the constants a user passes through while
// typing, each prepared by the app's pipeline, loaded into a tracer and drawn at 8 x 8. An
// error the user can act on (an octree budget, say) is allowed; an internal error, a shader
// the driver rejects or a failed frame is not.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render_support.hpp"
#include "support/random_formula.hpp"

namespace zs {
namespace {

std::vector<std::string> formulas() {
  // Constants, with and without parameters (a and b default to 0: 3(a-b) is 0 everywhere).
  std::vector<std::string> all{"0.5", "a", "cosh(a)", "3(a-b)", "1e-30", "0", "-x", "x - 0.3"};
  std::mt19937_64 rng(2711);
  for (int i = 0; i < 16; ++i) {
    test::RandomFormulaOptions o;
    o.maxDepth = 1 + i % 4;
    o.paramCount = i % 3;
    all.push_back(test::randomFormula(rng, o));
  }
  return all;
}

class EveryMethod : public ::testing::TestWithParam<TracingMethod> {};

TEST_P(EveryMethod, EveryFormulaRendersWithoutAnInternalError) {
  // Two dozen programs, each drawn once at 8 x 8: llvmpipe's optimization passes would cost
  // more than everything else (Mesa reads this when the driver starts, in this process).
  setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0);
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  int rendered = 0;
  for (const std::string& text : formulas()) {
    SCOPED_TRACE(text);
    Scene scene;
    scene.formula = text;
    scene.render.tracing.method = GetParam();
    scene.octree.level = 2;
    auto prepared = prepareSurface(scene);
    if (auto* message = std::get_if<std::string>(&prepared)) {
      EXPECT_EQ(message->find("internal error"), std::string::npos) << *message;
      continue;
    }
    const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
    RayTracer tracer;
    const std::string loaded = loadSurface(tracer, surface, scene.render);
    ASSERT_EQ(loaded, "");
    const Frame frame = tracer.render(scene.render, scene.domain, 8, 8);
    EXPECT_EQ(frame.error, "");
    ++rendered;
  }
  EXPECT_GE(rendered, int(formulas().size()) * 3 / 4);
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethod,
                         ::testing::Values(TracingMethod::Auto, TracingMethod::Bernstein,
                                           TracingMethod::Interval, TracingMethod::Sampling),
                         [](const auto& info) {
                           return std::string(info.param == TracingMethod::Auto        ? "Auto"
                                              : info.param == TracingMethod::Bernstein ? "Bernstein"
                                              : info.param == TracingMethod::Interval  ? "Interval"
                                                                                      : "Sampling");
                         });

}  // namespace
}  // namespace zs
