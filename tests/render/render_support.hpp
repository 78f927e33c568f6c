#pragma once
// Shared by the render tests: a GL context per backend (created once per process), a ready
// RayTracer for a formula made by the app's own pipeline (pipeline/pipeline.hpp: what users
// get), and reference-image comparison with ZS_UPDATE_REFERENCE=1 to regenerate the PNGs
// under tests/render/reference.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "expr/tape.hpp"
#include "interval/octree_settings.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/ray_tracer.hpp"
#include "render/settings.hpp"
#include "scene/scene.hpp"

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
  // Auto: Bernstein for polynomials up to the degree limit and interval otherwise, as the
  // app; Bernstein: for every polynomial, beyond the limit too.
  TracingMethod method = TracingMethod::Auto;
  // highlights.singular markers (codegen/shader_assembly.hpp markerBlock); none by default.
  std::vector<std::array<double, 3>> markers{};
  double markerRadius = 0.05;
  std::array<double, 3> markerColor{0.9, 0.15, 0.55};
  // The second derivatives (codegen/emit_hessian.hpp), which shading.color "gauss" and
  // "mean" need.
  bool hessian = false;
  // shading.contours: its function is part of the shader.
  Contours contours{};
  // Surfaces drawn with `formula` (scene.hpp), and where they meet (unset: the default).
  std::vector<SurfaceEntry> moreSurfaces{};
  std::optional<Highlight> intersection{};
  // How the frame's parameters reach the fragment stage; unset: as the driver's (RayTracer()).
  std::optional<FrameStorage> frameStorage{};
};

// Builds a ray tracer for `spec` on the current context. Returns null with `error` set
// (parse error, compile log, octree error) on failure.
std::unique_ptr<RayTracer> makeTracer(const SurfaceSpec& spec, std::string& error);

// Small, fast settings for tests: defaults of settings.hpp with the camera at `eye`.
RenderSettings testSettings(Vec3 eye = {0, 0, 3});

// The part [t0, t1] of the ray (t >= 0) inside `box`, in double: t0 > t1 when it misses.
std::pair<double, double> rayInBox(const Ray& r, const Domain& box);

// The first root of F along r in [t0, t1], in double precision; NaN if there is none. f(t) =
// F(o + t d) and f'(t) = grad F . d (f must be a tape of F and its gradient) are sampled
// `samples` times: the first step where f changes sign, or where f' changes sign and f at the
// extremum (found by bisecting f') has the other sign, holds the first root, which bisection
// then finds. So two roots closer than a step are found too, as long as a step holds at most
// one extremum of f.
// `params`: one value per graph parameter.
double sampledFirstHit(PointEvaluator& f, const Ray& r, double t0, double t1, int samples,
                       std::span<const double> params = {});
// The same for F and its gradient written by hand: out = (F, dF/dx, dF/dy, dF/dz) at (x, y, z).
// A reference that is cast many times per pixel is much faster so than through a tape.
using FieldWithGradient = std::function<void(double x, double y, double z, double out[4])>;
double sampledFirstHit(const FieldWithGradient& f, const Ray& r, double t0, double t1, int samples);

// Whether the reference's answer at pixel (i, j), hit or miss, stays the same half a pixel
// away in each direction: where it does not, either answer is right. `firstHit(i, j)` is the
// reference's first hit along the ray through (i, j) (NaN: none).
bool stableWithinHalfAPixel(const std::function<double(double, double)>& firstHit, int i, int j,
                            bool hit);

// A render's depth against a reference for every pixel of a size x size frame of `camera`.
// `shown` is a tape of F and its gradient (the surface that must be drawn); `firstHit(r)` the
// reference's first hit along r (NaN: none). Left out: pixels whose hit or miss changes
// within half a pixel, and rays whose first hit moves when they turn by 1e-6 (they graze a
// sheet: either answer is right; "grazing"). A render hit the reference lacks, or one nearer
// than the reference's, counts as "touching" where |F| / |grad F| there is at most
// `touchDistance(t)`: the method draws what it cannot separate from the surface.
struct DepthComparison {
  int hits = 0, missed = 0, extra = 0, grazing = 0, touching = 0;
  double worstDepth = 0;  // |depth - reference| over pixels both hit
};
DepthComparison compareDepth(const DepthMap& depth, const Camera& camera, int size,
                             PointEvaluator& shown,
                             const std::function<double(const Ray&)>& firstHit,
                             const std::function<double(double)>& touchDistance);

// Compares `image` with tests/render/reference/<name>.png within the tolerance of
// image.hpp; with ZS_UPDATE_REFERENCE=1 writes the reference instead. On mismatch the
// render is written next to the test binary as <name>.actual.png. "" when it matches.
std::string matchReference(const std::string& name, const Image& image);

std::string sourceDir();

// The three tracing methods, for suites that run over every one (INSTANTIATE_TEST_SUITE_P
// with kEveryMethod and methodName).
inline const std::vector<TracingMethod> kEveryMethod{
    TracingMethod::Sampling, TracingMethod::Bernstein, TracingMethod::Interval};
inline constexpr auto methodName = [](const auto& info) {
  return std::string(tracingMethodName(info.param));
};

// The world point of pixel (i, j)'s hit, from the frame's depth map and the camera it was
// drawn with; none where the pixel's ray hit nothing.
std::optional<Vec3> hitPoint(const Frame& frame, const Camera& camera, int i, int j);
// Every hit's world point.
std::vector<Vec3> hitPoints(const Frame& frame, const Camera& camera);

// Share of pixels whose RGB is within `tolerance` (0..255) of `rgb` (0..1).
double fractionNear(const Image& image, Vec3 rgb, int tolerance = 3);
bool pixelNear(const Image& image, int x, int y, Vec3 rgb, int tolerance = 3);

}  // namespace zs::test
