#pragma once
// The hand-over from the CPU half to the GPU half: takes a PreparedSurface and a RayTracer
// on a current context, puts the program (rebuilt only when the shader text changed), the
// packed sphere hierarchy and the parameter values into the tracer.
#include <string>

#include "app/pipeline.hpp"
#include "render/ray_tracer.hpp"

namespace zs::app {

// "" on success; otherwise text ready to print (the driver's log, or "error: ...").
std::string loadSurface(RayTracer& tracer, const PreparedSurface& surface);

}  // namespace zs::app
