// Templates are embedded faithfully, assembled in order with #line markers, and the whole
// fragment shader and the vertex shader pass glslang.
#include "codegen/shader_assembly.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "codegen/emit_interval_glsl.hpp"
#include "codegen/emit_ray_polynomial.hpp"
#include "codegen/glsl_validation.hpp"
#include "codegen_test_util.hpp"
#include "parser/parser.hpp"
#include "render/program_variant.hpp"
#include "scene/scene_io.hpp"

namespace zs::test {
namespace {

TEST(ShaderAssembly, EmbeddedTemplatesEqualTheFilesOnDisk) {
  for (std::string_view name :
       {kPreludeTemplate, kRaytraceTemplate, kShadingTemplate, kVertexTemplate, kFrameTemplate,
        kSamplingTemplate, kBernsteinTemplate}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(shaderTemplate(name), readFile(sourceDir() / "shaders/templates" / name));
  }
}

TEST(ShaderAssembly, UnknownTemplateIsALoudInternalError) {
  try {
    (void)shaderTemplate("no_such_template.glsl");
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_template.glsl"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find(std::string(kPreludeTemplate)), std::string::npos);
  }
}

TEST(ShaderAssembly, PiecesInOrderWithLineDirectives) {
  const std::optional<GlslFormula> glsl = generate("x^2 + y^2 + z^2 - 1");
  ASSERT_TRUE(glsl);
  const std::string shader = assembleFragmentShader(*glsl);
  EXPECT_EQ(shader.rfind("#version 330 core\n", 0), 0u);
  const auto prelude = shader.find("float zs_F(vec3 p);");
  const auto block = shader.find("#line 1 1\n" + glsl->source);
  // The frame's parameters: uniforms where RT_FRAME_UNIFORMS is defined, else flat varyings.
  const auto frame = shader.find("#line 1 2\n#ifdef RT_FRAME_UNIFORMS\n");
  EXPECT_NE(shader.find("#else\n#define RT_FRAME_STORAGE in\n" +
                            std::string(shaderTemplate(kFrameTemplate)),
                        frame),
            std::string::npos);
  const auto main = shader.find("#line 1 3\n" + std::string(shaderTemplate(kRaytraceTemplate)));
  ASSERT_NE(frame, std::string::npos);
  EXPECT_LT(block, frame);
  EXPECT_LT(frame, main);
  ASSERT_NE(prelude, std::string::npos);
  ASSERT_NE(block, std::string::npos);
  ASSERT_NE(main, std::string::npos);
  EXPECT_LT(prelude, block);
  EXPECT_LT(block, main);
}

TEST(ShaderAssembly, FragmentAndVertexShadersPassGlslang) {
  const std::optional<GlslFormula> glsl = generate("a x^2 + y^2 + z^2 - 1");
  ASSERT_TRUE(glsl);
  const ValidationResult fragment = validateGlsl(assembleFragmentShader(*glsl), Stage::Fragment);
  EXPECT_TRUE(fragment.ok) << formatInternalShaderError("fragment shader", fragment);
  const ValidationResult vertex = validateGlsl(vertexShaderSource(), Stage::Vertex);
  EXPECT_TRUE(vertex.ok) << formatInternalShaderError("vertex shader", vertex);
}

// WebGL2's GLSL ES 3.00 from the same templates: every method, the vertex stage too.
TEST(ShaderAssembly, GlslEsShadersPassGlslangForEveryMethod) {
  for (const char* text : {"a x^2 + y^2 + z^2 - 1", "x^4 + y^4 + z^4 - 1", "sin(x y) + z",
                           "x^2 y + y^2 z + z^2 x - 0.4 (x y + y z + z x)", "0.5"}) {
    SCOPED_TRACE(text);
    ParseResult parsed = parseFormula(text);
    ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
    const Formula& f = std::get<Formula>(parsed);
    const std::optional<GlslFormula> glsl = generate(text);
    ASSERT_TRUE(glsl);
    std::vector<std::string> shaders{
        assembleFragmentShader(*glsl, {}, ShaderDialect::Es300),
        assembleFragmentShader(*glsl, emitIntervalGlsl(f.graph, f.root), {}, ShaderDialect::Es300)};
    if (auto poly = emitRayPolynomialGlsl(f.graph, f.root, false)) {
      EXPECT_FALSE(poly->fp64);
      EXPECT_EQ(poly->source.find("double"), std::string::npos);
      shaders.push_back(assembleFragmentShader(*glsl, *poly, {}, ShaderDialect::Es300));
    }
    for (const std::string& shader : shaders) {
      EXPECT_EQ(shader.rfind("#version 300 es\n", 0), 0u);
      const ValidationResult result = validateGlsl(shader, Stage::Fragment);
      EXPECT_TRUE(result.ok) << formatInternalShaderError("GLSL ES fragment shader", result);
    }
  }
  const ValidationResult vertex =
      validateGlsl(vertexShaderSource(ShaderDialect::Es300), Stage::Vertex);
  EXPECT_TRUE(vertex.ok) << formatInternalShaderError("GLSL ES vertex shader", vertex);
}

// A double-float expansion too long to write out term by term (a software WebGL's JIT took
// minutes over the Sarti dodecic's) writes its large convolutions as calls of one loop; a
// shorter one, and every desktop expansion, stays written out. Both pass glslang.
TEST(ShaderAssembly, LongDoubleFloatExpansionsConvolveInALoop) {
  for (const auto& [example, loops] :
       {std::pair{"sarti-dodecic", true}, {"endrass-octic", false}}) {
    SCOPED_TRACE(example);
    SceneResult loaded = loadScene(sourceDir() / "examples" / (std::string(example) + ".surf"));
    ASSERT_TRUE(std::holds_alternative<Scene>(loaded));
    const std::string text = std::get<Scene>(loaded).formula;
    ParseResult parsed = parseFormula(text);
    ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
    const Formula& f = std::get<Formula>(parsed);
    const auto web = emitRayPolynomialGlsl(f.graph, f.root, false);
    const auto desktop = emitRayPolynomialGlsl(f.graph, f.root, true);
    ASSERT_TRUE(web && desktop);
    EXPECT_EQ(web->source.find("zs_dfConvolve(") != std::string::npos, loops);
    EXPECT_EQ(desktop->source.find("zs_dfConvolve("), std::string::npos);
    const std::optional<GlslFormula> glsl = generate(text);
    ASSERT_TRUE(glsl);
    const ValidationResult result = validateGlsl(
        assembleFragmentShader(*glsl, *web, {}, ShaderDialect::Es300), Stage::Fragment);
    EXPECT_TRUE(result.ok) << formatInternalShaderError("GLSL ES fragment shader", result);
  }
}

// The program variants the renderer and the page put in front of a shader
// (render/program_variant.hpp): shadows with their two lights, kept hits for opacity, an
// even sample grid, no reflection, the volume; every method, both dialects.
TEST(ShaderAssembly, ProgramVariantsPassGlslangForEveryMethodAndDialect) {
  const char* text = "x^4 + y^4 + z^4 - 1";
  ParseResult parsed = parseFormula(text);
  const Formula& f = std::get<Formula>(parsed);
  const std::optional<GlslFormula> glsl = generate(text);
  ASSERT_TRUE(glsl);
  RenderSettings shadows;
  shadows.shading.shadows = true;
  RenderSettings layered = shadows;
  layered.opacity = 0.5;
  layered.tracing.hits = 3;
  layered.samples = 2;
  layered.reflection.enabled = false;
  RenderSettings volume;
  volume.mode = RenderMode::Volume;
  for (ShaderDialect dialect : {ShaderDialect::Gl330, ShaderDialect::Es300}) {
    const auto poly = emitRayPolynomialGlsl(f.graph, f.root, dialect == ShaderDialect::Gl330);
    ASSERT_TRUE(poly);
    const std::string sources[] = {
        assembleFragmentShader(*glsl, {}, dialect),
        assembleFragmentShader(*glsl, emitIntervalGlsl(f.graph, f.root), {}, dialect),
        assembleFragmentShader(*glsl, *poly, {}, dialect)};
    // Desktop text passes the frame's parameters as flat varyings or as uniforms.
    std::vector<FrameStorage> storages = {FrameStorage::FlatVaryings};
    if (dialect == ShaderDialect::Gl330) storages.push_back(FrameStorage::Uniforms);
    for (FrameStorage storage : storages) {
      for (const RenderSettings& settings : {shadows, layered, volume}) {
        for (const std::string& source : sources) {
          const ValidationResult result = validateGlsl(
              withFrameStorage(withVariantDefines(source, ProgramVariant::of(settings)), storage),
              Stage::Fragment);
          EXPECT_TRUE(result.ok) << formatInternalShaderError("fragment shader variant", result);
        }
      }
      const ValidationResult vertex =
          validateGlsl(withFrameStorage(vertexShaderSource(dialect), storage), Stage::Vertex);
      EXPECT_TRUE(vertex.ok) << formatInternalShaderError("vertex shader", vertex);
    }
  }
}

// shading.contours: the contour function's block joins the formula block and passes glslang
// in both dialects, also for a function with domain restrictions; one with a parameter is
// refused (the scene refuses it first).
TEST(ShaderAssembly, ContourBlockPassesGlslangInBothDialects) {
  std::optional<GlslFormula> glsl = generate("x^4 + y^4 + z^4 - 1");
  ASSERT_TRUE(glsl);
  ParseResult function = parseFormula("sqrt(z + 1) + log(x^2 + 0.1) / y");
  const std::string block = emitContourGlsl(std::get<Formula>(function));
  ASSERT_NE(block.find("#define RT_CONTOURS"), std::string::npos);
  glsl->source += block;
  for (ShaderDialect dialect : {ShaderDialect::Gl330, ShaderDialect::Es300}) {
    const ValidationResult result =
        validateGlsl(assembleFragmentShader(*glsl, {}, dialect), Stage::Fragment);
    EXPECT_TRUE(result.ok) << formatInternalShaderError("fragment shader with contours", result);
  }
  ParseResult withParameter = parseFormula("z - a");
  EXPECT_EQ(emitContourGlsl(std::get<Formula>(withParameter)), "");
}

TEST(ShaderAssembly, DoublePrecisionRayPolynomialIsNotAssembledForGlslEs) {
  ParseResult parsed = parseFormula("x^2 + y^2 + z^2 - 1");
  const Formula& f = std::get<Formula>(parsed);
  const std::optional<GlslFormula> glsl = generate("x^2 + y^2 + z^2 - 1");
  ASSERT_TRUE(glsl);
  const auto poly = emitRayPolynomialGlsl(f.graph, f.root);  // double: desktop only
  ASSERT_TRUE(poly);
  EXPECT_THROW((void)assembleFragmentShader(*glsl, *poly, {}, ShaderDialect::Es300),
               std::logic_error);
}

TEST(ShaderAssembly, ErrorsInTheFormulaBlockPointIntoIt) {
  // A deliberately broken block: glslang's log must name string 1 at the broken line.
  GlslFormula broken;
  broken.source =
      "float zs_F(vec3 p) { return 1.0; }\nvec4 zs_FGrad(vec3 p) {\n  return oops;\n}\n";
  const ValidationResult result = validateGlsl(assembleFragmentShader(broken), Stage::Fragment);
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.log.find("1:3:"), std::string::npos) << result.log;
  EXPECT_NE(result.numberedSource.find("1:3 |   return oops;"), std::string::npos)
      << result.numberedSource;
}

}  // namespace
}  // namespace zs::test
