#include "codegen/shader_assembly.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include "codegen/embedded_templates.hpp"

namespace zs {
namespace {

// Appends one piece, preceded by a comment naming where it comes from and a #line that
// restarts the numbering at line 1 of source string `string`. GLSL 3.30 reads
// "#line L S" as "the next line is line L of string S" (older versions used L + 1).
void appendPiece(std::string& out, std::string_view origin, int string, std::string_view text) {
  if (!out.empty() && out.back() != '\n') out += '\n';
  out += "// ---- zeroset: ";
  out.append(origin);
  out += " ----\n#line 1 " + std::to_string(string) + "\n";
  out.append(text);
  if (out.back() != '\n') out += '\n';
}

// True when `name` occurs in `text` as a whole identifier (zs_F must not match zs_FGrad).
bool mentionsIdentifier(std::string_view text, std::string_view name) {
  auto isIdent = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  for (std::size_t pos = text.find(name); pos != std::string_view::npos;
       pos = text.find(name, pos + 1)) {
    const bool startOk = pos == 0 || !isIdent(text[pos - 1]);
    const std::size_t end = pos + name.size();
    const bool endOk = end == text.size() || !isIdent(text[end]);
    if (startOk && endOk) return true;
  }
  return false;
}

// The members of frame_params.glsl, (type, name) per line that starts with "flat ".
std::vector<std::pair<std::string, std::string>> frameMembers(std::string_view block) {
  std::vector<std::pair<std::string, std::string>> members;
  std::size_t pos = 0;
  while (pos < block.size()) {
    const std::size_t end = std::min(block.find('\n', pos), block.size());
    std::string_view line = block.substr(pos, end - pos);
    pos = end + 1;
    const std::size_t first = line.find_first_not_of(' ');
    if (first == std::string_view::npos || line.substr(first, 5) != "flat ") continue;
    line = line.substr(first + 5);
    const std::size_t space = line.find(' '), semicolon = line.find(';');
    members.emplace_back(std::string(line.substr(0, space)),
                         std::string(line.substr(space + 1, semicolon - space - 1)));
  }
  return members;
}

// The uniform that carries member `name` of the frame block: rtName.
std::string frameUniformName(const std::string& member) {
  std::string uniform = "rt" + member;
  uniform[2] = char(std::toupper(static_cast<unsigned char>(uniform[2])));
  return uniform;
}

// The uniforms rtName of the frame block's members, and rtCopyFrame(), which copies each into
// the block `rt`: the one list of the frame's parameters, generated from the block.
std::string frameUniformsAndCopy(std::string_view block) {
  std::string uniforms, copies;
  for (const auto& [type, member] : frameMembers(block)) {
    uniforms += "uniform " + type + " " + frameUniformName(member) + ";\n";
    copies += "  rt." + member + " = " + frameUniformName(member) + ";\n";
  }
  return uniforms + "\nvoid rtCopyFrame() {\n" + copies + "}\n";
}

// The frame's parameters read as uniforms by the fragment shader itself, into a global struct
// of the block's members at the start of main() (RT_FRAME_BEGIN); the vertex stage copies
// nothing. GLSL ES 3.00 has no interface blocks between stages, so WebGL2 always reads them
// so; desktop GL does where RT_FRAME_UNIFORMS is defined (FrameStorage, render stage).
std::string frameStruct(std::string_view block) {
  std::string s = "struct RtFrame {\n";
  for (const auto& [type, member] : frameMembers(block)) s += "  " + type + " " + member + ";\n";
  s += "};\nRtFrame rt;\n";
  return s + frameUniformsAndCopy(block) + "#define RT_FRAME_BEGIN rtCopyFrame();\n";
}

// The first line of a template (its #version) for `dialect`, with the precision GLSL ES
// requires; the template's own numbering resumes after it.
std::string versionHeader(std::string_view source, ShaderDialect dialect) {
  const std::size_t firstLine = source.find('\n') + 1;
  if (dialect == ShaderDialect::Gl330) return std::string(source.substr(0, firstLine));
  return "#version 300 es\nprecision highp float;\nprecision highp int;\n"
         "precision highp sampler2D;\nprecision highp usampler2D;\n#line 2 0\n";
}

}  // namespace

std::string_view shaderTemplate(std::string_view fileName) {
  std::string known;
  for (const EmbeddedTemplate& t : embeddedTemplates()) {
    if (t.fileName == fileName) return t.text;
    known += known.empty() ? "" : ", ";
    known.append(t.fileName);
  }
  throw std::logic_error("internal error in zeroset: no shader template named '" +
                         std::string(fileName) + "' was embedded (embedded: " + known + ")");
}

namespace {

std::string assemble(const GlslFormula& formula, const RayPolynomialGlsl* poly,
                     const IntervalGlsl* interval, std::string_view markers,
                     ShaderDialect dialect) {
  const std::string_view prelude = shaderTemplate(kPreludeTemplate);
  const std::string_view raytrace = shaderTemplate(kRaytraceTemplate);
  const std::string_view marchName =
      poly ? kBernsteinTemplate : (interval ? kIntervalTemplate : kSamplingTemplate);
  const std::string_view march = shaderTemplate(marchName);
  // The first-root methods share their rtMarch (raytrace_first_roots.frag.glsl).
  const std::string_view firstRoots = (poly || interval) ? shaderTemplate(kFirstRootsTemplate) : "";
  if (!mentionsIdentifier(march, "zs_F") && !mentionsIdentifier(march, "zs_FGrad") &&
      !mentionsIdentifier(firstRoots, "zs_FGrad")) {
    throw std::logic_error(
        "internal error in zeroset: shaders/templates/" + std::string(marchName) +
        " calls neither zs_F nor zs_FGrad, so the generated formula would be unused");
  }
  if (poly && poly->fp64 && dialect == ShaderDialect::Es300) {
    throw std::logic_error(
        "internal error in zeroset: a double-precision ray polynomial "
        "cannot be assembled for GLSL ES");
  }
  // #version must come first.
  std::string out = versionHeader(prelude, dialect);
  if (dialect == ShaderDialect::Gl330) {
    // NVIDIA's compiler unrolls every loop it can count, which costs up to half of a
    // program's compile and buys nothing measurable in its frames (docs/renderer.md, "GPU
    // drivers"); other drivers ignore the pragma, and WebGL2 never sees it.
    out += "#pragma optionNV(unroll none)\n#line 2 0\n";
  }
  out += prelude.substr(prelude.find('\n') + 1);
  if (poly && poly->fp64) {  // the ray polynomial is expanded in double
    // An #extension must precede every non-preprocessor token: right after #version.
    const std::size_t firstLine = out.find('\n') + 1;
    out.insert(firstLine, "#extension GL_ARB_gpu_shader_fp64 : require\n#line 2 0\n");
  }
  int string = 1;
  appendPiece(out, "generated formula block (src/codegen/emit_glsl.cpp)", string++, formula.source);
  if (poly) {
    appendPiece(out, "generated ray polynomial (src/codegen/emit_ray_polynomial.cpp)", string++,
                poly->source);
  }
  if (interval) {
    appendPiece(out, "shaders/templates/" + std::string(kIntervalPreludeTemplate), string++,
                shaderTemplate(kIntervalPreludeTemplate));
    appendPiece(out, "shaders/templates/" + std::string(kAffinePreludeTemplate), string++,
                shaderTemplate(kAffinePreludeTemplate));
    appendPiece(out, "generated interval block (src/codegen/emit_interval_glsl.cpp)", string++,
                interval->source);
  }
  const std::string_view frame = shaderTemplate(kFrameTemplate);
  appendPiece(
      out, "shaders/templates/" + std::string(kFrameTemplate), string++,
      (dialect == ShaderDialect::Gl330 ? "#ifdef RT_FRAME_UNIFORMS\n" + frameStruct(frame) +
                                             "#else\n#define RT_FRAME_STORAGE in\n" +
                                             std::string(frame) + "#define RT_FRAME_BEGIN\n#endif\n"
                                       : frameStruct(frame)) +
          (interval ? std::string(kHasBeamDefine) : std::string()));
  if (!markers.empty()) appendPiece(out, "highlights.singular markers", string++, markers);
  appendPiece(out, "shaders/templates/" + std::string(kRaytraceTemplate), string++, raytrace);
  appendPiece(out, "shaders/templates/" + std::string(kShadingTemplate), string++,
              shaderTemplate(kShadingTemplate));
  appendPiece(out, "shaders/templates/" + std::string(marchName), string++, march);
  if (!firstRoots.empty())
    appendPiece(out, "shaders/templates/" + std::string(kFirstRootsTemplate), string++, firstRoots);
  if (interval)
    appendPiece(out, "shaders/templates/" + std::string(kBeamTemplate), string++,
                shaderTemplate(kBeamTemplate));
  // Last: a volume skips stretches with what the interval or Bernstein pieces define.
  appendPiece(out, "shaders/templates/" + std::string(kVolumeTemplate), string,
              shaderTemplate(kVolumeTemplate));
  return out;
}

}  // namespace

std::string assembleFragmentShader(const GlslFormula& formula, std::string_view markers,
                                   ShaderDialect dialect) {
  return assemble(formula, nullptr, nullptr, markers, dialect);
}

std::string assembleFragmentShader(const GlslFormula& formula, const RayPolynomialGlsl& poly,
                                   std::string_view markers, ShaderDialect dialect) {
  return assemble(formula, &poly, nullptr, markers, dialect);
}

std::string assembleFragmentShader(const GlslFormula& formula, const IntervalGlsl& interval,
                                   std::string_view markers, ShaderDialect dialect) {
  return assemble(formula, nullptr, &interval, markers, dialect);
}

std::string markerBlock(const std::vector<std::array<double, 3>>& points, double radius,
                        const std::array<double, 3>& color) {
  if (points.empty()) return {};
  auto f = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    std::string t = text;
    if (t.find_first_of(".e") == std::string::npos) t += ".0";
    return t;
  };
  const std::string n = std::to_string(points.size());
  std::string s = "#define RT_MARKERS\nconst int RT_MARKER_COUNT = " + n + ";\n";
  s += "const vec4 rtMarkers[" + n + "] = vec4[" + n + "](";
  for (std::size_t i = 0; i < points.size(); ++i) {
    s += (i ? ",\n    " : "\n    ") + std::string("vec4(") + f(points[i][0]) + ", " +
         f(points[i][1]) + ", " + f(points[i][2]) + ", " + f(radius) + ")";
  }
  s += ");\nconst vec3 rtMarkerColor = vec3(" + f(color[0]) + ", " + f(color[1]) + ", " +
       f(color[2]) + ");\n";
  return s;
}

std::string vertexShaderSource(ShaderDialect dialect) {
  // The frame block and its uniforms go right after #version; the template's numbering
  // resumes after them.
  const std::string_view vertex = shaderTemplate(kVertexTemplate);
  const std::string_view frame = shaderTemplate(kFrameTemplate);
  const std::size_t firstLine = vertex.find('\n') + 1;
  std::string out = versionHeader(vertex, dialect);
  if (dialect == ShaderDialect::Gl330) {
    out += "#ifdef RT_FRAME_UNIFORMS\nvoid rtCopyFrame() {}\n#else\n";
    appendPiece(out, "shaders/templates/" + std::string(kFrameTemplate), 1,
                "#define RT_FRAME_STORAGE out\n" + std::string(frame));
    appendPiece(out, "generated from frame_params.glsl (shader_assembly.cpp)", 2,
                frameUniformsAndCopy(frame));
    out += "#endif\n";
  } else {
    appendPiece(out, "GLSL ES: the fragment stage reads the frame's uniforms (shader_assembly.cpp)",
                1, "void rtCopyFrame() {}\n");
  }
  out += "#line 2 0\n";
  out.append(vertex.substr(firstLine));
  return out;
}

}  // namespace zs
