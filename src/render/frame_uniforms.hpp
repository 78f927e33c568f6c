#pragma once
// The values of a frame's uniforms, without GL: takes the RenderSettings, the domain that
// clips the rays, the GPU hierarchy and the image size, puts out every uniform the ray
// tracer's programs read (the frame block of frame_params.glsl, the proxy's, the formula's
// parameters) as a list of names and values. The desktop tracer hands them to glUniform*
// (ray_tracer_uniforms.cpp); the web page hands the same list to WebGL2 (src/web), so both
// draw the same frame from the same numbers. Out-of-range knobs are clamped here
// (docs/renderer.md), so no setting can hang or break the shader.
#include <span>
#include <string>
#include <vector>

#include "render/hierarchy_gpu.hpp"
#include "render/settings.hpp"

namespace zs {

struct UniformValue {
  enum class Kind { Int, Float, Vec2, Vec3, Vec4, Mat4, FloatArray };
  std::string name;
  Kind kind = Kind::Float;
  std::vector<float> values;  // every kind but Int
  int integer = 0;            // Int
};

// Which geometry starts the rays: the thesis' two full-screen triangles, or the box where
// hits can lie, so background pixels cost nothing (same picture; docs/renderer.md).
enum class Proxy { FullScreen, Box };

struct FrameInputs {
  const GpuHierarchy* hierarchy = nullptr;  // required
  std::span<const float> params;            // zs_params, in declaration order
  int width = 1, height = 1;                // the full picture, in pixels
  // A band of rows [bandTop, bandTop + bandHeight) of the full picture drawn into a target of
  // bandHeight rows (bandHeight 0: the whole picture). Its bottom edge must lie on the beam
  // pass's tile grid, counted from the picture's bottom: (height - bandTop - bandHeight) a
  // multiple of kBeamTile (program_variant.hpp), so every ray is the whole picture's.
  int bandTop = 0, bandHeight = 0;
  Proxy proxy = Proxy::Box;
  bool tangentRoots = true;   // sampling: look for tangent roots
  double curvatureRange = 0;  // the curvature colorings' range; <= 0: 1
};

struct FrameUniforms {
  std::vector<UniformValue> values;
  int vertices = 0;  // of the proxy: 6, 36, or 0 when nothing can be hit
};

FrameUniforms frameUniforms(const RenderSettings& settings, const Domain& clip,
                            const FrameInputs& inputs);

}  // namespace zs
