#include "render/view_target.hpp"

#include <glad/gl.h>

#include "render/framebuffer_parts.hpp"

namespace zs {

ViewTarget::~ViewTarget() {
  release();
}

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

void ViewTarget::readPixels(std::vector<unsigned char>& rgba) const {
  rgba.resize(std::size_t(width_) * std::size_t(height_) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void ViewTarget::writePixels(const std::vector<unsigned char>& rgba) {
  if (rgba.size() < std::size_t(width_) * std::size_t(height_) * 4) return;
  glBindTexture(GL_TEXTURE_2D, color_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace zs
