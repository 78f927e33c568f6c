// OSMesa context, core profile. OSMesa insists on a client-memory color buffer for
// OSMesaMakeCurrent; a 1x1 buffer satisfies it, all real rendering goes to FBOs.
// glad first: osmesa.h includes GL/gl.h, which glad's header guard then skips.
#include <glad/gl.h>
// clang-format off
#include <GL/osmesa.h>
// clang-format on

#include <array>

#include "render/gl_context.hpp"

namespace zs {
namespace {

class OsMesaContext final : public GlContext {
 public:
  explicit OsMesaContext(OSMesaContext context) : context_(context) {}
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  bool makeCurrent() override {
    if (!OSMesaMakeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      error_ = "OSMesaMakeCurrent failed";
      return false;
    }
    if (!loadGlEntryPoints(reinterpret_cast<void* (*)(const char*)>(OSMesaGetProcAddress))) {
      error_ = "glad could not load GL entry points through OSMesaGetProcAddress";
      return false;
    }
    return true;
  }
  std::string backendName() const override { return "OSMesa"; }

 private:
  OSMesaContext context_;
  std::array<unsigned char, 4> pixel_{};
};

}  // namespace

ContextResult createOsMesaContext() {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  OSMesaContext context = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!context) return {nullptr, "OSMesaCreateContextAttribs(core 3.3) failed"};
  auto result = std::make_unique<OsMesaContext>(context);
  if (!result->makeCurrent()) return {nullptr, result->lastError()};
  return {std::move(result), {}};
}

}  // namespace zs
