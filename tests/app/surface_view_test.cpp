// The viewer's GL half (app/viewer/surface_view.hpp) in real GLFW windows (ctest runs this
// binary under xvfb-run): the first pictures' interpreters warm up on a thread of their own,
// in their own context, while the window's thread goes on drawing the surface's picture.
#include "app/viewer/surface_view.hpp"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <variant>
#include <vector>

#include "pipeline/pipeline.hpp"
#include "pipeline/quick_surface.hpp"
#include "render/glfw_context.hpp"

namespace zs::app {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Scene sceneOf(const std::string& formula) {
  Scene s;
  s.formula = formula;
  s.width = kWidth;
  s.height = kHeight;
  return s;
}

// Traces the picture, presents it to the window's back buffer and reads that back.
std::vector<unsigned char> picture(SurfaceView& view, const Scene& scene) {
  view.trace(scene.render, scene.domain, kWidth, kHeight, 1);
  view.present(kWidth, kHeight);
  std::vector<unsigned char> pixels(std::size_t(kWidth) * kHeight * 4);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

TEST(SurfaceView, InterpretersWarmOnAThreadOfTheirOwnWhileTheWindowDraws) {
  auto window = GlfwWindowContext::create(kWidth, kHeight, "zeroset surface view test", false);
  if (!window.context) GTEST_SKIP() << "no window: " << window.error;
  auto first = GlfwWindowContext::create(16, 16, "first pictures", false);
  ASSERT_TRUE(first.context) << first.error;
  window.context->makeCurrent();
  {
    SurfaceView view;
    view.drawFirstPicturesIn(std::move(first.context), window.context.get());
    const Scene sphere = sceneOf("x^2+y^2+z^2-1");
    auto prepared = prepareSurface(sphere);
    ASSERT_TRUE(std::holds_alternative<PreparedSurface>(prepared))
        << std::get<std::string>(prepared);
    ASSERT_EQ(view.upload(std::get<PreparedSurface>(prepared), sphere.render), "");

    std::atomic<bool> done{false};
    view.warmInterpreters(sphere, kWidth, kHeight, [&] { done = true; });
    EXPECT_FALSE(view.interpretersWarm(false)) << "the warm-up runs beside this thread";
    const std::vector<unsigned char> during = picture(view, sphere);
    const bool drewWhileWarming = !done;
    while (!done) picture(view, sphere);
    EXPECT_TRUE(drewWhileWarming) << "the window drew only after the warm-up";
    ASSERT_TRUE(view.interpretersWarm(false));
    EXPECT_EQ(during, picture(view, sphere)) << "the window's picture is the same as after it";

    // A first picture with the warmed interpreters, drawn into the window's picture.
    const Scene hyperboloid = sceneOf("x^2+y^2-z^2-0.3");
    auto quick = prepareQuickSurface(hyperboloid);
    ASSERT_TRUE(std::holds_alternative<QuickSurface>(quick)) << std::get<std::string>(quick);
    ASSERT_TRUE(view.showQuick(std::get<QuickSurface>(quick)));
    const std::vector<unsigned char> firstPicture = picture(view, hyperboloid);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < during.size(); i += 4) differing += firstPicture[i] != during[i];
    EXPECT_GT(differing, during.size() / 4 / 20) << "the hyperboloid's first picture is shown";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

}  // namespace
}  // namespace zs::app
