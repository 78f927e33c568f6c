#pragma once
// A picture's framebuffer for a window: one RGBA8 color texture (linear filtering, so a
// smaller picture stretches when blitted) and a depth-stencil renderbuffer for tile skipping.
// The viewer traces into these and blits them; its surface worker draws into one of the same
// formats, so the program a worker compiles is the very variant the window then uses.
// Needs a current GL context; its objects belong to it.
#include <vector>

namespace zs {

class ViewTarget {
 public:
  ViewTarget() = default;
  ~ViewTarget();
  ViewTarget(const ViewTarget&) = delete;
  ViewTarget& operator=(const ViewTarget&) = delete;

  // Exactly width x height (made again when the size changes); false when the driver
  // cannot make it.
  bool ensure(int width, int height);
  unsigned framebuffer() const { return fbo_; }
  // The picture as RGBA8 rows from the bottom, into `rgba` (resized); and written back from
  // such rows, of this target's size (a picture read from a target of another context).
  void readPixels(std::vector<unsigned char>& rgba) const;
  void writePixels(const std::vector<unsigned char>& rgba);
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void release();

  unsigned fbo_ = 0, color_ = 0, stencil_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace zs
