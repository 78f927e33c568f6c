#pragma once
// The CPU half of zeroset, end to end: takes a Scene, puts out everything the GPU half needs
// (the packed box hierarchy, the parameter values, the shader text validated by glslang)
// with the time each stage took. The one pipeline of every front end (the commands, the
// viewer, the prompt), the tests and the benchmarks; load_surface.hpp hands its result to
// a tracer. No GL here.
#include <array>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "codegen/emit_glsl.hpp"
#include "codegen/emit_ray_polynomial.hpp"
#include "codegen/shader_assembly.hpp"
#include "interval/hierarchy.hpp"
#include "interval/octree.hpp"
#include "scene/invalidation.hpp"
#include "scene/scene.hpp"

namespace zs {

struct StageTimes {
  double parseMs = 0, octreeMs = 0, codegenMs = 0, validateMs = 0;
};

struct PreparedSurface {
  Formula formula;
  // Each surface's function in formula.graph (one entry per [[surface]]; their product is
  // formula.root when there are several).
  std::vector<NodeId> surfaceRoots;
  std::array<NodeId, 3> gradient{};
  std::vector<double> params;  // graph.params() order
  Octree octree;
  BoxHierarchy hierarchy;
  TracingMethod method = TracingMethod::Interval;  // resolved: never Auto
  std::string methodWarning;  // why the method asked for could not be used ("" if it was)
  GlslFormula glsl;
  std::optional<RayPolynomialGlsl> rayPolynomial;  // Bernstein only
  // highlights.singular: the certified singular points drawn, and what to tell the user (a
  // search that failed or left regions uncertified); empty when the highlight is off.
  std::vector<std::array<double, 3>> singularPoints;
  std::string singularNote;
  // What to tell the user about the function traced ("" if nothing): F does not depend on
  // x, y, z (nothing to draw, or F = 0 everywhere).
  std::string formulaNote;
  std::string vertexShader, fragmentShader;
  StageTimes times;

  std::vector<float> paramsAsFloats() const { return {params.begin(), params.end()}; }
};

// The box the octree subdivides (the domain's bounding box) and, for a sphere domain, the
// ball that clips it.
Box toBox(const Domain& domain);
std::optional<Ball> toBall(const Domain& domain);

// The method `asked` resolves to for this formula: Bernstein for a polynomial of degree up
// to `maxBernsteinDegree` (Auto or Bernstein asked), interval arithmetic otherwise; sampling
// and interval when asked for. `warning` explains a fallback from an explicit "bernstein".
TracingMethod resolveMethod(TracingMethod asked, const Formula& formula, std::string& warning,
                            int maxBernsteinDegree = kMaxBernsteinDegree);

// The box hierarchy the tracer walks: the octree's leaves, cut for the exact methods
// (Bernstein, interval) to the surface's bounds (interval/surface_bounds.hpp), which they clip
// every ray to; the thesis' sampling method keeps the octree's own boxes, so its tables
// stay reproducible.
BoxHierarchy tracingHierarchy(const Formula& formula, std::span<const double> params,
                              const Octree& octree, TracingMethod method);

struct PrepareOptions {
  bool validate = true;  // run glslang on the assembled shaders (not in the web build)
  // GLSL ES 3.00 for WebGL2: no double there, so Bernstein expands in double-float up to
  // kWebBernsteinMaxDegree and polynomials of higher degree take the interval method.
  ShaderDialect dialect = ShaderDialect::Gl330;
  // With highlights.singular on: mark these points instead of searching for singular points.
  std::optional<std::vector<std::array<double, 3>>> markedPoints;
  // Bernstein for a polynomial of any degree when "bernstein" is asked for, above
  // kMaxBernsteinDegree too (which measures where that limit lies); the commands never set it.
  bool bernsteinAboveLimit = false;
};

// For callers that validate elsewhere or not at all (the driver compiles the shader anyway).
inline const PrepareOptions kWithoutGlslang = [] {
  PrepareOptions o;
  o.validate = false;
  return o;
}();

// The highest degree the exact Bernstein method is used for with these options.
int maxBernsteinDegree(const PrepareOptions& options);

// Error text is ready to print (caret formatting, octree budget messages, or an internal
// shader error that names itself a bug). prepareGeometry, then prepareShader.
std::variant<PreparedSurface, std::string> prepareSurface(const Scene& scene,
                                                          const PrepareOptions& options = {});

// The two halves, so that an edit redoes only what it invalidates (scene/invalidation.hpp).
// Geometry: parse, the method, the octree and the box hierarchy (everything but the shaders).
std::variant<PreparedSurface, std::string> prepareGeometry(const Scene& scene,
                                                           const PrepareOptions& options = {});
// Shader: the generated GLSL of a surface whose geometry is made (with the marked singular
// points), validated by glslang where the options say. "" or the error text.
std::string prepareShader(const Scene& scene, PreparedSurface& surface,
                          const PrepareOptions& options = {});

// `base` (prepared from an earlier scene) brought to `scene`, redoing only the stages `what`
// names: Geometry and Shader as above, nothing for Frame or Variant (a copy of base).
std::variant<PreparedSurface, std::string> updateSurface(const PreparedSurface& base,
                                                         const Scene& scene, Invalidation what,
                                                         const PrepareOptions& options = {});

}  // namespace zs
