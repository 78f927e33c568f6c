#include "render/offscreen_target.hpp"

#include <glad/gl.h>

#include "render/framebuffer_parts.hpp"

namespace zs {

OffscreenTarget::~OffscreenTarget() {
  release();
}

void OffscreenTarget::release() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (color_) glDeleteTextures(1, &color_);
  if (depth_) glDeleteTextures(1, &depth_);
  if (value_) glDeleteTextures(1, &value_);
  if (stencil_) glDeleteRenderbuffers(1, &stencil_);
  fbo_ = color_ = depth_ = value_ = stencil_ = 0;
  width_ = height_ = 0;
}

std::string OffscreenTarget::ensure(int width, int height) {
  if (fbo_ && width == width_ && height == height_) return {};
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
    return "image size " + std::to_string(width) + "x" + std::to_string(height) +
           " is outside 1.." + std::to_string(maxSize);
  release();
  color_ = newTexture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
  depth_ = newTexture2D(GL_R32F, GL_RED, GL_FLOAT, width, height);  // distance to the first hit
  value_ = newTexture2D(GL_R32F, GL_RED, GL_FLOAT, width, height);  // curvature colorings
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, depth_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, value_, 0);
  stencil_ = attachDepthStencil(width, height);  // tile skipping (markClearTiles)
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    return "offscreen framebuffer incomplete (status " + std::to_string(status) + ")";
  }
  width_ = width;
  height_ = height;
  return {};
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(3, buffers);
}

}  // namespace zs
