#pragma once
// The GL half of the viewer: takes prepared surfaces (shader text, packed hierarchy,
// parameter values) and render settings, puts out frames in the window. The ray-traced
// image is cached in an offscreen target and only re-traced when something changed; each
// window frame just blits it (and the panel draws on top). While the user drags, the trace
// runs at 1/scale of the window's resolution into a second, smaller target that the blit
// stretches, so llvmpipe keeps up; when the drag ends the full-resolution image replaces it.
// A new formula's first picture comes from the tape interpreter (docs/interpreter.md) until
// its own surface is uploaded, drawn in a GL context of its own where the viewer gives one.
// Needs the window's GL context current for its whole life.
#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/glfw_context.hpp"
#include "render/ray_tracer.hpp"
#include "render/view_target.hpp"

namespace zs::app {

class SurfaceView {
 public:
  SurfaceView();
  ~SurfaceView();
  SurfaceView(const SurfaceView&) = delete;
  SurfaceView& operator=(const SurfaceView&) = delete;

  // First pictures in `first`, a GL context made for them (`home` is the window's, current
  // again after each use). llvmpipe drops a context's least recently used compiled programs
  // beyond a budget, and a formula's own program compiled beside the interpreter with every
  // operation would drop the interpreter's: the next first picture would compile it again,
  // a pause of over a second (docs/interpreter.md). Call before the interpreters warm up.
  // A hidden window's context: the interpreters warm up in it on a thread of their own.
  void drawFirstPicturesIn(std::unique_ptr<GlfwWindowContext> first, GlContext* home);

  // Compiles the shaders (skipped when their text equals the current program's: a new
  // parameter value or octree level changes only the hierarchy), then sets the hierarchy
  // and the parameters. "" on success; on failure the previous surface stays.
  // The surface's own program replaces a first picture only when `endsQuick`.
  std::string upload(const PreparedSurface& surface, const RenderSettings& drawnWith,
                     bool endsQuick = true);
  void setParams(std::span<const float> params);
  // Whether the surface's own program draws with its beam pass and tile mask (the picture is
  // the same without them): off until the ShaderWarmer has compiled them.
  void setBeamPass(bool on) { tracer_.setBeamPass(on); }
  bool ready() const { return tracer_.ready() || quick_; }

  // Compiles and draws the interpreters for this kind of method (quicker once the surface
  // worker's ShaderWarmer has compiled them: the driver's cache holds them). With a context
  // of their own this happens on a thread of its own, which calls `done` when it finishes
  // (from that thread), and the window's frames go on meanwhile: on llvmpipe it takes about
  // a second even from the cache. Without, it happens here, before this returns.
  // width x height: the window's, whose first pictures they draw.
  void warmInterpreters(const Scene& scene, int width, int height,
                        const std::function<void()>& done = {});
  bool interpretersWarm(bool sampling) const { return warm_[sampling]; }
  // Draws `surface` with the tape interpreter from the next trace on, until an upload that
  // ends it; false (nothing changes) when no interpreter is ready for it.
  bool showQuick(const QuickSurface& surface);
  void endQuick() { quick_ = nullptr; }
  bool showingQuick() const { return quick_ != nullptr; }

  // Traces into the target for `scale` (1 = full resolution) of a width x height window
  // framebuffer and waits for it; returns the time the trace took in milliseconds.
  double trace(const RenderSettings& settings, const Domain& domain, int width, int height,
               int scale);
  // Draws the latest traced image over the whole default framebuffer (width x height).
  void present(int width, int height);
  int presentedScale() const { return lastScale_; }
  // The curvature coloring's range in the latest trace (0 for the other colorings).
  double curvatureRange() const { return current().curvatureRange(); }
  bool hasImage() const { return lastScale_ > 0; }

  // A clean full-resolution frame (no panel), for screenshots.
  Frame screenshot(const RenderSettings& settings, const Domain& domain, int width, int height);

 private:
  RayTracer& current() { return quick_ ? *quick_ : tracer_; }
  const RayTracer& current() const { return quick_ ? *quick_ : tracer_; }

  // The interpreters and what they draw into: GL objects of the first pictures' context.
  struct FirstPictures {
    TapeInterpreters interpreters;
    ViewTarget warmTarget, target;
  };
  // Makes the first pictures' context current for its life, the window's again after.
  class FirstPicturesScope {
   public:
    explicit FirstPicturesScope(const SurfaceView& view);
    ~FirstPicturesScope();
    FirstPicturesScope(const FirstPicturesScope&) = delete;
    FirstPicturesScope& operator=(const FirstPicturesScope&) = delete;

   private:
    const SurfaceView& view_;
  };
  // Draws the first picture w x h in its own context, reads it back and copies it into
  // `into` (a target of the window's context).
  void traceQuick(ViewTarget& into, const RenderSettings& settings, const Domain& domain, int w,
                  int h);

  RayTracer tracer_;
  std::unique_ptr<GlfwWindowContext> firstContext_;
  GlContext* home_ = nullptr;
  std::unique_ptr<FirstPictures> first_;
  std::vector<unsigned char> quickPixels_;
  RayTracer* quick_ = nullptr;  // the interpreter drawing a first picture, or none
  ViewTarget full_, reduced_;
  int lastScale_ = 0;  // which target holds the latest image; 0 = none yet
  // The warm-up thread owns the first pictures' context (and first_) while warming_ is set:
  // nothing here makes that context current meanwhile.
  std::thread warmUp_;
  std::atomic<bool> warming_{false};
  std::array<std::atomic<bool>, 2> warm_{};  // [sampling]: the interpreters draw
};

}  // namespace zs::app
