#pragma once
// Shader assembly: takes a generated formula block (codegen/emit_glsl.hpp) and the templates
// embedded at build time, puts out the complete text the renderer hands to GL. The fragment
// shader is three pieces joined by prototypes, no markers:
//
//   raytrace_prelude.frag.glsl  (#version, zs_F / zs_FGrad prototypes, helpers)   string 0
//   generated formula block     (zs_params, zs_F, zs_FGrad)                       string 1
//   raytrace_main.frag.glsl     (uniforms, traversal, tracing, shading, main)     string 2
//
// A comment naming its origin and `#line 1 <string>` precede pieces 2 and 3, so compiler
// logs ("0:12", "1:7", "2:40") point into the right piece at the right line.
#include <string>
#include <string_view>

#include "codegen/emit_glsl.hpp"

namespace zs {

inline constexpr std::string_view kPreludeTemplate = "raytrace_prelude.frag.glsl";
inline constexpr std::string_view kRaytraceTemplate = "raytrace_main.frag.glsl";
inline constexpr std::string_view kVertexTemplate = "fullscreen.vert.glsl";

// The embedded text of shaders/templates/<fileName>. An unknown name is a bug in zeroset:
// throws std::logic_error naming the templates that exist.
std::string_view shaderTemplate(std::string_view fileName);

// Prelude + formula block + ray tracer. Throws std::logic_error if the ray tracer never
// calls zs_F or zs_FGrad (the formula block would be an unused piece).
std::string assembleFragmentShader(const GlslFormula& formula);

std::string_view vertexShaderSource();

}  // namespace zs
