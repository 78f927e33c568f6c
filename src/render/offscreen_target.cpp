#include "render/offscreen_target.hpp"

#include <glad/gl.h>

namespace zs {

OffscreenTarget::~OffscreenTarget() { release(); }

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
  auto makeTexture = [&](GLenum internal, GLenum format, GLenum type) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return tex;
  };
  color_ = makeTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
  depth_ = makeTexture(GL_R32F, GL_RED, GL_FLOAT);  // distance to the first hit
  value_ = makeTexture(GL_R32F, GL_RED, GL_FLOAT);  // curvature colorings: the curvature
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, depth_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, value_, 0);
  // For tile skipping (the ray tracer's markClearTiles); depth and stencil come in one
  // format everywhere.
  glGenRenderbuffers(1, &stencil_);
  glBindRenderbuffer(GL_RENDERBUFFER, stencil_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            stencil_);
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
