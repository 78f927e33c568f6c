#include "app/load_surface.hpp"

namespace zs::app {

std::string loadSurface(RayTracer& tracer, const PreparedSurface& surface) {
  std::string log;
  if (!tracer.build(surface.vertexShader, surface.fragmentShader, log)) return log;
  if (std::string err = tracer.setHierarchy(surface.hierarchy.packed()); !err.empty()) {
    return "error: " + err + "\n";
  }
  tracer.setParams(surface.paramsAsFloats());
  return {};
}

}  // namespace zs::app
