#include "pipeline/load_surface.hpp"

#include <iostream>

#include "interpreter/interpreter_glsl.hpp"

namespace zs {

std::string loadSurface(RayTracer& tracer, const PreparedSurface& surface) {
  std::string log;
  if (!tracer.build(surface.vertexShader, surface.fragmentShader, log)) return log;
  if (std::string err = tracer.setHierarchy(surface.hierarchy.packed()); !err.empty()) {
    return "error: " + err + "\n";
  }
  tracer.setParams(surface.paramsAsFloats());
  return {};
}

std::string buildInterpreter(RayTracer& tracer, bool sampling, bool polynomialOnly) {
  std::string log;
  if (!tracer.build(vertexShaderSource(ShaderDialect::Gl330),
                    interpreterFragmentShader(sampling, polynomialOnly), log))
    return log;
  return {};
}

std::string loadQuickSurface(RayTracer& tracer, const QuickSurface& surface) {
  if (std::string err = tracer.setTape(surface.tape.texels); !err.empty()) return "error: " + err + "\n";
  if (std::string err = tracer.setHierarchy(surface.hierarchy.packed()); !err.empty())
    return "error: " + err + "\n";
  tracer.setParams(std::vector<float>(surface.params.begin(), surface.params.end()));
  return {};
}

HeadlessTracer openHeadlessTracer(Backend backend, const PreparedSurface& surface) {
  ContextResult ctx = createHeadlessContext(backend);
  if (!ctx.context) {
    std::cerr << "error: " << ctx.error << "\n"
              << (backend == Backend::Egl ? "hint: try --backend osmesa\n" : "");
    return {};
  }
  HeadlessTracer out{std::move(ctx.context), std::make_unique<RayTracer>()};  // needs the context
  if (std::string err = loadSurface(*out.tracer, surface); !err.empty()) {
    std::cerr << err;
    return {};
  }
  return out;
}

}  // namespace zs
