#include "pipeline/pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <limits>

#include "codegen/emit_hessian.hpp"
#if ZS_HAVE_GLSLANG
#include "codegen/glsl_validation.hpp"
#endif
#include "codegen/shader_assembly.hpp"
#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "interval/hierarchy_builder.hpp"
#include "interval/surface_bounds.hpp"
#include "parser/parser.hpp"
#include "scene/scene_io.hpp"
#include "singular/singular.hpp"

namespace zs {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// A formula free of x, y and z has no surface (or, where it is 0, is a surface everywhere):
// every method draws that faithfully, and the user is told why the picture looks as it does.
std::string constantFormulaNote(const Formula& formula, std::span<const double> params) {
  if (!formula.graph.isSpatiallyConstant(formula.root)) return {};
  PointEvaluator eval(compileTape(formula.graph, {formula.root}));
  const double value = eval.eval1(0, 0, 0, params);
  char text[200];
  if (value == 0) {
    std::snprintf(text, sizeof text,
                  "note: F does not depend on x, y or z and is 0: every point of the domain is "
                  "on the surface\n");
  } else {
    std::snprintf(text, sizeof text,
                  "note: F does not depend on x, y or z (F = %.6g everywhere): there is no "
                  "surface to draw\n",
                  value);
  }
  return text;
}

}  // namespace

Box toBox(const Domain& domain) {
  const Domain box = boundingBox(domain);
  return Box{box.min, box.max};
}

std::optional<Ball> toBall(const Domain& domain) {
  if (domain.shape != DomainShape::Sphere) return std::nullopt;
  return Ball{domain.center, domain.radius};
}

TracingMethod resolveMethod(TracingMethod asked, const Formula& formula, std::string& warning,
                            int maxBernsteinDegree) {
  warning.clear();
  if (asked == TracingMethod::Sampling || asked == TracingMethod::Interval) return asked;
  const std::optional<int> degree = rayPolynomialDegree(formula.graph, formula.root);
  if (degree && *degree <= maxBernsteinDegree) return TracingMethod::Bernstein;
  if (degree && asked == TracingMethod::Bernstein) {
    warning = "warning: degree " + std::to_string(*degree) + " is above " +
              std::to_string(maxBernsteinDegree) +
              ", the highest the exact Bernstein method compiles for (its shader grows as the "
              "degree squared); using interval arithmetic (tracing.method = \"interval\")\n";
  } else if (asked == TracingMethod::Bernstein) {
    warning =
        "warning: tracing.method = \"bernstein\" needs a polynomial in x, y, z; this "
        "formula is not one, so it is traced with interval arithmetic "
        "(tracing.method = \"interval\")\n";
  }
  return TracingMethod::Interval;
}

namespace {

// highlights.singular: the certified singular points of the scene's domain (src/singular),
// with a budget that keeps a surface whose singular set is a curve from stalling the build.
void findMarkedPoints(const Scene& scene, PreparedSurface& s) {
  SingularSettings settings;
  settings.maxDepth = 12;
  settings.boxBudget = 500'000;
  auto found =
      findSingularPoints(s.formula, s.params, toBox(scene.domain), toBall(scene.domain), settings);
  if (auto* err = std::get_if<std::string>(&found)) {
    s.singularNote = "note: no singular points marked: " + *err + "\n";
    return;
  }
  const SingularResult& r = std::get<SingularResult>(found);
  for (const SingularPoint& p : r.points) s.singularPoints.push_back(p.point);
  if (!r.uncertified.empty())
    s.singularNote = "note: " + std::to_string(s.singularPoints.size()) +
                     " certified singular points marked; some regions could not be certified "
                     "(zeroset singular lists them)\n";
}

// The surfaces block: each surface's function (`roots`, in the product's graph) with its
// materials, and the intersection highlight.
std::string surfacesBlock(const Scene& scene, Graph& graph, const std::vector<NodeId>& roots) {
  std::vector<SurfaceLook> looks;
  const double ambient = scene.render.lights.ambient;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const Materials m = surfaceAt(scene, i).materials;
    looks.push_back({m.front.color, m.back.color, phongWeights(m.front, ambient),
                     phongWeights(m.back, ambient)});
  }
  const Highlight& h = scene.render.intersection;
  return emitSurfacesGlsl(graph, roots, looks, {h.enabled, h.threshold, h.color});
}

}  // namespace

