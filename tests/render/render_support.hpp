#pragma once
// Shared by the render tests: a GL context per backend (created once per process), the
// real pipeline from formula text to a ready RayTracer (parser -> gradient -> GLSL ->
// octree -> hierarchy), and reference-image comparison with ZS_UPDATE_REFERENCE=1 to
// regenerate the PNGs under tests/render/reference.
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/camera.hpp"
#include "render/ray_tracer.hpp"
#include "render/settings.hpp"
#include "interval/octree_settings.hpp"

namespace zs::test {

// The context of `backend`, made current; null (with a message in `error`) when the
// machine has none. Contexts live until the process exits.
GlContext* context(Backend backend, std::string& error);

struct SurfaceSpec {
  std::string formula;
  Domain domain{};
  int octreeLevel = 3;
  std::vector<double> params{};
  Criteria criteria = Criteria::Thesis;
  // Auto: Bernstein for polynomials up to the degree limit, as the app; Bernstein: for every
  // polynomial, beyond the limit too.
  TracingMethod method = TracingMethod::Auto;
  // highlights.singular markers (codegen/shader_assembly.hpp markerBlock); none by default.
  std::vector<std::array<double, 3>> markers{};
  double markerRadius = 0.05;
  std::array<double, 3> markerColor{0.9, 0.15, 0.55};
  // The second derivatives (codegen/emit_hessian.hpp), which shading.color "gauss" and
  // "mean" need.
  bool hessian = false;
};

// Builds a ray tracer for `spec` on the current context. Returns null with `error` set
// (parse error, compile log, octree error) on failure.
std::unique_ptr<RayTracer> makeTracer(const SurfaceSpec& spec, std::string& error);

// Small, fast settings for tests: defaults of settings.hpp with the camera at `eye`.
RenderSettings testSettings(Vec3 eye = {0, 0, 3});

// The part [t0, t1] of the ray (t >= 0) inside `box`, in double: t0 > t1 when it misses.
std::pair<double, double> rayInBox(const Ray& r, const Domain& box);

// Compares `image` with tests/render/reference/<name>.png within the tolerance of
// image.hpp; with ZS_UPDATE_REFERENCE=1 writes the reference instead. On mismatch the
// render is written next to the test binary as <name>.actual.png. "" when it matches.
std::string matchReference(const std::string& name, const Image& image);

std::string sourceDir();

// Share of pixels whose RGB is within `tolerance` (0..255) of `rgb` (0..1).
double fractionNear(const Image& image, Vec3 rgb, int tolerance = 3);
bool pixelNear(const Image& image, int x, int y, Vec3 rgb, int tolerance = 3);

}  // namespace zs::test
