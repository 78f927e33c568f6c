// Golden files: the generated formula block for the 7 thesis surfaces and for edge cases,
// compared byte for byte with tests/golden/<name>.glsl. Regenerate them all with
//   ZS_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden
// (or ZS_UPDATE_GOLDEN=1 zs_codegen_tests --gtest_filter='Golden*') and review the diff.
// Every golden also passes glslang, assembled into the complete fragment shader.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <string>

#include "codegen/emit_interval_glsl.hpp"
#include "codegen/glsl_validation.hpp"
#include "codegen/shader_assembly.hpp"
#include "codegen_test_util.hpp"
#include "expr/derivative.hpp"
#include "golden_cases.hpp"

namespace zs::test {
namespace {

bool updating() {
  const char* env = std::getenv("ZS_UPDATE_GOLDEN");
  return env && std::string(env) == "1";
}

std::filesystem::path goldenPath(const std::string& name) {
  return sourceDir() / "tests" / "golden" / (name + ".glsl");
}

// `actual` against the golden file at `path`; with ZS_UPDATE_GOLDEN=1 writes it instead.
void expectGolden(const std::filesystem::path& path, const std::string& actual) {
  if (updating()) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(path))
      << path << " is missing; create it with ZS_UPDATE_GOLDEN=1 (docs/codegen.md)";
  EXPECT_EQ(readFile(path), actual)
      << path << " differs; if the change is intended, regenerate with ZS_UPDATE_GOLDEN=1";
}

void checkGolden(const GoldenCase& c) {
  SCOPED_TRACE(std::string(c.name) + ": " + c.formula);
  const std::optional<GlslFormula> glsl = generate(c.formula);
  ASSERT_TRUE(glsl.has_value());
  expectGolden(goldenPath(c.name), std::string("// formula: ") + c.formula + "\n" + glsl->source);
  const ValidationResult result = validateGlsl(assembleFragmentShader(*glsl), Stage::Fragment);
  EXPECT_TRUE(result.ok) << formatInternalShaderError("fragment shader", result);
}

// The interval block (emit_interval_glsl.hpp) of a handful of edge cases, in
// tests/golden/interval_<name>.glsl, assembled into the interval method's shader.
void checkIntervalGolden(const GoldenCase& c) {
  SCOPED_TRACE(std::string(c.name) + ": " + c.formula);
  std::optional<Formula> formula = parseOrFail(c.formula);
  ASSERT_TRUE(formula.has_value());
  const std::array<NodeId, 3> grad = gradient(formula->graph, formula->root);
  const IntervalGlsl interval = emitIntervalGlsl(formula->graph, formula->root);
  expectGolden(goldenPath(std::string("interval_") + c.name),
               std::string("// formula: ") + c.formula + "\n" + interval.source);
  const GlslFormula glsl = emitFormulaGlsl(formula->graph, formula->root, grad);
  std::string source = assembleFragmentShader(glsl, interval);
  const ValidationResult result = validateGlsl(source, Stage::Fragment);
  EXPECT_TRUE(result.ok) << formatInternalShaderError("interval fragment shader", result);
  // The beam pass's program and its tile mask's are the same text with RT_BEAM and
  // RT_TILE_MASK defined (render/ray_tracer.cpp).
  for (const char* define : {"RT_BEAM", "RT_TILE_MASK"}) {
    std::string variant = source;
    variant.insert(variant.find('\n') + 1, std::string("#define ") + define + "\n#line 2 0\n");
    const ValidationResult result = validateGlsl(variant, Stage::Fragment);
    EXPECT_TRUE(result.ok) << formatInternalShaderError(
        std::string("interval ") + define + " shader", result);
  }
}

class GoldenThesis : public ::testing::TestWithParam<GoldenCase> {};
TEST_P(GoldenThesis, MatchesAndValidates) {
  checkGolden(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Golden, GoldenThesis, ::testing::ValuesIn(kThesis),
                         [](const auto& info) { return std::string(info.param.name); });

class GoldenEdge : public ::testing::TestWithParam<GoldenCase> {};
TEST_P(GoldenEdge, MatchesAndValidates) {
  checkGolden(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Golden, GoldenEdge, ::testing::ValuesIn(kEdgeCases),
                         [](const auto& info) { return std::string(info.param.name); });

class GoldenInterval : public ::testing::TestWithParam<GoldenCase> {};
TEST_P(GoldenInterval, MatchesAndValidates) {
  checkIntervalGolden(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Golden, GoldenInterval, ::testing::ValuesIn(kIntervalCases),
                         [](const auto& info) { return std::string(info.param.name); });

// A golden without a case would never be checked again: stale files fail the suite.
TEST(Golden, EveryFileHasACase) {
  std::set<std::string> names;
  for (const GoldenCase& c : kThesis) names.insert(std::string(c.name) + ".glsl");
  for (const GoldenCase& c : kEdgeCases) names.insert(std::string(c.name) + ".glsl");
  for (const GoldenCase& c : kIntervalCases)
    names.insert("interval_" + std::string(c.name) + ".glsl");
  for (const auto& entry : std::filesystem::directory_iterator(sourceDir() / "tests/golden")) {
    EXPECT_TRUE(names.count(entry.path().filename().string()))
        << entry.path() << " belongs to no golden case";
  }
}

}  // namespace
}  // namespace zs::test
