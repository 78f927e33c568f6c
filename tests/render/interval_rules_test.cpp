// The interval rules of the GPU (shaders/templates/interval_prelude.frag.glsl, called as the
// code generator calls them: codegen/op_interval_glsl.hpp) run on the GPU that runs the
// tests, against double precision on the CPU: for random operand intervals of every opcode,
// every value the operation takes at points of its operands (the ends and random points
// between) must lie in the rule's result. This is the rounding contract of docs/codegen.md
// ("Interval GLSL") checked on real hardware (llvmpipe here), which no CPU test can do.
// The affine rules (affine_prelude.frag.glsl, codegen/op_interval_glsl.hpp) likewise: for
// random forms c + s tau +- r of the operands sharing one tau, the value of the operation at
// every sampled tau and remainder must lie within the rule's form at that tau.
#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <random>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "codegen/emit_interval_glsl.hpp"
#include "codegen/op_interval_glsl.hpp"
#include "codegen/shader_assembly.hpp"
#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "parser/parser.hpp"
#include "render/shader_program.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kLanes = 256;  // operand pairs per draw: one pixel each

struct Rule {
  Op op;
  int ival = 0;     // PowI's exponent
  double lo, hi;    // where operands are drawn from
  double maxWidth;  // largest operand width
};

// Operand ranges reach past each function's domain, so restriction and the undefined flag
// are exercised too.
const Rule kRules[] = {
    {Op::Neg, 0, -1e3, 1e3, 50}, {Op::Add, 0, -1e3, 1e3, 50}, {Op::Sub, 0, -1e3, 1e3, 50},
    {Op::Mul, 0, -30, 30, 10},   {Op::Div, 0, -30, 30, 10},   {Op::PowI, 2, -5, 5, 3},
    {Op::PowI, 3, -5, 5, 3},     {Op::PowI, 6, -3, 3, 2},     {Op::PowI, -3, -5, 5, 3},
    {Op::Pow, 0, -3, 3, 2},      {Op::Sin, 0, -100, 100, 4},  {Op::Cos, 0, -100, 100, 4},
    {Op::Sin, 0, -2, 2, 0.01},   {Op::Cos, 0, -2, 2, 0.01},   {Op::Tan, 0, -5, 5, 1},
    {Op::Asin, 0, -1.5, 1.5, 1}, {Op::Acos, 0, -1.5, 1.5, 1}, {Op::Atan, 0, -50, 50, 20},
    {Op::Atan2, 0, -3, 3, 2},    {Op::Sinh, 0, -10, 10, 3},   {Op::Cosh, 0, -10, 10, 3},
    {Op::Tanh, 0, -5, 5, 2},     {Op::Exp, 0, -20, 20, 3},    {Op::Log, 0, -1, 50, 10},
    {Op::Sqrt, 0, -1, 100, 10},  {Op::Cbrt, 0, -50, 50, 10},  {Op::Abs, 0, -10, 10, 5},
    {Op::Sign, 0, -2, 2, 1},     {Op::Floor, 0, -10, 10, 3},  {Op::Ceil, 0, -10, 10, 3},
    {Op::Min, 0, -10, 10, 5},    {Op::Max, 0, -10, 10, 5},
};

// The preludes, `declarations` (generated code the body calls) and a main() around `body`,
// which reads its pixel's operands from zsTestInput (`inputs` vec4s) and sets zsTestOut.
std::string testShader(std::initializer_list<std::string_view> templates, int inputs,
                       const std::string& body, const std::string& declarations = {}) {
  std::string s(shaderTemplate(kPreludeTemplate));
  for (std::string_view t : templates) s += shaderTemplate(t);
  return s + declarations + "uniform vec4 zsTestInput[" + std::to_string(inputs) +
         "];\n"
         "out vec4 zsTestOut;\n"
         "void main() {\n"
         "  bool u = false;\n"
         "  zsi_partial = false;\n" +
         body + "}\n";
}

// Applies rule `rule` (as the emitter writes it) to the operand intervals of its pixel: out
// (lo, hi, undefined everywhere, restricted).
std::string fragmentSource(const Rule& rule) {
  return testShader({kIntervalPreludeTemplate}, kLanes,
                    "  vec4 in4 = zsTestInput[int(gl_FragCoord.x)];\n"
                    "  vec2 a = in4.xy, b = in4.zw;\n"
                    "  vec2 r = " +
                        glslIntervalOpExpression(rule.op, "a", "b", rule.ival, "u") +
                        ";\n"
                        "  zsTestOut = vec4(r, u ? 1.0 : 0.0, zsi_partial ? 1.0 : 0.0);\n");
}

