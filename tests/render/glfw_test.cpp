// The viewer's path: a GLFW window context (3.3 core forward-compatible) and
// RayTracer::draw into its default framebuffer. Needs an X display: run the suite under
// `xvfb-run -a` to include it; without DISPLAY it is skipped, not failed.
#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "render/glfw_context.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

TEST(Glfw, WindowDrawMatchesOffscreenRender) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (run under xvfb-run -a)";
  const int size = 48;
  auto window = GlfwWindowContext::create(size, size, "zeroset test", false);
  ASSERT_NE(window.context, nullptr) << window.error;
  EXPECT_NE(GlContext::describeCurrent().find("Core"), std::string::npos);
  std::string error;
  auto tracer = test::makeTracer({"x^2+y^2+z^2-1", {}, 2}, error);
  ASSERT_NE(tracer, nullptr) << error;
  int w = 0, h = 0;
  window.context->framebufferSize(w, h);
  ASSERT_EQ(w, size);
  ASSERT_EQ(h, size);
  const RenderSettings s = test::testSettings({0.5, 1.0, 3.0});
  tracer->draw(s, Domain{}, w, h);
  std::vector<std::uint8_t> rgba(std::size_t(w) * h * 4);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image drawn{w, h, std::vector<std::uint8_t>(rgba.size())};
  for (int y = 0; y < h; ++y)  // GL rows come bottom-up
    std::memcpy(drawn.pixel(0, y), &rgba[std::size_t(h - 1 - y) * w * 4], std::size_t(w) * 4);
  const Frame frame = tracer->render(s, Domain{}, w, h);
  ASSERT_EQ(frame.error, "");
  const ImageDiff diff = compareImages(drawn, frame.color, 2);
  EXPECT_EQ(diff.fractionOver, 0.0) << "max difference " << diff.maxDifference;
  EXPECT_LT(test::fractionNear(drawn, s.background), 0.9);  // the sphere is there
  window.context->swapBuffers();
}

}  // namespace
}  // namespace zs
