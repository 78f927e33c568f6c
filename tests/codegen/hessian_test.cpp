// The second derivatives for the curvature colorings: emitted as zs_FHess only on request,
// and every coloring x lighting variant of the shading template passes glslang, with every
// tracing method.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "codegen/emit_glsl.hpp"
#include "codegen/emit_hessian.hpp"
#include "codegen/emit_ray_polynomial.hpp"
#include "codegen/glsl_validation.hpp"
#include "codegen/shader_assembly.hpp"
#include "expr/derivative.hpp"
#include "parser/parser.hpp"

namespace zs {
namespace {

struct Generated {
  GlslFormula glsl;
  std::string hessian;
  std::optional<RayPolynomialGlsl> poly;
  IntervalGlsl interval;
};

Generated generate(const std::string& text) {
  ParseResult parsed = parseFormula(text);
  Formula f = std::get<Formula>(std::move(parsed));
  const auto grad = gradient(f.graph, f.root);
  Generated g;
  g.glsl = emitFormulaGlsl(f.graph, f.root, grad);
  g.hessian = emitHessianGlsl(f.graph, grad);
  g.poly = emitRayPolynomialGlsl(f.graph, f.root);
  g.interval = emitIntervalGlsl(f.graph, f.root);
  return g;
}

// The defines render/shading_defines.cpp writes, after #version.
std::string withDefines(std::string shader, int color) {
  const std::string defines =
      "#define RT_LIGHTS RT_DIRECTIONAL(vec3(0.0, 0.6, 0.8), vec3(0.8, 0.8, 0.8)) "
      "RT_POINT(vec3(3.0, 3.0, 4.0), vec3(0.6, 0.5, 0.4))\n"
      "#define RT_KEY_LIGHT vec3(0.0, 0.6, 0.8)\n#define RT_COLOR " +
      std::to_string(color) + "\n#line 2 0\n";
  shader.insert(shader.find('\n') + 1, defines);
  return shader;
}

TEST(Hessian, IsAMat3FunctionOfP) {
  const Generated g = generate("x^3*y + sin(z)");
  EXPECT_NE(g.hessian.find("mat3 zs_FHess(vec3 p) {"), std::string::npos) << g.hessian;
  EXPECT_NE(g.hessian.find("return mat3("), std::string::npos);
  EXPECT_EQ(g.glsl.source.find("zs_FHess"), std::string::npos) << "only on request";
}

TEST(Hessian, EveryColoringVariantPassesGlslang) {
  for (const char* formula : {"x^2 + y^2 + z^2 - 1", "a*x^4 - y^2*z + exp(x*y) - 1"}) {
    const Generated g = generate(formula);
    for (int color = 0; color <= 3; ++color) {
      SCOPED_TRACE(std::string(formula) + ", RT_COLOR " + std::to_string(color));
      GlslFormula block = g.glsl;
      if (color == 1 || color == 2) block.source += g.hessian;
      const ValidationResult sampling =
          validateGlsl(withDefines(assembleFragmentShader(block), color), Stage::Fragment);
      EXPECT_TRUE(sampling.ok) << formatInternalShaderError("sampling", sampling);
      const ValidationResult interval = validateGlsl(
          withDefines(assembleFragmentShader(block, g.interval), color), Stage::Fragment);
      EXPECT_TRUE(interval.ok) << formatInternalShaderError("interval", interval);
      if (!g.poly) continue;
      const ValidationResult bernstein =
          validateGlsl(withDefines(assembleFragmentShader(block, *g.poly), color), Stage::Fragment);
      EXPECT_TRUE(bernstein.ok) << formatInternalShaderError("bernstein", bernstein);
    }
  }
}

TEST(Hessian, NoLightsAtAllIsAValidVariant) {
  const Generated g = generate("x^2 + y^2 - 1");
  std::string shader = assembleFragmentShader(g.glsl);
  shader.insert(shader.find('\n') + 1, "#define RT_LIGHTS\n#line 2 0\n");
  const ValidationResult result = validateGlsl(shader, Stage::Fragment);
  EXPECT_TRUE(result.ok) << formatInternalShaderError("no lights", result);
}

}  // namespace
}  // namespace zs
