#pragma once
// A GLFW window with a 3.3 core forward-compatible context, for the interactive viewer
// (works under xvfb-run). Takes a size and a title, puts out the window (for input
// callbacks and swapping) and a GlContext whose makeCurrent reloads glad through
// glfwGetProcAddress. glfwInit/glfwTerminate are reference-counted across windows.
#include <string>

#include "render/gl_context.hpp"

struct GLFWwindow;

namespace zs {

class GlfwWindowContext final : public GlContext {
 public:
  ~GlfwWindowContext() override;
  bool makeCurrent() override;
  std::string backendName() const override { return "GLFW window"; }
  // Leaves the calling thread without a current context, so that another thread can make
  // this one current.
  static void releaseCurrent();

  GLFWwindow* window() const { return window_; }
  void swapBuffers();
  bool shouldClose() const;
  // Framebuffer size in pixels (differs from the window size on HiDPI screens).
  void framebufferSize(int& width, int& height) const;

  struct Result {
    std::unique_ptr<GlfwWindowContext> context;  // current on success
    std::string error;
  };
  // visible = false gives a hidden window (tests under xvfb). Never aborts: no display, no
  // GLFW or a refused context come back as an error.
  static Result create(int width, int height, const std::string& title, bool visible = true);

 private:
  explicit GlfwWindowContext(GLFWwindow* window) : window_(window) {}
  GLFWwindow* window_ = nullptr;
};

}  // namespace zs
