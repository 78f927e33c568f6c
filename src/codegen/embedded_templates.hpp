#pragma once
// The shader templates compiled into the binary: takes nothing, puts out (file name, text)
// pairs. The definition is generated at build time by cmake/EmbedShaders.cmake from
// shaders/templates/*.glsl; use shaderTemplate() from codegen/shader_assembly.hpp instead.
#include <span>
#include <string_view>

namespace zs {

struct EmbeddedTemplate {
  std::string_view fileName;  // e.g. "raytrace_main.frag.glsl"
  std::string_view text;
};

std::span<const EmbeddedTemplate> embeddedTemplates();

}  // namespace zs