// Applies the affine rule of `rule` to the forms of its pixel (a in zsTestInput[2 i].xyz, b in
// zsTestInput[2 i + 1].xyz): out (c, s, r, undefined everywhere).
// The operands are settled forms (their m the magnitude of their (c, s, r)); a polynomial
// rule's result is settled as the emitter settles it, as a chain of one operation.
std::string affineFragmentSource(const Rule& rule) {
  const std::string result = glslAffineOpExpression(rule.op, "a", "b", rule.ival, "u");
  return testShader(
      {kIntervalPreludeTemplate, kAffinePreludeTemplate}, 2 * kLanes,
      "  int i = int(gl_FragCoord.x);\n"
      "  vec3 a3 = zsTestInput[2 * i].xyz, b3 = zsTestInput[2 * i + 1].xyz;\n"
      "  vec4 a = vec4(a3, abs(a3.x) + abs(a3.y) + a3.z + ZSI_ETA);\n"
      "  vec4 b = vec4(b3, abs(b3.x) + abs(b3.y) + b3.z + ZSI_ETA);\n"
      "  vec4 r = " +
          (affineOpIsPolynomial(rule.op, rule.ival) ? "zsa_settle(" + result + ", 1.0)" : result) +
          ";\n"
          "  zsTestOut = vec4(r.xyz, u ? 1.0 : 0.0);\n");
}

const char* kVertex =
    "#version 330 core\n"
    "void main() {\n"
    "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";

// Runs a test shader on the GPU, one lane per pixel, with `operands` as zsTestInput.
std::vector<float> runOnGpu(const std::string& fragment, const std::vector<float>& operands,
                            std::string& error) {
  const unsigned program = compileProgram(kVertex, fragment, error);
  if (program == 0) return {};
  GLuint fbo = 0, texture = 0, vao = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kLanes, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glUseProgram(program);
  glUniform4fv(glGetUniformLocation(program, "zsTestInput"), GLsizei(operands.size() / 4),
               operands.data());
  glViewport(0, 0, kLanes, 1);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);  // a ray tracer drawn before in this process culls front faces
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> out(4 * kLanes);
  glReadPixels(0, 0, kLanes, 1, GL_RGBA, GL_FLOAT, out.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &texture);
  glDeleteVertexArrays(1, &vao);
  glDeleteProgram(program);
  if (glGetError() != GL_NO_ERROR) error = "a GL error while running the rule";
  return out;
}

TEST(IntervalRules, EveryRuleEnclosesTheOperationOnThisGpu) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  std::mt19937_64 rng(1123);
  for (const Rule& rule : kRules) {
    const std::string name = std::string(opInfo(rule.op).enumName) +
                             (rule.op == Op::PowI ? std::to_string(rule.ival) : "") + " on [" +
                             std::to_string(rule.lo) + ", " + std::to_string(rule.hi) + "]";
    SCOPED_TRACE(name);
    std::uniform_real_distribution<double> at(rule.lo, rule.hi), width(0.0, rule.maxWidth);
    std::vector<float> operands(4 * kLanes);
    for (int i = 0; i < kLanes; ++i) {
      for (int k = 0; k < 2; ++k) {
        // Every 8th operand is a point; the rest random intervals.
        const float lo = float(at(rng));
        const float hi = i % 8 == 0 ? lo : float(lo + width(rng));
        operands[4 * i + 2 * k] = lo;
        operands[4 * i + 2 * k + 1] = hi;
      }
    }
    const std::vector<float> out = runOnGpu(fragmentSource(rule), operands, error);
    ASSERT_EQ(error, "");
    int checked = 0, escaped = 0;
    for (int i = 0; i < kLanes; ++i) {
      const double alo = operands[4 * i], ahi = operands[4 * i + 1];
      const double blo = operands[4 * i + 2], bhi = operands[4 * i + 3];
      const double rlo = out[4 * i], rhi = out[4 * i + 1];
      const bool undefinedEverywhere = out[4 * i + 2] != 0.0f;
      std::uniform_real_distribution<double> pa(0, 1);
      for (int s = 0; s < 40; ++s) {
        const double x = s == 0 ? alo : s == 1 ? ahi : alo + (ahi - alo) * pa(rng);
        const double y = s == 0 ? blo : s == 1 ? bhi : blo + (bhi - blo) * pa(rng);
        const double v = applyScalar(rule.op, x, y, rule.ival, 0.0);
        if (std::isnan(v)) continue;  // outside the operation's domain
        ++checked;
        const bool inside = !undefinedEverywhere && rlo <= v && v <= rhi;
        if (!inside && escaped++ < 5) {
          ADD_FAILURE() << name << ": op(" << x << ", " << y << ") = " << v
                        << " escapes the GPU's [" << rlo << ", " << rhi << "] for operands [" << alo
                        << ", " << ahi << "], [" << blo << ", " << bhi << "]"
                        << (undefinedEverywhere ? " (flagged undefined everywhere)" : "");
        }
      }
    }
    EXPECT_GT(checked, kLanes * 4) << "too few defined points: the comparison means little";
  }
}

