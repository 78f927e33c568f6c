#pragma once
// The ray tracer's offscreen framebuffer: color (RGBA8), the depth of the first hit and the
// curvature value (R32F each) as attachments 0, 1 and 2, and a depth-stencil renderbuffer for
// tile skipping. Made at a size when a frame first needs it, kept while the size stays.
// Needs a current GL context; its objects belong to it.
#include <string>

namespace zs {

class OffscreenTarget {
 public:
  OffscreenTarget() = default;
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  // At least width x height; "" on success, else why not (a size the driver cannot make).
  std::string ensure(int width, int height);
  // Binds it for drawing, with all three color attachments as draw buffers.
  void bind() const;
  unsigned framebuffer() const { return fbo_; }

 private:
  void release();

  unsigned fbo_ = 0, color_ = 0, depth_ = 0, value_ = 0, stencil_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace zs
