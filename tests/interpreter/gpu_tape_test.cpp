// The tape's layout (gpu_tape.hpp) and the interpreter's shaders under glslang.
#include "interpreter/gpu_tape.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "codegen/glsl_validation.hpp"
#include "expr/derivative.hpp"
#include "interpreter/interpreter_glsl.hpp"
#include "parser/parser.hpp"

namespace zs {
namespace {

GpuTape tapeOf(const std::string& text) {
  Formula f = std::get<Formula>(parseFormula(text));
  const auto grad = gradient(f.graph, f.root);
  auto tape = encodeGpuTape(f.graph, f.root, grad);
  EXPECT_TRUE(std::holds_alternative<GpuTape>(tape)) << std::get<std::string>(tape);
  return std::get<GpuTape>(tape);
}

TEST(GpuTape, HeaderPointsAtThreeProgramsInOrder) {
  const GpuTape t = tapeOf("x^2+y^2+z^2-1");
  const auto& w = t.texels;
  ASSERT_GE(w.size(), std::size_t(kTapeHeaderTexels * 4));
  EXPECT_EQ(w[0], std::uint32_t(kTapeHeaderTexels));  // F begins after the header
  EXPECT_EQ(w[1], w[2]);                              // the gradient program follows F's
  EXPECT_EQ(w[3], w[4]);                              // the affine program follows
  EXPECT_LE(w[4], w[5]);                              // dF/dt's own steps start inside it
  EXPECT_LE(w[5], w[6]);
  EXPECT_EQ(w[6], std::uint32_t(t.texels.size() / 4));
  EXPECT_EQ(w[15], 0u);  // no parameters
  EXPECT_EQ(t.instructions(), int(w[6]) - kTapeHeaderTexels);
}

TEST(GpuTape, RegistersAreReusedAlongALongSum) {
  std::string sum = "x";
  for (int i = 1; i <= 100; ++i) sum += "+" + std::to_string(i) + "*x^" + std::to_string(i % 7 + 1);
  const GpuTape t = tapeOf(sum);
  EXPECT_GT(t.instructions(), 300);
  EXPECT_LE(t.pointRegisters, 48);  // the powers of x and their derivatives stay live
  EXPECT_LE(t.affineRegisters, 48);
}

TEST(GpuTape, ParameterCountIsLimited) {
  std::string many;
  for (int i = 0; i <= kTapeMaxParams; ++i)
    many += (i ? "+" : "") + std::string("p") + std::to_string(i) + "*x";
  Formula f = std::get<Formula>(parseFormula(many));
  ASSERT_GT(f.graph.params().size(), std::size_t(kTapeMaxParams));
  auto tape = encodeGpuTape(f.graph, f.root, gradient(f.graph, f.root));
  ASSERT_TRUE(std::holds_alternative<std::string>(tape));
  EXPECT_NE(std::get<std::string>(tape).find("parameters"), std::string::npos);
}

TEST(GpuTape, UndefinedConstantIsFlaggedInBothPrograms) {
  // No formula text folds to NaN; a graph can still hold one (the code generator's goldens
  // flag it the same way).
  Graph g;
  const NodeId f = g.binary(Op::Add, g.var(0), g.constant(std::nan("")));
  const auto grad = gradient(g, f);
  auto tape = encodeGpuTape(g, f, grad);
  ASSERT_TRUE(std::holds_alternative<GpuTape>(tape));
  const GpuTape& t = std::get<GpuTape>(tape);
  int flagged = 0;
  for (std::size_t i = kTapeHeaderTexels * 4; i < t.texels.size(); i += 4)
    flagged += (t.texels[i] & kTapeUndefinedBit) != 0;
  EXPECT_EQ(flagged, 3);  // F's point program, the gradient program, the affine program
}

TEST(InterpreterShader, EveryMethodAndDialectValidates) {
  for (bool sampling : {false, true}) {
    for (bool polynomialOnly : {false, true}) {
      for (ShaderDialect dialect : {ShaderDialect::Gl330, ShaderDialect::Es300}) {
        const ValidationResult r = validateGlsl(
            interpreterFragmentShader(sampling, polynomialOnly, dialect), Stage::Fragment);
        EXPECT_TRUE(r.ok) << (sampling ? "sampling " : "interval ")
                          << (polynomialOnly ? "polynomial " : "every operation ")
                          << (dialect == ShaderDialect::Es300 ? "ES" : "GL") << "\n"
                          << r.log;
      }
    }
  }
}

TEST(GpuTape, SaysWhetherOnlyPolynomialOperationsOccur) {
  EXPECT_TRUE(tapeOf("a*x^2-y^-3+z*y").polynomialOnly);
  EXPECT_FALSE(tapeOf("x^2+y^2-sin(z)").polynomialOnly);
  EXPECT_FALSE(tapeOf("x/y+z").polynomialOnly);
}

}  // namespace
}  // namespace zs
