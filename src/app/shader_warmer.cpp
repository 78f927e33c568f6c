#include "app/shader_warmer.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <functional>
#include <mutex>
#include <string>

#include "interact/trace_budget.hpp"

namespace zs::app {

void drawWarmUp(RayTracer& tracer, ViewTarget& target, const Scene& scene, int width, int height) {
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
  const std::size_t program = programKey(surface.fragmentShader);
  loaded_ = 0;
  if (!loadSurface(*tracer_, surface, scene.render).empty()) return;
  loaded_ = program;
  // A program whose passes were warmed before (a new parameter value, octree level) is drawn
  // with them at once; a new one without them, which the front end then does too until
  // warmPasses: its beam and tile mask are programs of their own, whose compile would hold up
  // the first picture.
  bool passes = true;
  if (tracer_->hasBeamPass()) {
    std::lock_guard lock(mutex_);
    passes = contains(warm_, program);
    if (!passes && !contains(deferred_, program)) remember(deferred_, program);
  }
  tracer_->setBeamPass(passes);
  // From the scene's eye at a quarter of its size: a picture like the front end's next full
  // one, so that the variant llvmpipe compiles is the one that picture needs (drawWarmUp
  // says why), for a sixteenth of its pixels.
  draw(scene, std::max(1, scene.width / 4), std::max(1, scene.height / 4));
}

void ShaderWarmer::warmPasses(const Scene& scene) {
  if (!context_ || !loaded_ || passesWarm(loaded_)) return;
  // The picture itself, at its full size: whether the frame skips its clear tiles with a
  // stencil test (another variant of the frame's program) depends on it.
  tracer_->setBeamPass(true);
  draw(scene, std::max(1, scene.width), std::max(1, scene.height));
  std::lock_guard lock(mutex_);
  deferred_.erase(std::remove(deferred_.begin(), deferred_.end(), loaded_), deferred_.end());
  remember(warm_, loaded_);
}

std::size_t ShaderWarmer::programKey(const std::string& fragmentShader) {
  return std::hash<std::string>{}(fragmentShader);
}

bool ShaderWarmer::passesWarm(std::size_t program) const {
  std::lock_guard lock(mutex_);
  return !contains(deferred_, program);
}

bool ShaderWarmer::contains(const std::vector<std::size_t>& programs, std::size_t program) {
  return std::find(programs.begin(), programs.end(), program) != programs.end();
}

void ShaderWarmer::remember(std::vector<std::size_t>& programs, std::size_t program) {
  programs.push_back(program);
  if (programs.size() > kRemembered) programs.erase(programs.begin());
}

void ShaderWarmer::draw(const Scene& scene, int width, int height) {
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
    single.render = firstPictureSettings(scene.render);
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
