#pragma once
// Validation of shader text with glslang's C++ API, before any GL call: takes GLSL source
// and its stage, puts out whether glslang (compile + single-stage link) accepts it, its log,
// and the source with line numbers that follow the #line directives, so "ERROR: 1:7" in the
// log is found as "1:7" in the listing. Also formats the messages shown when a generated
// shader is rejected: that is always a bug in zeroset, never a problem with the formula.
#include <string>
#include <string_view>

namespace zs {

enum class Stage { Vertex, Fragment };

struct ValidationResult {
  bool ok = false;
  std::string log;             // glslang's compile and link logs (warnings too when ok)
  std::string numberedSource;  // "S:L | text" per line, S:L as #line directives set them
};

// Thread-safe; glslang's process state is initialized once, on first use.
ValidationResult validateGlsl(std::string_view source, Stage stage);

// "S:L | text" for every line. Lines start at 0:1; a "#line L S" (or "#line L") directive
// makes the next line L of string S, as in GLSL 3.30.
std::string numberSourceLines(std::string_view source);

// The message for a generated shader that glslang rejected: says it is an internal error
// of zeroset, then the glslang log, then the numbered source. `what` names the shader
// ("fragment shader for x^2+y^2-1").
std::string formatInternalShaderError(std::string_view what, const ValidationResult& result);

// The message for a shader that glslang accepted but the GL driver rejected: the driver's
// log first, then glslang's (empty when clean), then the numbered source.
std::string formatDriverShaderError(std::string_view what, Stage stage, std::string_view driverLog,
                                    std::string_view source);

}  // namespace zs
