#include "render/view_target.hpp"

#include <glad/gl.h>

#include "render/framebuffer_parts.hpp"

namespace zs {

ViewTarget::~ViewTarget() { release(); }

void ViewTarget::release() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (color_) glDeleteTextures(1, &color_);
  if (stencil_) glDeleteRenderbuffers(1, &stencil_);
  fbo_ = color_ = stencil_ = 0;
  width_ = height_ = 0;
}

bool ViewTarget::ensure(int width, int height) {
  if (fbo_ && width_ == width && height_ == height) return true;
  release();
  color_ = newTexture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height, /*linear=*/true);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  stencil_ = attachDepthStencil(width, height);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    release();
    return false;
  }
  width_ = width;
  height_ = height;
  return true;
}

}  // namespace zs
