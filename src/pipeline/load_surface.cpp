#include "pipeline/load_surface.hpp"

#include <iostream>

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
