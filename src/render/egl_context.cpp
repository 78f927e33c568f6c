// Headless EGL context: no display server, no window, rendering goes to FBOs. The display
// is Mesa's surfaceless platform (EGL_MESA_platform_surfaceless) when that initializes,
// else the first EGL device (EGL_EXT_device_enumeration + EGL_EXT_platform_device) that
// gives a context: NVIDIA's EGL need not have the surfaceless platform, but has devices.
// Either way the context is bound without surfaces (EGL_KHR_surfaceless_context). Mesa
// hands out 4.5 core for any request up to 4.5.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "render/gl_context.hpp"

namespace zs {
namespace {

std::string eglErrorText(const char* what) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what,
                static_cast<unsigned>(eglGetError()));
  return buf;
}

// Whole-word match in a space-separated EGL extension string (a prefix match would take
// EGL_EXT_device_base for EGL_EXT_device_b, say).
bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay display, EGLContext context, std::string name)
      : display_(display), context_(context), name_(std::move(name)) {}
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
    if (!loadGlEntryPoints(reinterpret_cast<void* (*)(const char*)>(eglGetProcAddress))) {
      error_ = "glad could not load GL entry points through eglGetProcAddress";
      return false;
    }
    return true;
  }
  std::string backendName() const override { return name_; }

 private:
  EGLDisplay display_;
  EGLContext context_;
  std::string name_;
};

// Initializes `display` and makes a current core context on it. A display that fails is
// not terminated either: another context of this process may be living on it.
ContextResult contextOn(EGLDisplay display, const char* name) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return {nullptr, eglErrorText("eglInitialize")};
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
    return {nullptr, "display lacks EGL_KHR_surfaceless_context"};
  if (!eglBindAPI(EGL_OPENGL_API)) return {nullptr, eglErrorText("eglBindAPI(OpenGL)")};

  // No config where the display allows it: surfaceless contexts never get a default
  // framebuffer (EGL_KHR_no_config_context). Elsewhere any GL-renderable config will do,
  // since the config would only describe that framebuffer.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE,
                             EGL_NONE};
    EGLint found = 0;
    if (!eglChooseConfig(display, wanted, &config, 1, &found) || found < 1)
      return {nullptr, "no OpenGL-renderable EGL config"};
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                            3,
                            EGL_CONTEXT_MINOR_VERSION,
                            3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) return {nullptr, eglErrorText("eglCreateContext(core 3.3)")};

  auto result = std::make_unique<EglContext>(display, context, name);
  if (!result->makeCurrent()) return {nullptr, result->lastError()};
  return {std::move(result), {}};
}

}  // namespace

ContextResult createEglContext() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return {nullptr, "EGL lacks eglGetPlatformDisplayEXT"};
  // Client extensions (EGL_NO_DISPLAY); with glvnd, the union over the installed vendors.
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  // Every failure is kept: when no display works, the reason of each one is the message.
  std::string errors;
  auto note = [&errors](const std::string& why) { errors += (errors.empty() ? "" : "; ") + why; };

  if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) {
      note(eglErrorText("surfaceless EGL display"));
    } else {
      ContextResult result = contextOn(display, "EGL surfaceless");
      if (result.context) return result;
      note("surfaceless: " + result.error);
    }
  } else {
    note("no EGL_MESA_platform_surfaceless");
  }

  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  const bool enumerates = hasExtension(client, "EGL_EXT_device_enumeration") ||
                          hasExtension(client, "EGL_EXT_device_base");
  if (!queryDevices || !enumerates || !hasExtension(client, "EGL_EXT_platform_device")) {
    note("no EGL_EXT_device_enumeration with EGL_EXT_platform_device");
    return {nullptr, errors};
  }
  EGLint count = 0;
  if (!queryDevices(0, nullptr, &count)) {
    note(eglErrorText("eglQueryDevicesEXT"));
    return {nullptr, errors};
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count > 0 ? count : 0));
  if (count > 0 && !queryDevices(count, devices.data(), &count)) {
    note(eglErrorText("eglQueryDevicesEXT"));
    return {nullptr, errors};
  }
  if (count <= 0) note("no EGL devices");
  for (EGLint i = 0; i < count; ++i) {
    const std::string label = "EGL device " + std::to_string(i);
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    if (display == EGL_NO_DISPLAY) {
      note(eglErrorText((label + " display").c_str()));
      continue;
    }
    ContextResult result = contextOn(display, label.c_str());
    if (result.context) return result;
    note(label + ": " + result.error);
  }
  return {nullptr, errors};
}

}  // namespace zs
