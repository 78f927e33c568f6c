// Offscreen targets are plain RGBA8 textures behind FBOs; presenting is one
// glBlitFramebuffer with linear filtering, which is cheap even on llvmpipe.
#include "app/viewer/surface_view.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>

#include "pipeline/load_surface.hpp"

namespace zs::app {

SurfaceView::~SurfaceView() {
  release(full_);
  release(reduced_);
}

std::string SurfaceView::upload(const PreparedSurface& surface) {
  return loadSurface(tracer_, surface);
}

void SurfaceView::release(Target& t) {
  if (t.fbo) glDeleteFramebuffers(1, &t.fbo);
  if (t.color) glDeleteTextures(1, &t.color);
  if (t.stencil) glDeleteRenderbuffers(1, &t.stencil);
  t = {};
}

bool SurfaceView::ensure(Target& t, int width, int height) {
  if (t.fbo && t.width == width && t.height == height) return true;
  release(t);
  glGenTextures(1, &t.color);
  glBindTexture(GL_TEXTURE_2D, t.color);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glGenFramebuffers(1, &t.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color, 0);
  glGenRenderbuffers(1, &t.stencil);
  glBindRenderbuffer(GL_RENDERBUFFER, t.stencil);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            t.stencil);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    release(t);
    return false;
  }
  t.width = width;
  t.height = height;
  return true;
}

double SurfaceView::trace(const RenderSettings& settings, const Domain& domain, int width,
                          int height, int scale) {
  if (!tracer_.ready() || width <= 0 || height <= 0) return 0;
  scale = std::clamp(scale, 1, 8);
  Target& target = scale == 1 ? full_ : reduced_;
  const int w = std::max(1, width / scale), h = std::max(1, height / scale);
  if (!ensure(target, w, h)) return 0;
  const auto start = std::chrono::steady_clock::now();
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
  tracer_.draw(settings, domain, w, h);
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
  const Target* source = lastScale_ == 1 ? &full_ : lastScale_ > 1 ? &reduced_ : nullptr;
  if (!source || !source->fbo) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source->fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, source->width, source->height, 0, 0, width, height,
                    GL_COLOR_BUFFER_BIT, source->width == width ? GL_NEAREST : GL_LINEAR);
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
