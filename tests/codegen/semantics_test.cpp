// The generated GLSL computes what the double-precision tape computes, up to float rounding:
// runs the formula blocks of all golden formulas (and a few more) in the float interpreter
// of glsl_interpreter.hpp and compares F, the gradient and the undefined sentinel with
// PointEvaluator at random points of the default domain.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "codegen_test_util.hpp"
#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "glsl_interpreter.hpp"
#include "golden_cases.hpp"
#include "parser/parser.hpp"

namespace zs::test {
namespace {

// Float vs double: relative 1e-3 (deep formulas round at every step). Beyond 1e30 only
// the sign is compared: float overflows (or the literal was clamped) where double does not.
::testing::AssertionResult close(const char* what, double expected, float actual) {
  if (std::fabs(expected) > 1e30) {
    if ((expected > 0) == (actual > 0)) return ::testing::AssertionSuccess();
  } else if (std::fabs(actual - expected) <= 1e-3 * (1.0 + std::fabs(expected))) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << what << ": GLSL " << actual << ", double " << expected;
}

void compareAtRandomPoints(const char* text, int points) {
  SCOPED_TRACE(text);
  std::optional<Formula> formula = parseOrFail(text);
  ASSERT_TRUE(formula);
  const std::array<NodeId, 3> grad = gradient(formula->graph, formula->root);
  const GlslFormula glsl = emitFormulaGlsl(formula->graph, formula->root, grad);
  const FormulaBlockInterpreter interpreter(glsl.source);
  const Tape tape = compileTape(formula->graph, {formula->root, grad[0], grad[1], grad[2]});
  PointEvaluator evaluator(tape);
  const std::vector<double> params(glsl.paramCount, kDefaultParamValue);
  const std::vector<float> paramsF(glsl.paramCount, float(kDefaultParamValue));

  std::mt19937_64 rng(42);
  auto coordinate = [&] { return float(double(rng() >> 11) * 0x1.0p-53 * 3.0 - 1.5); };
  int undefined = 0;
  for (int i = 0; i < points; ++i) {
    const float x = coordinate(), y = coordinate(), z = coordinate();
    double ref[4];
    evaluator.eval(x, y, z, params, ref);  // F, dF/dx, dF/dy, dF/dz
    const float f = interpreter.evalF({x, y, z}, paramsF);
    const std::array<float, 4> fg = interpreter.evalFGrad({x, y, z}, paramsF);
    SCOPED_TRACE("at (" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
                 ")");
    EXPECT_EQ(f, fg[3]) << "zs_F and zs_FGrad disagree on F";
    if (std::isnan(ref[0])) {
      ++undefined;
      EXPECT_EQ(f, kGlslUndefined);
      EXPECT_EQ(fg[3], kGlslUndefined);
      continue;
    }
    ASSERT_TRUE(close("F", ref[0], f));
    const bool gradDefined = !std::isnan(ref[1]) && !std::isnan(ref[2]) && !std::isnan(ref[3]);
    for (int k = 0; k < 3; ++k) {
      if (gradDefined) {
        EXPECT_TRUE(close("dF", ref[k + 1], fg[k]));
      } else {
        EXPECT_EQ(fg[k], 0.0f) << "an undefined gradient is reported as 0";
      }
    }
  }
  ::testing::Test::RecordProperty("undefined_points", undefined);
}

// All edge cases but the clamped constants: 1e300 becoming FLT_MAX changes the function on
// purpose (ClampedConstantsKeepTheirSign checks what it promises).
std::vector<GoldenCase> edgeCasesWithinFloatRange() {
  std::vector<GoldenCase> out;
  for (const GoldenCase& c : kEdgeCases) {
    if (std::string(c.name) != "edge_tiny_huge_constants") out.push_back(c);
  }
  return out;
}

class SemanticsGolden : public ::testing::TestWithParam<GoldenCase> {};
TEST_P(SemanticsGolden, MatchesTapeEvaluator) {
  compareAtRandomPoints(GetParam().formula, 300);
}
INSTANTIATE_TEST_SUITE_P(Thesis, SemanticsGolden, ::testing::ValuesIn(kThesis),
                         [](const auto& info) { return std::string(info.param.name); });
INSTANTIATE_TEST_SUITE_P(Edge, SemanticsGolden, ::testing::ValuesIn(edgeCasesWithinFloatRange()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Semantics, ClampedConstantsKeepTheirSign) {
  auto f = [](const char* text, std::array<float, 3> p) {
    const std::optional<GlslFormula> glsl = generate(text);
    EXPECT_TRUE(glsl);
    return glsl ? FormulaBlockInterpreter(glsl->source).evalF(p, {}) : 0.0f;
  };
  // 1e-50 becomes FLT_MIN, not 0: x^2 + 1e-50 has no root at x = 0.
  EXPECT_GT(f("x^2 + 1e-50", {0, 0, 0}), 0.0f);
  EXPECT_LT(f("x^2 - 1e-50", {0, 0, 0}), 0.0f);
  // 1e300 becomes FLT_MAX: huge, with the sign of the double.
  EXPECT_GE(f("1e300 x + 1", {1, 0, 0}), kGlslHuge);
  EXPECT_LE(f("1e300 x + 1", {-1, 0, 0}), -kGlslHuge);
  EXPECT_LT(f("-1e300 + x", {1, 0, 0}), -1e37f);
}

TEST(Semantics, DomainViolationsAreUndefinedNotSignChanges) {
  for (const char* text : {"sqrt(x) - 1", "log(x) + 5", "asin(2x) + y", "acos(x-1) - z",
                           "x^0.5 - 0.5", "pow(x, 1.5) + y", "0/(x-x) + y"}) {
    SCOPED_TRACE(text);
    const std::optional<GlslFormula> glsl = generate(text);
    ASSERT_TRUE(glsl);
    const FormulaBlockInterpreter interpreter(glsl->source);
    // x = -1 lies outside every domain above (0/0 everywhere for the last one).
    EXPECT_EQ(interpreter.evalF({-1.0f, 0.25f, 0.25f}, {}), kGlslUndefined);
  }
}

TEST(Semantics, IntegerPowersOfNegativeBasesAreDefined) {
  for (const char* text : {"x^3 + 1", "x^-3 + 0.1", "pow(x, 3) + 1", "x^1023 + 1"}) {
    SCOPED_TRACE(text);
    const std::optional<GlslFormula> glsl = generate(text);
    ASSERT_TRUE(glsl);
    const FormulaBlockInterpreter interpreter(glsl->source);
    EXPECT_LT(interpreter.evalF({-2.0f, 0.0f, 0.0f}, {}), 0.0f);
  }
}

TEST(Semantics, MoreFormulasMatchTapeEvaluator) {
  for (const char* text : {"x^13*y^-5 + z^1024", "(x^2+y^2+z^2+0.5^2-0.2^2)^2-4*0.5^2*(x^2+y^2)",
                           "max(min(x, y), -z) + sign(x)*abs(y)^2.5", "a x^2 + b y^2 - c z + d",
                           "atan2(0, x) + atan2(y, z)"}) {
    compareAtRandomPoints(text, 300);
  }
}

}  // namespace
}  // namespace zs::test
