#pragma once
// The GL half of the viewer: takes prepared surfaces (shader text, packed hierarchy,
// parameter values) and render settings, puts out frames in the window. The ray-traced
// image is cached in an offscreen target and only re-traced when something changed; each
// window frame just blits it (and the panel draws on top). While the user drags, the trace
// runs at 1/scale of the window's resolution into a second, smaller target that the blit
// stretches, so llvmpipe keeps up; when the drag ends the full-resolution image replaces it.
// Needs the window's GL context current for its whole life.
#include <span>
#include <string>

#include "pipeline/pipeline.hpp"
#include "render/ray_tracer.hpp"

namespace zs::app {

class SurfaceView {
 public:
  SurfaceView() = default;
  ~SurfaceView();
  SurfaceView(const SurfaceView&) = delete;
  SurfaceView& operator=(const SurfaceView&) = delete;

  // Compiles the shaders (skipped when their text equals the current program's: a new
  // parameter value or octree level changes only the hierarchy), then sets the hierarchy
  // and the parameters. "" on success; on failure the previous surface stays.
  std::string upload(const PreparedSurface& surface);
  void setParams(std::span<const float> params) { tracer_.setParams(params); }
  bool ready() const { return tracer_.ready(); }

  // Traces into the target for `scale` (1 = full resolution) of a width x height window
  // framebuffer and waits for it; returns the time the trace took in milliseconds.
  double trace(const RenderSettings& settings, const Domain& domain, int width, int height,
               int scale);
  // Draws the latest traced image over the whole default framebuffer (width x height).
  void present(int width, int height);
  int presentedScale() const { return lastScale_; }
  // The curvature coloring's range in the latest trace (0 for the other colorings).
  double curvatureRange() const { return tracer_.curvatureRange(); }
  bool hasImage() const { return lastScale_ > 0; }

  // A clean full-resolution frame (no panel), for screenshots.
  Frame screenshot(const RenderSettings& settings, const Domain& domain, int width, int height);

 private:
  struct Target {
    unsigned fbo = 0, color = 0;
    unsigned stencil = 0;  // the tracer's tile skipping marks tiles off in it
    int width = 0, height = 0;
  };
  bool ensure(Target& target, int width, int height);
  static void release(Target& target);

  RayTracer tracer_;
  Target full_, reduced_;
  int lastScale_ = 0;  // which target holds the latest image; 0 = none yet
};

}  // namespace zs::app
