// Offscreen targets are plain RGBA8 textures behind FBOs (render/view_target.hpp);
// presenting is one glBlitFramebuffer with linear filtering, cheap even on llvmpipe.
#include "app/viewer/surface_view.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>

#include "app/shader_warmer.hpp"
#include "pipeline/load_surface.hpp"

namespace zs::app {

SurfaceView::SurfaceView() : first_(std::make_unique<FirstPictures>()) {}

SurfaceView::~SurfaceView() {
  if (warmUp_.joinable()) warmUp_.join();
  FirstPicturesScope scope(*this);  // their GL objects go with their context
  quick_ = nullptr;
  first_.reset();
}

SurfaceView::FirstPicturesScope::FirstPicturesScope(const SurfaceView& view) : view_(view) {
  if (view_.firstContext_) view_.firstContext_->makeCurrent();
}

SurfaceView::FirstPicturesScope::~FirstPicturesScope() {
  if (view_.firstContext_) view_.home_->makeCurrent();
}

void SurfaceView::drawFirstPicturesIn(std::unique_ptr<GlfwWindowContext> first, GlContext* home) {
  if (!first || !home) return;
  if (warmUp_.joinable()) warmUp_.join();
  warm_[0] = warm_[1] = false;
  {
    FirstPicturesScope scope(*this);  // what was made in the window's context goes there
    quick_ = nullptr;
    first_.reset();
  }
  firstContext_ = std::move(first);
  home_ = home;
  FirstPicturesScope scope(*this);
  first_ = std::make_unique<FirstPictures>();
}

std::string SurfaceView::upload(const PreparedSurface& surface, const RenderSettings& drawnWith,
                                bool endsQuick) {
  std::string error = loadSurface(tracer_, surface, drawnWith);
  if (error.empty() && endsQuick) quick_ = nullptr;
  return error;
}

void SurfaceView::setParams(std::span<const float> params) {
  tracer_.setParams(params);
  if (quick_) quick_->setParams(params);  // kept on the CPU until the next draw
}

void SurfaceView::warmInterpreters(const Scene& scene, int width, int height,
                                   const std::function<void()>& done) {
  const bool sampling = scene.render.tracing.method == TracingMethod::Sampling;
  if (warm_[sampling] || warming_) return;
  Scene single = scene;
  single.render = firstPictureSettings(scene.render);
  // On the thread whose context is current; says whether they draw.
  const auto warm = [this, single, sampling, width, height] {
    first_->interpreters.warm(sampling, single, [&](RayTracer& t, const Scene& s) {
      drawInterpreterWarmUp(t, first_->warmTarget, s, width, height);
    });
    return first_->interpreters.warmed(sampling);
  };
  if (!firstContext_) {
    warm_[sampling] = warm();
    if (done) done();
    return;
  }
  if (warmUp_.joinable()) warmUp_.join();  // the warm-up of the other kind, finished
  quick_ = nullptr;  // a first picture of the other kind would need the context meanwhile
  warming_ = true;
  warmUp_ = std::thread([this, warm, sampling, done] {
    firstContext_->makeCurrent();
    const bool warmed = warm();
    glFinish();
    GlfwWindowContext::releaseCurrent();  // for the window's thread to make current
    warm_[sampling] = warmed;
    warming_ = false;
    if (done) done();
  });
}

bool SurfaceView::showQuick(const QuickSurface& surface) {
  if (warming_) return false;
  std::string error;
  FirstPicturesScope scope(*this);
  RayTracer* tracer = first_->interpreters.load(surface, error);
  if (!tracer) return false;
  quick_ = tracer;
  return true;
}

void SurfaceView::traceQuick(ViewTarget& into, const RenderSettings& settings, const Domain& domain,
                             int w, int h) {
  {
    FirstPicturesScope scope(*this);
    if (!first_->target.ensure(w, h)) return;
    glBindFramebuffer(GL_FRAMEBUFFER, first_->target.framebuffer());
    quick_->draw(settings, domain, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    first_->target.readPixels(quickPixels_);
  }
  into.writePixels(quickPixels_);
}

double SurfaceView::trace(const RenderSettings& settings, const Domain& domain, int width,
                          int height, int scale) {
  if (!ready() || width <= 0 || height <= 0) return 0;
  scale = std::clamp(scale, 1, 8);
  ViewTarget& target = scale == 1 ? full_ : reduced_;
  const int w = std::max(1, width / scale), h = std::max(1, height / scale);
  if (!target.ensure(w, h)) return 0;
  const auto start = std::chrono::steady_clock::now();
  if (quick_ && firstContext_) {
    traceQuick(target, settings, domain, w, h);
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    current().draw(settings, domain, w, h);
  }
  // Waiting here keeps the measured time honest and stops llvmpipe from queueing traces
  // behind each other while the mouse moves.
  glFinish();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  lastScale_ = scale;
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void SurfaceView::present(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const ViewTarget* source = lastScale_ == 1 ? &full_ : lastScale_ > 1 ? &reduced_ : nullptr;
  if (!source || !source->framebuffer()) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source->framebuffer());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, source->width(), source->height(), 0, 0, width, height,
                    GL_COLOR_BUFFER_BIT, source->width() == width ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Frame SurfaceView::screenshot(const RenderSettings& settings, const Domain& domain, int width,
                              int height) {
  if (!tracer_.ready()) {
    Frame frame;
    frame.error = "no surface to take a screenshot of yet";
    return frame;
  }
  return tracer_.render(settings, domain, width, height);
}

}  // namespace zs::app
