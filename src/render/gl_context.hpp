#pragma once
// GL contexts: takes a backend choice, puts out a current OpenGL 3.3+ core context whose
// entry points are loaded through glad. Three backends: EGL (the headless default,
// Mesa's surfaceless platform or else an EGL device; renders into FBOs only), OSMesa (core profile,
// software only) and a GLFW window (glfw_context.hpp, for the viewer). Every makeCurrent() reloads
// the glad function pointers from that context's own get-proc-address, because libOSMesa and
// libOpenGL both export gl* symbols and whichever the linker picked may be the wrong one. Creation
// never aborts: failures come back as an error string.
#include <memory>
#include <string>

namespace zs {

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread and reloads glad. False (with
  // lastError()) when the platform refuses or the loader finds no GL.
  virtual bool makeCurrent() = 0;
  // "EGL surfaceless", "EGL device 0" (the first of EGL_EXT_device_enumeration that worked),
  // "OSMesa", "GLFW window".
  virtual std::string backendName() const = 0;
  const std::string& lastError() const { return error_; }

  // GL_VERSION and GL_RENDERER of the current context, e.g. "4.5 (Core Profile) Mesa
  // 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)". Requires this context to be current.
  static std::string describeCurrent();

 protected:
  std::string error_;
};

enum class Backend { Egl, OsMesa };

struct ContextResult {
  std::unique_ptr<GlContext> context;  // current on success, null on failure
  std::string error;                   // why it failed; empty on success
};

// gladLoadGL through `getProcAddress`, one thread at a time: glad's entry points are process
// globals, and the viewer makes headless contexts current on other threads (the surface
// worker, a print) beside its window. Under libglvnd every loader hands out the same
// dispatch stubs, so a reload by another thread never changes a pointer in use.
bool loadGlEntryPoints(void* (*getProcAddress)(const char*));

// Creates a context with no window and makes it current. Never aborts.
ContextResult createHeadlessContext(Backend backend);

// Backends (egl_context.cpp, osmesa_context.cpp); createHeadlessContext dispatches here.
ContextResult createEglContext();
ContextResult createOsMesaContext();

// "egl" / "osmesa" -> Backend; false for anything else.
bool parseBackend(const std::string& name, Backend& out);

}  // namespace zs
