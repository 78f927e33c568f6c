// Structure of the formula block: only generated identifiers, integer powers as
// multiplication chains, shared subexpressions computed once, uniforms only when needed.
#include "codegen/emit_glsl.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <regex>
#include <set>
#include <string>

#include "codegen_test_util.hpp"
#include "glsl_interpreter.hpp"

namespace zs::test {
namespace {

std::string withoutComments(const std::string& s) {
  return std::regex_replace(s, std::regex("//[^\n]*"), "");
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = s.find(what); pos != std::string::npos; pos = s.find(what, pos + 1)) ++n;
  return n;
}

// The text of one function ("float zs_F(vec3 p) {" up to its closing brace).
std::string functionText(const std::string& block, const std::string& signature) {
  const auto begin = block.find(signature);
  return block.substr(begin, block.find("\n}\n", begin) - begin);
}

// Every identifier must be ours: a temporary t<N>[_<power>|_m], a zs_ name, a swizzle of
// p, or a GLSL keyword/built-in. A formula's parameter names never appear.
TEST(EmitGlsl, OnlyGeneratedIdentifiers) {
  const std::set<std::string> glsl = {"float", "vec3", "vec4", "bool", "uniform", "return", "true",
                                      "false", "p",    "x",    "y",    "z",       "sin",    "cos",
                                      "tan",   "atan", "sinh", "cosh", "exp",     "abs",    "sign",
                                      "floor", "ceil", "min",  "max"};
  const std::regex temporary("t[0-9]+(_[0-9]+|_m)?");
  const char* formulas[] = {
      "main + gl_FragColor*x - float^2 + zs_F + discard y + t0 z + sin(uniform)",
      "atan2(y, x) + sinh(x) + cosh(y) + tanh(z) + exp(x) + log(y^2+1) + asin(x) + acos(y)",
      "sqrt(x) + cbrt(y) + abs(z) + sign(x) + floor(y) + ceil(z) + min(x,y) + max(y,z)",
      "pow(x, y) + x^-3 + y^1000 + 1/z + tan(x)"};
  for (const char* text : formulas) {
    SCOPED_TRACE(text);
    const std::optional<GlslFormula> out = generate(text);
    ASSERT_TRUE(out);
    const std::string code = withoutComments(out->source);
    const std::regex identifier("[A-Za-z_][A-Za-z0-9_]*");
    for (auto it = std::sregex_iterator(code.begin(), code.end(), identifier);
         it != std::sregex_iterator(); ++it) {
      const std::string id = it->str();
      const auto pos = static_cast<std::size_t>(it->position());
      if (pos > 0 &&
          (std::isdigit(static_cast<unsigned char>(code[pos - 1])) || code[pos - 1] == '.')) {
        // The exponent of a literal such as 1e-05, or a swizzle (checked by the set).
        if (code[pos - 1] != '.' || pos < 2 || code[pos - 2] != 'p') continue;
      }
      const bool ok = glsl.count(id) || id.rfind("zs_", 0) == 0 || std::regex_match(id, temporary);
      EXPECT_TRUE(ok) << "identifier '" << id << "' in\n" << out->source;
    }
    for (const char* param : {"main", "gl_FragColor", "discard"}) {
      EXPECT_EQ(code.find(param), std::string::npos) << param;  // became zs_params[i]
    }
  }
}

TEST(EmitGlsl, IntegerPowersAreMultiplicationChains) {
  const std::optional<GlslFormula> out = generate("x^13 + y^-6 + z^1024 + (x+y)^3");
  ASSERT_TRUE(out);
  const std::string code = withoutComments(out->source);
  EXPECT_EQ(code.find("pow("), std::string::npos) << code;
  const std::string f = functionText(code, "float zs_F");
  // z^1024: 9 named squares + the last squaring; x^13 = x^4 * x^4 * x^4 * x.
  EXPECT_EQ(count(f, "p.z * p.z"), 1u) << f;
  EXPECT_NE(f.find("p.x * p.x"), std::string::npos) << f;
  EXPECT_NE(f.find("zs_div(1.0, "), std::string::npos) << "y^-6 divides 1 by y^6\n" << f;
}

TEST(EmitGlsl, SquaresAreSharedBetweenPowersOfOneBase) {
  const std::optional<GlslFormula> out = generate("x^2 + x^4 + x^8 + x^3");
  ASSERT_TRUE(out);
  const std::string f = functionText(out->source, "float zs_F");
  EXPECT_EQ(count(f, "p.x * p.x"), 1u) << f;  // x^2 once, reused by x^4, x^8 and x^3
  EXPECT_EQ(count(f, " * "), 4u) << f;        // x^2, x^4 = x^2 x^2, x^8 = x^4 x^4, x^3 = x^2 x
}

TEST(EmitGlsl, SharedSubexpressionsAreComputedOnce) {
  const std::optional<GlslFormula> out = generate("sin(x*y+z) + cos(x*y+z) + (x*y+z)^2");
  ASSERT_TRUE(out);
  const std::string f = functionText(out->source, "float zs_F");
  EXPECT_EQ(count(f, "p.x * p.y"), 1u) << f;
  const std::string g = functionText(out->source, "vec4 zs_FGrad");
  EXPECT_EQ(count(g, "p.x * p.y"), 1u) << "F and gradient share temporaries\n" << g;
}

TEST(EmitGlsl, FunctionOfFAloneOmitsGradientNodes) {
  const std::optional<GlslFormula> out = generate("sin(x) + y");
  ASSERT_TRUE(out);
  EXPECT_EQ(functionText(out->source, "float zs_F").find("cos("), std::string::npos);
  EXPECT_NE(functionText(out->source, "vec4 zs_FGrad").find("cos("), std::string::npos);
}

TEST(EmitGlsl, ParametersBecomeOneUniformArray) {
  const std::optional<GlslFormula> with = generate("a x + b y + a z");
  ASSERT_TRUE(with);
  EXPECT_EQ(with->paramCount, 2u);
  EXPECT_NE(with->source.find("uniform float zs_params[2];  // [0] a [1] b\n"), std::string::npos)
      << with->source;
  const std::optional<GlslFormula> without = generate("x + y");
  ASSERT_TRUE(without);
  EXPECT_EQ(without->paramCount, 0u);
  EXPECT_EQ(without->source.find("uniform"), std::string::npos);
}

TEST(EmitGlsl, DomainHelpersReportToTheRightFlag) {
  const std::optional<GlslFormula> out = generate("sqrt(x) + y");
  ASSERT_TRUE(out);
  EXPECT_NE(out->source.find("zs_sqrt(p.x, zs_u)"), std::string::npos) << out->source;
  // d/dx of sqrt(x) divides by sqrt(x): a node only the gradient needs reports to zs_ug.
  EXPECT_NE(functionText(out->source, "vec4 zs_FGrad").find("zs_ug)"), std::string::npos)
      << out->source;
}

// The parser keeps sqrt(-1) as a node, but a graph built elsewhere may hold a NaN constant:
// it must make F undefined, never print "nan".
TEST(EmitGlsl, NanConstantMakesFUndefined) {
  Formula f;
  f.root = f.graph.binary(Op::Add, f.graph.constant(std::nan("")), f.graph.var(0));
  const GlslFormula out = emitFormulaGlsl(f);
  EXPECT_EQ(out.source.find("nan"), std::string::npos) << out.source;
  const FormulaBlockInterpreter interpreter(out.source);
  EXPECT_EQ(interpreter.evalF({0.5f, 0.0f, 0.0f}, {}), kGlslUndefined) << out.source;
  EXPECT_EQ(interpreter.evalFGrad({0.5f, 0.0f, 0.0f}, {})[3], kGlslUndefined);
}

TEST(EmitGlsl, TemporariesCountsTheDeclarationsOfFGrad) {
  const std::optional<GlslFormula> out = generate("x^4 + y^3 + sin(z) - 1");
  ASSERT_TRUE(out);
  EXPECT_EQ(out->temporaries, count(functionText(out->source, "vec4 zs_FGrad"), "  float "));
}

TEST(EmitGlsl, DeepFormulasEmitWithoutRecursion) {
  // 200000 nested additions: the emitter walks ids upward, never recursively.
  Formula f;
  NodeId acc = f.graph.var(0);
  for (int i = 0; i < 200000; ++i) {
    acc = f.graph.binary(Op::Add, f.graph.binary(Op::Mul, acc, f.graph.var(i % 3)),
                         f.graph.constant(i));
  }
  f.root = acc;
  const GlslFormula out = emitFormulaGlsl(f);
  EXPECT_GT(out.temporaries, 400000u);
}

}  // namespace
}  // namespace zs::test
