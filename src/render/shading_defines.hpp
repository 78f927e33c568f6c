#pragma once
// The compile-time half of shading: takes the RenderSettings, puts out the #define lines of
// the shader variant that raytrace_shading.frag.glsl reads (RT_LIGHTS: one constant entry
// per light that is on; RT_KEY_LIGHT; RT_COLOR; with shading.shadows RT_SHADOWS, the number
// of lights, and RT_SHADOW_RAYS, where each one's shadow ray goes). Lights are constants, not frame
// parameters, because llvmpipe's flat varyings cannot hold 8 lights and uniform reads in a
// fragment shader are slow (docs/renderer.md); changing a light compiles a new variant.
#include <string>
#include <vector>

#include "render/settings.hpp"

namespace zs {

std::string shadingDefines(const RenderSettings& settings);

// The automatic curvature range (shading.curvature_range = 0) from the values read back
// from a picture (NaN where nothing was hit): the 95th percentile of |value|, at least
// `floor` (a flat or cylindrical surface would otherwise stretch float noise over the whole
// color map); 1 when nothing was hit.
double curvatureRangeOf(std::vector<float> values, double floor);

}  // namespace zs
