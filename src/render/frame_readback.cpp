#include "render/frame_readback.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "render/shading_defines.hpp"

namespace zs {

Frame readFrame(OffscreenTarget& target, int width, int height, bool curvature) {
  GLint drawBinding = 0, readBinding = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawBinding);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readBinding);
  target.bind();
  Frame frame;
  // GL rows come bottom-up, frames are top-down.
  frame.color = {width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  frame.depth = {width, height, std::vector<float>(std::size_t(width) * height)};
  std::vector<std::uint8_t> rgba(frame.color.rgba.size());
  std::vector<float> depth(frame.depth.values.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, depth.data());
  std::vector<float> value(curvature ? depth.size() : 0);
  if (curvature) {
    glReadBuffer(GL_COLOR_ATTACHMENT2);
    glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, value.data());
    frame.value = {width, height, std::vector<float>(value.size())};
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawBinding));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readBinding));
  for (int y = 0; y < height; ++y) {
    const std::size_t src = std::size_t(height - 1 - y) * width, dst = std::size_t(y) * width;
    std::memcpy(&frame.color.rgba[dst * 4], &rgba[src * 4], std::size_t(width) * 4);
    std::memcpy(&frame.depth.values[dst], &depth[src], std::size_t(width) * sizeof(float));
    if (curvature)
      std::memcpy(&frame.value.values[dst], &value[src], std::size_t(width) * sizeof(float));
  }
  return frame;
}

double probeCurvatureRange(OffscreenTarget& target, const RenderSettings& settings,
                           const Domain& domain, int width, int height,
                           const std::function<void(int w, int h)>& draw) {
  GLint drawBinding = 0, readBinding = 0;  // the viewer traces into its own framebuffer
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawBinding);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readBinding);
  if (!target.ensure(std::max(width, 1), std::max(height, 1)).empty()) return 1;
  const int w = std::max(width / 4, 1), h = std::max(height / 4, 1);
  target.bind();
  draw(w, h);
  std::vector<float> values(std::size_t(w) * h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT2);
  glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, values.data());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawBinding));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readBinding));
  // Noise floor: 1e-3 of the curvature of a sphere as large as the domain.
  const Domain box = boundingBox(domain);
  const double half =
      0.5 * std::hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]);
  const double floor =
      settings.shading.color == ColorMode::Gauss ? 1e-3 / (half * half) : 1e-3 / half;
  return curvatureRangeOf(std::move(values), floor);
}

}  // namespace zs