TEST(AffineRules, EveryRuleEnclosesTheOperationAlongTheSegmentOnThisGpu) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  std::mt19937_64 rng(1124);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  for (const Rule& rule : kRules) {
    const std::string name = std::string(opInfo(rule.op).enumName) +
                             (rule.op == Op::PowI ? std::to_string(rule.ival) : "") + " on [" +
                             std::to_string(rule.lo) + ", " + std::to_string(rule.hi) + "]";
    SCOPED_TRACE(name);
    std::uniform_real_distribution<double> at(rule.lo, rule.hi);
    // Forms (c, s, r): half-widths from rule.maxWidth / 2 down to a thousandth of it (short
    // segments are where the first-order rules act); every 8th operand a point.
    std::vector<float> operands(8 * kLanes, 0.0f);
    for (int i = 0; i < kLanes; ++i) {
      for (int k = 0; k < 2; ++k) {
        const double half = 0.5 * rule.maxWidth * std::pow(10.0, -3.0 * unit(rng));
        float* f = &operands[8 * i + 4 * k];
        f[0] = float(at(rng));
        f[1] = i % 8 == 0 ? 0.0f : float(half * sym(rng));
        f[2] = i % 8 == 0 ? 0.0f : float(0.2 * half * unit(rng));
      }
    }
    const std::vector<float> out = runOnGpu(affineFragmentSource(rule), operands, error);
    ASSERT_EQ(error, "");
    int checked = 0, escaped = 0;
    for (int i = 0; i < kLanes; ++i) {
      const float* a = &operands[8 * i];
      const float* b = &operands[8 * i + 4];
      const double c = out[4 * i], slope = out[4 * i + 1], r = out[4 * i + 2];
      const bool undefinedEverywhere = out[4 * i + 3] != 0.0f;
      for (int n = 0; n < 40; ++n) {
        // The ends of tau and of both remainders first, then random points.
        const double tau = n < 8 ? ((n & 1) ? 1.0 : -1.0) : sym(rng);
        const double ea = n < 8 ? ((n & 2) ? 1.0 : -1.0) : sym(rng);
        const double eb = n < 8 ? ((n & 4) ? 1.0 : -1.0) : sym(rng);
        const double x = double(a[0]) + double(a[1]) * tau + double(a[2]) * ea;
        const double y = double(b[0]) + double(b[1]) * tau + double(b[2]) * eb;
        const double v = applyScalar(rule.op, x, y, rule.ival, 0.0);
        if (std::isnan(v)) continue;  // outside the operation's domain
        ++checked;
        const double mid = c + slope * tau;
        const bool inside = !undefinedEverywhere && mid - r <= v && v <= mid + r;
        if (!inside && escaped++ < 5) {
          ADD_FAILURE() << name << ": op(" << x << ", " << y << ") = " << v << " at tau " << tau
                        << " escapes the GPU's " << c << " + " << slope << " tau +- " << r
                        << " for operands (" << a[0] << ", " << a[1] << ", " << a[2] << "), ("
                        << b[0] << ", " << b[1] << ", " << b[2] << ")"
                        << (undefinedEverywhere ? " (flagged undefined everywhere)" : "");
        }
      }
    }
    EXPECT_GT(checked, kLanes * 4) << "too few defined points: the comparison means little";
  }
}

