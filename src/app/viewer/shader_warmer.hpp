#pragma once
// The viewer's surface worker's second job (surface_worker.hpp, its warm-up step): in a
// headless GL context of its own, compile each new surface's program and draw it once, small,
// into a target of the window's formats (render/view_target.hpp), so the driver's shader
// cache holds the very program the window asks for next, and the window's compile of it
// takes milliseconds instead of stopping the picture. At its first surface it warms the
// tape interpreters (pipeline/load_surface.hpp) the same way, which the window then draws
// every new formula's first picture with. Without a headless context (no EGL) it does
// nothing and the window compiles as before.
#include <array>
#include <atomic>
#include <memory>

#include "pipeline/load_surface.hpp"
#include "render/gl_context.hpp"
#include "render/view_target.hpp"

namespace zs::app {

class ShaderWarmer {
 public:
  // All on the worker thread. warm: a new surface's program; warmInterpreters: the tape
  // interpreters for the method of the last surface warmed, once (while the worker is idle:
  // several seconds of JIT on llvmpipe that no build waits for).
  void warm(const Scene& scene, const PreparedSurface& surface);
  void warmInterpreters();
  void stop();  // releases every GL object and the context

  // Whether the interpreters for this kind of method have been warmed (any thread).
  bool interpretersWarm(bool sampling) const { return interpretersWarm_[sampling].load(); }

 private:
  bool ensureContext();

  std::unique_ptr<GlContext> context_;
  bool failed_ = false;
  std::unique_ptr<RayTracer> tracer_;
  std::unique_ptr<ViewTarget> target_;
  std::unique_ptr<TapeInterpreters> interpreters_;
  Scene last_;  // the scene of the last surface warmed
  std::array<std::atomic<bool>, 2> interpretersWarm_{};
};

// The window's variant of a picture in a ViewTarget of 16 x 16 pixels (the size does not
// change the program): what the warmer and the window's own first use draw.
void drawWarmUp(RayTracer& tracer, ViewTarget& target, const Scene& scene);

}  // namespace zs::app
