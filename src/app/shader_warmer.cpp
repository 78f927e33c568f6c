#include "app/shader_warmer.hpp"

#include <glad/gl.h>

#include <algorithm>

#include "interact/trace_budget.hpp"

namespace zs::app {

void drawWarmUp(RayTracer& tracer, ViewTarget& target, const Scene& scene, int width,
                int height) {
  if (!target.ensure(width, height)) return;
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
  tracer.draw(scene.render, scene.domain, width, height);
  // The reduced-resolution picture of a drag or a first picture draws without
  // supersampling (viewer.cpp): that variant too, where it differs.
  if (scene.render.samples > 1) {
    RenderSettings single = scene.render;
    single.samples = 1;
    tracer.draw(single, scene.domain, width, height);
  }
  glFinish();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void drawInterpreterWarmUp(RayTracer& tracer, ViewTarget& target, const Scene& scene,
                           int windowWidth, int windowHeight) {
  drawWarmUp(tracer, target, scene, std::max(1, windowWidth / interact::kFirstPictureMinScale),
             std::max(1, windowHeight / interact::kFirstPictureMinScale));
}

bool ShaderWarmer::ensureContext() {
  if (context_) return true;
  if (failed_) return false;
  ContextResult ctx = createHeadlessContext(backend_);
  if (!ctx.context) {  // no warm-up: the front end compiles it all
    failed_ = true;
    return false;
  }
  context_ = std::move(ctx.context);
  tracer_ = std::make_unique<RayTracer>();
  target_ = std::make_unique<ViewTarget>();
  return true;
}

void ShaderWarmer::warm(const Scene& scene, const PreparedSurface& surface) {
  if (!ensureContext()) return;
  if (!loadSurface(*tracer_, surface).empty()) return;
  // From the scene's eye at a quarter of its size: a picture like the front end's next full
  // one, so that the variant llvmpipe compiles is the one that picture needs (drawWarmUp
  // says why), for a sixteenth of its pixels.
  const int width = std::max(1, scene.width / 4), height = std::max(1, scene.height / 4);
  if (kind_ == Target::Window) {
    drawWarmUp(*tracer_, *target_, scene, width, height);
  } else {
    tracer_->drawOffscreen(scene.render, scene.domain, width, height);
    glFinish();
  }
}

void ShaderWarmer::stop() {
  target_.reset();
  tracer_.reset();
  context_.reset();
}

void ShaderWarmer::wantInterpreters(const Scene& scene) {
  if (interpretersThread_.joinable()) return;
  interpretersThread_ = std::thread([this, scene] {
    ContextResult ctx = createHeadlessContext(Backend::Egl);
    if (!ctx.context) return;
    const bool sampling = scene.render.tracing.method == TracingMethod::Sampling;
    Scene single = scene;
    single.render.samples = 1;  // first pictures draw without supersampling
    {
      TapeInterpreters interpreters;  // its GL objects go before the context
      ViewTarget target;
      const auto draw = [&](RayTracer& t, const Scene& s) {
        drawInterpreterWarmUp(t, target, s, s.width, s.height);  // a window of the scene's size
      };
      const std::string error = interpreters.warm(sampling, single, draw);
      interpretersWarm_[sampling] = error.empty();
      // Then, while the window's first pictures already draw, the variant for pictures a
      // surface fills, into the driver's shader cache for the window's first use.
      if (error.empty()) interpreters.warmFilledPictures(sampling, single, draw);
    }
  });
}

ShaderWarmer::~ShaderWarmer() {
  if (interpretersThread_.joinable()) interpretersThread_.join();
}

}  // namespace zs::app
