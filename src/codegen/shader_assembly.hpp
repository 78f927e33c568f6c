#pragma once
// Shader assembly: takes a generated formula block (codegen/emit_glsl.hpp) and the templates
// embedded at build time, puts out the complete text the renderer hands to GL. The fragment
// shader is three pieces joined by prototypes, no markers:
//
//   raytrace_prelude.frag.glsl  (#version, zs_F / zs_FGrad prototypes, helpers)   string 0
//   generated formula block     (zs_params, zs_F, zs_FGrad)                       string 1
//   [ray polynomial block       (zs_FPoly, Bernstein kernels; Bernstein only)]    string 2
//   frame_params.glsl           (the frame's parameters, flat inputs `rt`)
//   raytrace_main.frag.glsl     (rays, passes, main; rtMarch and shade prototypes)
//   raytrace_shading.frag.glsl  (shade: lights, materials, curvature colors, highlights)
//   raytrace_sampling.frag.glsl (rtMarch), or raytrace_bernstein.frag.glsl or
//   raytrace_interval.frag.glsl (rtFirstRoot) and raytrace_first_roots.frag.glsl (rtMarch)
//
// The interval method has three more pieces after the formula block: interval_prelude.frag.glsl
// (the zsi_* rules), affine_prelude.frag.glsl (the zsa_* rules) and the generated interval
// block (zs_FAffine, emit_interval_glsl.hpp).
//
// A comment naming its origin and `#line 1 <string>` precede pieces 2 and 3, so compiler
// logs ("0:12", "1:7", "2:40") point into the right piece at the right line.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "codegen/emit_glsl.hpp"
#include "codegen/emit_interval_glsl.hpp"
#include "codegen/emit_ray_polynomial.hpp"

namespace zs {

inline constexpr std::string_view kPreludeTemplate = "raytrace_prelude.frag.glsl";
inline constexpr std::string_view kRaytraceTemplate = "raytrace_main.frag.glsl";
inline constexpr std::string_view kShadingTemplate = "raytrace_shading.frag.glsl";
inline constexpr std::string_view kVolumeTemplate = "raytrace_volume.frag.glsl";
inline constexpr std::string_view kSamplingTemplate = "raytrace_sampling.frag.glsl";
inline constexpr std::string_view kBernsteinTemplate = "raytrace_bernstein.frag.glsl";
inline constexpr std::string_view kIntervalTemplate = "raytrace_interval.frag.glsl";
inline constexpr std::string_view kFirstRootsTemplate = "raytrace_first_roots.frag.glsl";
// The interval method's beam pass: its main() with RT_BEAM defined (render/ray_tracer.cpp).
inline constexpr std::string_view kBeamTemplate = "raytrace_beam.frag.glsl";
// Where a fragment shader has a beam pass (the interval method's), it says so with this line.
inline constexpr std::string_view kHasBeamDefine = "#define RT_HAS_BEAM\n";
inline constexpr std::string_view kIntervalPreludeTemplate = "interval_prelude.frag.glsl";
inline constexpr std::string_view kAffinePreludeTemplate = "affine_prelude.frag.glsl";
inline constexpr std::string_view kVertexTemplate = "fullscreen.vert.glsl";
inline constexpr std::string_view kFrameTemplate = "frame_params.glsl";  // both stages

// Which GLSL the pieces are assembled for: the templates' own desktop GLSL 3.30, or GLSL ES
// 3.00 for WebGL2. For ES the assembly replaces #version with ES's and the precisions it
// requires, and carries the frame's parameters as uniforms the fragment stage copies into a
// struct (ES has no interface blocks between stages); the templates are the same files.
// Gl330 text carries both ways of passing the frame's parameters: flat varyings from the
// vertex stage (the default) or, where RT_FRAME_UNIFORMS is defined, uniforms read as ES
// reads them (render/program_variant.hpp, FrameStorage, chooses per GL driver).
enum class ShaderDialect { Gl330, Es300 };

// The embedded text of shaders/templates/<fileName>. An unknown name is a bug in zeroset:
// throws std::logic_error naming the templates that exist.
std::string_view shaderTemplate(std::string_view fileName);

// Constants for highlights.singular: the marked points, their radius and color, as a block
// that defines RT_MARKERS (raytrace_main.frag.glsl draws them); empty for no points.
std::string markerBlock(const std::vector<std::array<double, 3>>& points, double radius,
                        const std::array<double, 3>& color);

// Prelude + formula block + ray tracer with the thesis' sampling march. Throws
// std::logic_error if the ray tracer never calls zs_F or zs_FGrad (the formula block would
// be an unused piece).
std::string assembleFragmentShader(const GlslFormula& formula, std::string_view markers = {},
                                   ShaderDialect dialect = ShaderDialect::Gl330);

// The same with the exact Bernstein march: the ray polynomial block (emit_ray_polynomial.hpp)
// follows the formula block.
// Throws std::logic_error for a double-precision block (poly.fp64) and GLSL ES.
std::string assembleFragmentShader(const GlslFormula& formula, const RayPolynomialGlsl& poly,
                                   std::string_view markers = {},
                                   ShaderDialect dialect = ShaderDialect::Gl330);

// The same with the interval march: the interval prelude and block follow the formula block.
std::string assembleFragmentShader(const GlslFormula& formula, const IntervalGlsl& interval,
                                   std::string_view markers = {},
                                   ShaderDialect dialect = ShaderDialect::Gl330);

// fullscreen.vert.glsl with frame_params.glsl (as outputs) after its #version line.
std::string vertexShaderSource(ShaderDialect dialect = ShaderDialect::Gl330);

}  // namespace zs