BoxHierarchy tracingHierarchy(const Formula& formula, std::span<const double> params,
                              const Octree& octree, TracingMethod method) {
  if (method == TracingMethod::Sampling) return buildBoxHierarchy(octree);
  const Box bounds = surfaceBounds(formula, params, octree.domain, octree.ball);
  return buildBoxHierarchy(octree, &bounds);
}

int maxBernsteinDegree(const PrepareOptions& options) {
  return options.dialect == ShaderDialect::Es300 ? kWebBernsteinMaxDegree : kMaxBernsteinDegree;
}

std::variant<PreparedSurface, std::string> prepareGeometry(const Scene& scene,
                                                           const PrepareOptions& options) {
  PreparedSurface s;
  auto t = std::chrono::steady_clock::now();
  std::size_t failedSurface = 0;
  ParseResult parsed = parseSceneFormula(scene, &failedSurface, &s.surfaceRoots);
  if (auto* err = std::get_if<ParseError>(&parsed))
    return formatSceneFormulaError(scene, failedSurface, *err);
  if (surfaceCount(scene) > 1 && scene.render.mode == RenderMode::Volume)
    return "error: render.mode = \"volume\" draws the field of one function, and this scene "
           "has " +
           std::to_string(surfaceCount(scene)) +
           " surfaces\n"
           "hint: keep one [[surface]], or draw them as surfaces (render.mode = \"surface\")\n";
  s.formula = std::get<Formula>(std::move(parsed));
  s.gradient = gradient(s.formula.graph, s.formula.root);
  s.params = paramValues(scene, s.formula.graph);
  s.formulaNote = constantFormulaNote(s.formula, s.params);
  s.times.parseMs = msSince(t);

  t = std::chrono::steady_clock::now();
  OctreeResult tree =
      buildOctree(s.formula, s.params, toBox(scene.domain), scene.octree, toBall(scene.domain));
  if (auto* err = std::get_if<OctreeError>(&tree)) return "error: " + err->message + "\n";
  s.octree = std::get<Octree>(std::move(tree));
  // Above the limit only where "bernstein" is asked for: Auto keeps the limit either way.
  const bool anyDegree =
      options.bernsteinAboveLimit && scene.render.tracing.method == TracingMethod::Bernstein;
  s.method =
      resolveMethod(scene.render.tracing.method, s.formula, s.methodWarning,
                    anyDegree ? std::numeric_limits<int>::max() : maxBernsteinDegree(options));
  // A volume finds no roots; it skips the stretches of its rays where F is proven far from
  // the level (raytrace_volume.frag.glsl): by the control points of the ray polynomial for a
  // polynomial within the Bernstein method's degree limit, else by the interval method's
  // affine form. So it is one of those programs, whatever tracing.method says.
  if (scene.render.mode == RenderMode::Volume) {
    std::string unused;
    s.method = resolveMethod(TracingMethod::Auto, s.formula, unused, maxBernsteinDegree(options));
    s.methodWarning.clear();
  }
  s.hierarchy = tracingHierarchy(s.formula, s.params, s.octree, s.method);
  s.times.octreeMs = msSince(t);
  return s;
}