// The whole generated block (emit_interval_glsl.cpp), which settles the rounding of chains of
// polynomial operations once instead of widening each (affine_prelude.frag.glsl): along
// random segments t = tm + h tau of random rays, F at every sampled tau must lie in the GPU's
// c + s tau +- r and dF/dt in its D, against double precision. The formulas include long
// chains with heavy cancellation, where the settled rounding is all that keeps F's value
// inside: (x + 1000)^2 - 2000 x - 10^6 is x^2 computed through terms of size 10^6.
TEST(AffineBlock, EnclosesFAndItsDerivativeAlongSegmentsOnThisGpu) {
  // Fourteen large programs, each drawn once: llvmpipe's LLVM optimization passes would cost
  // minutes on a machine whose shader cache is empty and buy nothing for one 256 x 1 draw.
  // Mesa reads this when the driver starts: in this test's own process (ctest runs each test
  // alone), before the first context.
  setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0);
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  const char* kFormulas[] = {
      "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)",
      "sqrt(x^2+y^2+z^2)-1-0.08*sin(10*x)*sin(10*y)*sin(10*z)",
      "exp(-4*((x-0.5)^2+y^2+z^2))+exp(-4*((x+0.5)^2+y^2+z^2))-0.6",
      "(x+1000)^2-2000*x-1000000+(y-3000)*(y+3000)-y^2+9000000-z",
      "((((x*y+z)*x-y)*z+x)*y-z)*x+(x+y+z)^2*(x-y)*3.7-0.1",
      "x^4+y^4+z^4-(x^2+y^2+z^2)*1.5+0.5+1/(1+x^2)",
      // Factors constant along the ray that are not floats (zsa_mulk): 0.1, pi, exp(0.7),
      // and the direction times them in dF/dt.
      "0.1*(x+y)^2*sin(0.3*z)-exp(0.7)*x*y*0.3+pi*z*cos(x)",
  };
  std::mt19937_64 rng(2611);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  for (const char* text : kFormulas) {
    SCOPED_TRACE(text);
    ParseResult parsed = parseFormula(text);
    ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
    Formula formula = std::get<Formula>(std::move(parsed));
    Graph& g = formula.graph;
    const NodeId f = formula.root;
    const std::string block = emitIntervalGlsl(g, f).source;
    const std::array<NodeId, 3> grad = gradient(g, f);
    PointEvaluator reference(compileTape(g, {f, grad[0], grad[1], grad[2]}));
    // Lanes: (o, tm) and (d, h); out (c, s, r, 0) from the first program, (D, 0, 0) from
    // the second.
    std::vector<float> operands(8 * kLanes, 0.0f);
    for (int i = 0; i < kLanes; ++i) {
      const double scale = std::pow(10.0, -4.0 * unit(rng));  // segments from 2 down to 2e-4
      double d[3] = {sym(rng), sym(rng), sym(rng)};
      const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      float* a = &operands[8 * i];
      for (int k = 0; k < 3; ++k) {
        a[k] = float(2.0 * sym(rng));
        a[4 + k] = float(d[k] / n);
      }
      a[3] = float(2.0 * sym(rng));
      a[7] = float(scale);
    }
    auto source = [&](const char* out) {
      return testShader({kIntervalPreludeTemplate, kAffinePreludeTemplate}, 2 * kLanes,
                        "  int i = int(gl_FragCoord.x);\n"
                        "  vec4 a = zsTestInput[2 * i], b = zsTestInput[2 * i + 1];\n"
                        "  vec3 F;\n  vec2 D;\n  bool partial;\n"
                        "  zs_FAffine(a.xyz, b.xyz, a.w, b.w, F, D, partial);\n"
                        "  zsTestOut = " +
                            std::string(out) + ";\n",
                        block);
    };
    const std::vector<float> forms = runOnGpu(source("vec4(F, 0.0)"), operands, error);
    ASSERT_EQ(error, "");
    const std::vector<float> slopes = runOnGpu(source("vec4(D, 0.0, 0.0)"), operands, error);
    ASSERT_EQ(error, "");
    int checked = 0, escaped = 0;
    for (int i = 0; i < kLanes; ++i) {
      const float* a = &operands[8 * i];
      const double c = forms[4 * i], s = forms[4 * i + 1], r = forms[4 * i + 2];
      const double dLo = slopes[4 * i], dHi = slopes[4 * i + 1];
      if (r < 0.0) continue;  // F defined nowhere on the segment
      for (int k = 0; k < 40; ++k) {
        const double tau = k < 2 ? (k == 0 ? -1.0 : 1.0) : sym(rng);
        const double t = double(a[3]) + double(a[7]) * tau;
        double out[4];
        reference.eval(a[0] + t * a[4], a[1] + t * a[5], a[2] + t * a[6], {}, out);
        if (!std::isfinite(out[0])) continue;
        ++checked;
        const double mid = c + s * tau;
        const double dt = out[1] * a[4] + out[2] * a[5] + out[3] * a[6];
        const bool inside = mid - r <= out[0] && out[0] <= mid + r;
        const bool slopeInside = !std::isfinite(dt) || (dLo <= dt && dt <= dHi);
        if ((!inside || !slopeInside) && escaped++ < 5) {
          ADD_FAILURE() << "F = " << out[0] << ", dF/dt = " << dt << " at tau " << tau
                        << " escape the GPU's " << c << " + " << s << " tau +- " << r << " and ["
                        << dLo << ", " << dHi << "] on the segment tm " << a[3] << ", h " << a[7]
                        << " of the ray (" << a[0] << ", " << a[1] << ", " << a[2] << ") + t ("
                        << a[4] << ", " << a[5] << ", " << a[6] << ")";
        }
      }
    }
    EXPECT_GT(checked, kLanes * 20) << "too few defined points: the comparison means little";
  }
}

}  // namespace
}  // namespace zs
