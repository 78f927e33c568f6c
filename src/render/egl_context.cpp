// EGL surfaceless context (EGL_MESA_platform_surfaceless): no display server, no window,
// rendering goes to FBOs. Mesa hands out 4.5 core for any request up to 4.5.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdio>

#include "render/gl_context.hpp"

namespace zs {
namespace {

std::string eglErrorText(const char* what) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what,
                static_cast<unsigned>(eglGetError()));
  return buf;
}

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
  ~EglContext() override {
    if (eglGetCurrentContext() == context_)
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // The display is shared by every EGL context of the process (EGL refcounts nothing),
    // so it is not terminated here; the driver releases it at exit.
  }

  bool makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      error_ = eglErrorText("eglMakeCurrent");
      return false;
    }
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0) {
      error_ = "glad could not load GL entry points through eglGetProcAddress";
      return false;
    }
    return true;
  }
  std::string backendName() const override { return "EGL surfaceless"; }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

}  // namespace

ContextResult createEglContext() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return {nullptr, "EGL lacks eglGetPlatformDisplayEXT"};
  EGLDisplay display =
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) return {nullptr, eglErrorText("surfaceless EGL display")};
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return {nullptr, eglErrorText("eglInitialize")};
  if (!eglBindAPI(EGL_OPENGL_API)) return {nullptr, eglErrorText("eglBindAPI(OpenGL)")};

  // No config: surfaceless contexts never get a default framebuffer (EGL_KHR_no_config_context).
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) return {nullptr, eglErrorText("eglCreateContext(core 3.3)")};

  auto result = std::make_unique<EglContext>(display, context);
  if (!result->makeCurrent()) return {nullptr, result->lastError()};
  return {std::move(result), {}};
}

}  // namespace zs
