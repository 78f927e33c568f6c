// GLFW window context. GLFW reports errors through a global callback; the last message is
// kept so create() can say why it failed (typically "X11: The DISPLAY environment variable
// is missing").
#include "render/glfw_context.hpp"

#include <GLFW/glfw3.h>
#include <glad/gl.h>

namespace zs {
namespace {

std::string g_lastGlfwError;
int g_liveWindows = 0;

void onGlfwError(int code, const char* text) {
  g_lastGlfwError = "GLFW error " + std::to_string(code) + ": " + (text ? text : "");
}

}  // namespace

GlfwWindowContext::Result GlfwWindowContext::create(int width, int height, const std::string& title,
                                                    bool visible) {
  if (width <= 0 || height <= 0) return {nullptr, "window size must be positive"};
  glfwSetErrorCallback(onGlfwError);
  if (g_liveWindows == 0 && !glfwInit()) return {nullptr, "glfwInit failed: " + g_lastGlfwError};
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window) {
    std::string error = "glfwCreateWindow(3.3 core) failed: " + g_lastGlfwError;
    if (g_liveWindows == 0) glfwTerminate();
    return {nullptr, error};
  }
  ++g_liveWindows;
  std::unique_ptr<GlfwWindowContext> context(new GlfwWindowContext(window));
  if (!context->makeCurrent()) return {nullptr, context->lastError()};
  return {std::move(context), {}};
}

GlfwWindowContext::~GlfwWindowContext() {
  glfwDestroyWindow(window_);
  if (--g_liveWindows == 0) glfwTerminate();
}

bool GlfwWindowContext::makeCurrent() {
  glfwMakeContextCurrent(window_);
  if (!loadGlEntryPoints(reinterpret_cast<void* (*)(const char*)>(glfwGetProcAddress))) {
    error_ = "glad could not load GL entry points through glfwGetProcAddress";
    return false;
  }
  return true;
}

void GlfwWindowContext::releaseCurrent() {
  glfwMakeContextCurrent(nullptr);
}

void GlfwWindowContext::swapBuffers() {
  glfwSwapBuffers(window_);
}
bool GlfwWindowContext::shouldClose() const {
  return glfwWindowShouldClose(window_) != 0;
}
void GlfwWindowContext::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

}  // namespace zs
