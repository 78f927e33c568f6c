// Random formulas (tests/support): the generator is deterministic and covers the language;
// every formula it produces parses, and every parsed formula yields a fragment shader that
// glslang accepts for every method that applies (2000 of them, fixed seed). Also measures glslang's
// time per formula and validates one very large formula; the numbers are printed and recorded in
// the test XML.
#include "support/random_formula.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <regex>
#include <vector>

#include "codegen/emit_interval_glsl.hpp"
#include "codegen/emit_ray_polynomial.hpp"
#include "codegen/glsl_validation.hpp"
#include "codegen/shader_assembly.hpp"
#include "codegen_test_util.hpp"
#include "expr/derivative.hpp"
#include "render/settings.hpp"

namespace zs::test {
namespace {

constexpr int kFormulas = 600;  // every depth and parameter count many times; fuzz/ runs many more

RandomFormulaOptions optionsFor(int i) {
  RandomFormulaOptions o;
  o.maxDepth = 1 + i % 7;
  o.paramCount = i % 11;  // 0 to 10: every parameter name
  return o;
}

TEST(RandomFormula, SameSeedSameFormulas) {
  std::mt19937_64 a(123), b(123), c(124);
  std::vector<std::string> fromA, fromC;
  for (int i = 0; i < 50; ++i) {
    fromA.push_back(randomFormula(a, optionsFor(i)));
    EXPECT_EQ(fromA.back(), randomFormula(b, optionsFor(i)));
    fromC.push_back(randomFormula(c, optionsFor(i)));
  }
  EXPECT_NE(fromA, fromC);
}

TEST(RandomFormula, CoversTheLanguage) {
  std::mt19937_64 rng(1);
  std::string all;
  for (int i = 0; i < kFormulas; ++i) all += randomFormula(rng, optionsFor(i)) + "\n";
  for (const OpInfo& info : kOpTable) {
    if (info.kind == OpKind::Call) {
      EXPECT_NE(all.find(std::string(info.spelling) + "("), std::string::npos) << info.spelling;
    }
  }
  EXPECT_TRUE(std::regex_search(all, std::regex("[0-9][xyz]"))) << "never generated: 2x";
  for (const char* piece : {"**", "^", "[", "]", "=", "pi", " e", "radius", ")(", "^-", "--", " .",
                            "e-", "E+", " x ", "+", "/", "*", ","}) {
    EXPECT_NE(all.find(piece), std::string::npos) << "never generated: '" << piece << "'";
  }
}

// Sharded so the shards run in parallel: each validates its share of the formulas with the
// shader of every method that applies (sampling; interval; Bernstein for polynomials).
class RandomFormulaShard : public ::testing::TestWithParam<int> {};
constexpr int kShards = 4;

TEST_P(RandomFormulaShard, EveryFormulaParsesAndPassesGlslangForEveryMethod) {
  std::mt19937_64 rng(20240601);
  std::vector<double> millis;
  std::size_t largestNodes = 0;
  int polynomials = 0;
  for (int i = 0; i < kFormulas; ++i) {
    const std::string text = randomFormula(rng, optionsFor(i));
    if (i % kShards != GetParam()) continue;  // every shard draws the same sequence
    SCOPED_TRACE("formula #" + std::to_string(i) + ": " + text);
    std::optional<Formula> formula = parseOrFail(text);
    ASSERT_TRUE(formula);
    const std::array<NodeId, 3> grad = gradient(formula->graph, formula->root);
    const GlslFormula glsl = emitFormulaGlsl(formula->graph, formula->root, grad);
    const std::string shader = assembleFragmentShader(glsl);
    const auto start = std::chrono::steady_clock::now();
    const ValidationResult result = validateGlsl(shader, Stage::Fragment);
    millis.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    ASSERT_TRUE(result.ok) << formatInternalShaderError("fragment shader", result);
    // The interval method's shader (the default for every formula that is not a polynomial).
    const ValidationResult interval =
        validateGlsl(assembleFragmentShader(glsl, emitIntervalGlsl(formula->graph, formula->root)),
                     Stage::Fragment);
    ASSERT_TRUE(interval.ok) << formatInternalShaderError("interval fragment shader", interval);
    // The Bernstein method's (the default for polynomials), constants included.
    if (auto poly = emitRayPolynomialGlsl(formula->graph, formula->root)) {
      ++polynomials;
      const ValidationResult bernstein =
          validateGlsl(assembleFragmentShader(glsl, *poly), Stage::Fragment);
      ASSERT_TRUE(bernstein.ok) << formatInternalShaderError("Bernstein fragment shader",
                                                             bernstein);
    }
    largestNodes = std::max(largestNodes, formula->graph.size());
  }
  std::sort(millis.begin(), millis.end());
  const double median = millis[millis.size() / 2];
  std::printf(
      "glslang: %zu formulas (%d polynomials), median %.2f ms, max %.2f ms, largest "
      "graph %zu nodes\n",
      millis.size(), polynomials, median, millis.back(), largestNodes);
  EXPECT_GT(polynomials, int(millis.size()) / 10) << "too few polynomials: Bernstein untested";
  RecordProperty("glslang_median_us", static_cast<int>(median * 1000));
  RecordProperty("largest_graph_nodes", static_cast<int>(largestNodes));
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomFormulaShard, ::testing::Range(0, kShards));

// Scenes of 2 to 4 random surfaces (constants and parameters included), traced as their
// product with the surfaces block after the formula block, as the pipeline assembles them:
// every method's shader passes glslang, in desktop GLSL and GLSL ES.
TEST(RandomFormula, SeveralSurfacesPassGlslangForEveryMethod) {
  std::mt19937_64 rng(20261127);
  int polynomials = 0, standIns = 0;
  for (int scene = 0; scene < 24; ++scene) {
    const int count = 2 + scene % 3;
    Formula product;
    std::vector<Formula> surfaces;
    std::string texts;
    for (int i = 0; i < count; ++i) {
      const std::string text = randomFormula(rng, optionsFor(scene * 4 + i));
      texts += (i ? " | " : "") + text;
      std::optional<Formula> f = parseOrFail(text);
      ASSERT_TRUE(f) << text;
      surfaces.push_back(std::move(*f));
    }
    SCOPED_TRACE("surfaces: " + texts);
    // As scene/surfaces.cpp forms it: a factor undefined in places stands in as 1 there.
    product.root =
        definedOrOne(product.graph, copyInto(product.graph, surfaces[0].graph, surfaces[0].root));
    for (int i = 1; i < count; ++i) {
      product.root = product.graph.binary(
          Op::Mul, product.root,
          definedOrOne(product.graph,
                       copyInto(product.graph, surfaces[i].graph, surfaces[i].root)));
    }
    const std::array<NodeId, 3> grad = gradient(product.graph, product.root);
    GlslFormula glsl = emitFormulaGlsl(product.graph, product.root, grad);
    standIns += glsl.source.find("#define ZS_STAND_INS") != std::string::npos;
    std::vector<NodeId> roots;
    std::vector<SurfaceLook> looks;
    for (const Formula& f : surfaces) {
      roots.push_back(copyInto(product.graph, f.graph, f.root));
      looks.push_back({{0.2, 0.4, 0.6}, {0.6, 0.4, 0.2}, {0.1, 1, 0.5, 40}, {0.1, 1, 0.5, 40}});
    }
    glsl.source += emitSurfacesGlsl(product.graph, roots, looks, {scene % 2 == 0, 0.02, {0, 0, 0}});
    const IntervalGlsl interval = emitIntervalGlsl(product.graph, product.root);
    for (const ShaderDialect dialect : {ShaderDialect::Gl330, ShaderDialect::Es300}) {
      const Stage stage = Stage::Fragment;
      const ValidationResult sampling =
          validateGlsl(assembleFragmentShader(glsl, {}, dialect), stage);
      ASSERT_TRUE(sampling.ok) << formatInternalShaderError("sampling", sampling);
      const ValidationResult intervals =
          validateGlsl(assembleFragmentShader(glsl, interval, {}, dialect), stage);
      ASSERT_TRUE(intervals.ok) << formatInternalShaderError("interval", intervals);
      // Bernstein up to the degree the pipeline uses it for in each dialect.
      const std::optional<int> degree = rayPolynomialDegree(product.graph, product.root);
      const int limit =
          dialect == ShaderDialect::Gl330 ? kMaxBernsteinDegree : kWebBernsteinMaxDegree;
      if (!degree || *degree > limit) continue;
      if (auto poly =
              emitRayPolynomialGlsl(product.graph, product.root, dialect == ShaderDialect::Gl330)) {
        polynomials += dialect == ShaderDialect::Gl330;
        const ValidationResult bernstein =
            validateGlsl(assembleFragmentShader(glsl, *poly, {}, dialect), stage);
        ASSERT_TRUE(bernstein.ok) << formatInternalShaderError("Bernstein", bernstein);
      }
    }
  }
  EXPECT_GT(polynomials, 0) << "no product was a polynomial: Bernstein untested";
  EXPECT_GT(standIns, 0) << "no factor was undefined in places: the stand-ins untested";
}

// One very large formula: the sum of many random terms (shared subexpressions are merged by
// the graph, so the node count is what is measured, not the text length).
TEST(RandomFormula, VeryLargeFormulaPassesGlslang) {
  std::mt19937_64 rng(99);
  RandomFormulaOptions o;
  o.maxDepth = 6;
  o.equalsProbability = 0;
  std::string text = "0";
  for (int i = 0; i < 1500; ++i) text += " + (" + randomFormula(rng, o) + ")";
  std::optional<Formula> formula = parseOrFail(text);
  ASSERT_TRUE(formula);
  const std::array<NodeId, 3> grad = gradient(formula->graph, formula->root);
  const std::size_t nodes = reachable(formula->graph, {formula->root}).size();
  const std::size_t withGradient =
      reachable(formula->graph, {formula->root, grad[0], grad[1], grad[2]}).size();
  const GlslFormula glsl = emitFormulaGlsl(formula->graph, formula->root, grad);
  const auto start = std::chrono::steady_clock::now();
  const ValidationResult result = validateGlsl(assembleFragmentShader(glsl), Stage::Fragment);
  const ValidationResult interval =
      validateGlsl(assembleFragmentShader(glsl, emitIntervalGlsl(formula->graph, formula->root)),
                   Stage::Fragment);
  EXPECT_TRUE(interval.ok) << formatInternalShaderError("interval fragment shader", interval);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.ok) << formatInternalShaderError("fragment shader", result);
  std::printf(
      "large formula: %zu nodes (F), %zu with gradient, %zu temporaries, %zu bytes of "
      "GLSL, glslang %.0f ms\n",
      nodes, withGradient, glsl.temporaries, glsl.source.size(), ms);
  RecordProperty("large_formula_nodes", static_cast<int>(nodes));
  EXPECT_GT(nodes, 8000u);
}

}  // namespace
}  // namespace zs::test
