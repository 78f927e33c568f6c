// The tape interpreter draws what the formula's own shader draws: the same scene through
// both programs, compared pixel by pixel. The two run the same rules in the same order, so
// the pictures agree but for the rare pixel where the driver contracts a product and a sum
// differently in the two programs.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/load_surface.hpp"
#include "pipeline/quick_surface.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

struct Case {
  const char* name;
  const char* formula;
  TracingMethod method = TracingMethod::Interval;
};

// Every rule kind of the affine program: products with constants and parameters (scale,
// mulk), sin/cos pairs, settled chains, interval-only rules, domain errors, negative powers.
const Case kCases[] = {
    {"sphere", "x^2+y^2+z^2-1"},
    {"gyroid", "sin(3x)cos(3y)+sin(3y)cos(3z)+sin(3z)cos(3x)"},
    {"domains", "sqrt(x^2+y^2)-0.5+0.2*z^3+log(z+1.4)/5"},
    {"parameter", "a*x^2+y^2+z^2-1"},
    {"negative_power", "x^-2/8+y^2+z^2-1"},
    {"steps_and_jumps", "max(abs(x),abs(y))+z^2-0.8+0.1*floor(2y)"},
    {"interval_only", "atan(2x)+tanh(y)+cbrt(z)-0.2+0.1*pow(z+2,0.5)"},
    {"sampling_torus", "(x^2+y^2+z^2+0.36-0.25)^2-1.44*(x^2+y^2)", TracingMethod::Sampling},
    {"sampling_domains", "sqrt(x^2+y^2)-0.5+0.2*z^3+exp(-x)/9", TracingMethod::Sampling},
};

class InterpreterPicture : public ::testing::TestWithParam<Case> {};

TEST_P(InterpreterPicture, MatchesTheFormulasOwnShader) {
  std::string error;
  if (!test::context(Backend::Egl, error)) GTEST_SKIP() << error;
  const Case& c = GetParam();
  Scene scene;
  scene.formula = c.formula;
  scene.params = {{"a", 0.7}};
  scene.render.tracing.method = c.method;
  auto prepared = prepareSurface(scene, kWithoutGlslang);
  ASSERT_TRUE(std::holds_alternative<PreparedSurface>(prepared)) << std::get<std::string>(prepared);
  auto quick = prepareQuickSurface(scene);
  ASSERT_TRUE(std::holds_alternative<QuickSurface>(quick)) << std::get<std::string>(quick);

  const RenderSettings settings = test::testSettings({1.2, 1.6, 2.4});
  const int size = 96;
  RayTracer own;
  ASSERT_EQ(loadSurface(own, std::get<PreparedSurface>(prepared), settings), "");
  const Frame expected = own.render(settings, scene.domain, size, size);
  ASSERT_EQ(expected.error, "");

  // One interpreter per kind for the whole process, as the front ends keep them.
  static RayTracer interpreters[2][2];
  const bool sampling = std::get<QuickSurface>(quick).sampling;
  const bool polynomial = std::get<QuickSurface>(quick).tape.polynomialOnly;
  RayTracer& interpreter = interpreters[sampling][polynomial];
  ASSERT_EQ(buildInterpreter(interpreter, sampling, polynomial), "");
  ASSERT_EQ(loadQuickSurface(interpreter, std::get<QuickSurface>(quick)), "");
  const Frame actual = interpreter.render(settings, scene.domain, size, size);
  ASSERT_EQ(actual.error, "");

  const ImageDiff diff = compareImages(expected.color, actual.color);
  EXPECT_LE(diff.fractionOver, 0.003) << c.name << ": rmse " << diff.rmse;
  int hitsExpected = 0, hitsActual = 0;
  for (float d : expected.depth.values) hitsExpected += std::isfinite(d);
  for (float d : actual.depth.values) hitsActual += std::isfinite(d);
  EXPECT_GT(hitsExpected, size * size / 20) << c.name << ": the scene shows too little to compare";
  EXPECT_NEAR(hitsActual, hitsExpected, size * size / 500 + 2) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Cases, InterpreterPicture, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace zs