std::string prepareShader(const Scene& scene, PreparedSurface& s, const PrepareOptions& options) {
  auto t = std::chrono::steady_clock::now();
  s.singularPoints.clear();
  s.singularNote.clear();
  s.rayPolynomial.reset();
  s.glsl = emitFormulaGlsl(s.formula.graph, s.formula.root, s.gradient);
  // Second derivatives only for the colorings that show curvature (docs/curvature.md).
  if (needsCurvature(scene.render.shading.color))
    s.glsl.source += emitHessianGlsl(s.formula.graph, s.gradient);
  if (const Contours& contours = scene.render.shading.contours; contours.enabled) {
    ParseResult function = parseFormula(contours.function);
    if (auto* err = std::get_if<ParseError>(&function))
      return "shading.contours.function: " + formatError(contours.function, *err);
    const std::string block = emitContourGlsl(std::get<Formula>(function));
    if (block.empty())
      return "shading.contours.function: " + contours.function +
             " has parameters; it may use only x, y, z and constants\n";
    s.glsl.source += block;
  }
  if (s.surfaceRoots.size() > 1)
    s.glsl.source += surfacesBlock(scene, s.formula.graph, s.surfaceRoots);
  std::string markers;
  if (scene.render.singular.enabled) {
    if (options.markedPoints)
      s.singularPoints = *options.markedPoints;
    else
      findMarkedPoints(scene, s);
    markers =
        markerBlock(s.singularPoints, scene.render.singular.threshold, scene.render.singular.color);
  }
  const ShaderDialect dialect = options.dialect;
  if (s.method == TracingMethod::Bernstein) {
    s.rayPolynomial =
        emitRayPolynomialGlsl(s.formula.graph, s.formula.root, dialect == ShaderDialect::Gl330);
    s.fragmentShader = assembleFragmentShader(s.glsl, *s.rayPolynomial, markers, dialect);
  } else if (s.method == TracingMethod::Interval) {
    s.fragmentShader = assembleFragmentShader(
        s.glsl, emitIntervalGlsl(s.formula.graph, s.formula.root), markers, dialect);
  } else {
    s.fragmentShader = assembleFragmentShader(s.glsl, markers, dialect);
  }
  s.vertexShader = vertexShaderSource(dialect);
  s.times.codegenMs = msSince(t);
  s.times.validateMs = 0;

#if ZS_HAVE_GLSLANG
  if (options.validate) {
    t = std::chrono::steady_clock::now();
    const ValidationResult vert = validateGlsl(s.vertexShader, Stage::Vertex);
    if (!vert.ok) return formatInternalShaderError("vertex shader", vert);
    const ValidationResult frag = validateGlsl(s.fragmentShader, Stage::Fragment);
    if (!frag.ok) return formatInternalShaderError("fragment shader for " + scene.formula, frag);
    s.times.validateMs = msSince(t);
  }
#endif  // the web build has no glslang: WebGL2 compiles the shaders and reports their errors
  return {};
}

std::variant<PreparedSurface, std::string> prepareSurface(const Scene& scene,
                                                          const PrepareOptions& options) {
  auto geometry = prepareGeometry(scene, options);
  if (auto* err = std::get_if<std::string>(&geometry)) return *err;
  PreparedSurface& s = std::get<PreparedSurface>(geometry);
  if (std::string err = prepareShader(scene, s, options); !err.empty()) return err;
  return geometry;
}

std::variant<PreparedSurface, std::string> updateSurface(const PreparedSurface& base,
                                                         const Scene& scene, Invalidation what,
                                                         const PrepareOptions& options) {
  if (!(what & invalidates::Geometry)) {
    PreparedSurface s = base;
    s.times = {};
    if (what & invalidates::Shader) {
      if (std::string err = prepareShader(scene, s, options); !err.empty()) return err;
    }
    return s;
  }
  auto geometry = prepareGeometry(scene, options);
  if (auto* err = std::get_if<std::string>(&geometry)) return *err;
  PreparedSurface& s = std::get<PreparedSurface>(geometry);
  if (what & invalidates::Shader) {
    if (std::string err = prepareShader(scene, s, options); !err.empty()) return err;
    return geometry;
  }
  // The same formula with new parameter values or another octree: the shader text stays
  // (parameters are uniforms), and so do the points it marks.
  s.glsl = base.glsl;
  s.rayPolynomial = base.rayPolynomial;
  s.singularPoints = base.singularPoints;
  s.singularNote = base.singularNote;
  s.vertexShader = base.vertexShader;
  s.fragmentShader = base.fragmentShader;
  return geometry;
}

}  // namespace zs
