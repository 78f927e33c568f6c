#pragma once
// Reading a finished frame back from the offscreen target: takes the target bound for
// reading and the picture's size, puts out the Frame (color top row first, depth, and the
// curvature values where a curvature coloring drew them), and the automatic curvature range
// from a smaller picture's values. Leaves the read framebuffer binding as it found it.
#include <functional>

#include "render/offscreen_target.hpp"
#include "render/ray_tracer.hpp"

namespace zs {

// The color, depth and (with `curvature`) value attachments of `target`, rows flipped to
// top-first.
Frame readFrame(OffscreenTarget& target, int width, int height, bool curvature);

// shading.curvature_range = 0: the range measured on a picture a quarter the size, drawn by
// `draw(w, h)` into the corner of `target` (bound for drawing by this function; the shader
// derives its rays from rt.resolution and the pixel, so a smaller resolution is a smaller
// picture of the same view), from its value attachment (render/shading_defines.hpp
// curvatureRangeOf). Restores the draw framebuffer binding.
double probeCurvatureRange(OffscreenTarget& target, const RenderSettings& settings,
                           const Domain& domain, int width, int height,
                           const std::function<void(int w, int h)>& draw);

}  // namespace zs
