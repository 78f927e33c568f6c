// The backend-independent part of the contexts: the factory and the description string.
#include "render/gl_context.hpp"

#include <glad/gl.h>

#include <mutex>

namespace zs {

bool loadGlEntryPoints(void* (*getProcAddress)(const char*)) {
  static std::mutex loading;
  std::lock_guard lock(loading);
  return gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress)) != 0;
}

std::string GlContext::describeCurrent() {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_VERSION) + " / " + text(GL_RENDERER);
}

ContextResult createHeadlessContext(Backend backend) {
  switch (backend) {
    case Backend::Egl:
      return createEglContext();
    case Backend::OsMesa:
      return createOsMesaContext();
  }
  return {nullptr, "unknown GL backend"};
}

bool parseBackend(const std::string& name, Backend& out) {
  if (name == "egl") {
    out = Backend::Egl;
    return true;
  }
  if (name == "osmesa") {
    out = Backend::OsMesa;
    return true;
  }
  return false;
}

}  // namespace zs
