#include "render_support.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <variant>

#include "codegen/emit_glsl.hpp"
#include "codegen/emit_hessian.hpp"
#include "expr/derivative.hpp"
#include "codegen/shader_assembly.hpp"
#include "interval/octree.hpp"
#include "interval/sphere_builder.hpp"
#include "parser/parser.hpp"

namespace zs::test {

GlContext* context(Backend backend, std::string& error) {
  static std::map<Backend, ContextResult> contexts;
  auto it = contexts.find(backend);
  if (it == contexts.end()) it = contexts.emplace(backend, createHeadlessContext(backend)).first;
  error = it->second.error;
  GlContext* ctx = it->second.context.get();
  if (ctx && !ctx->makeCurrent()) {
    error = ctx->lastError();
    return nullptr;
  }
  return ctx;
}

std::unique_ptr<RayTracer> makeTracer(const SurfaceSpec& spec, std::string& error) {
  ParseResult parsed = parseFormula(spec.formula);
  if (auto* e = std::get_if<ParseError>(&parsed)) {
    error = formatError(spec.formula, *e);
    return nullptr;
  }
  Formula formula = std::get<Formula>(std::move(parsed));
  Box box{spec.domain.min, spec.domain.max};
  OctreeSettings octree;
  octree.level = spec.octreeLevel;
  octree.criteria = spec.criteria;
  OctreeResult tree = buildOctree(formula, spec.params, box, octree);
  if (auto* e = std::get_if<OctreeError>(&tree)) {
    error = e->message;
    return nullptr;
  }
  const std::vector<float> packed = buildSphereHierarchy(std::get<Octree>(tree)).packed();
  GlslFormula glsl = emitFormulaGlsl(formula);
  if (spec.hessian) glsl.source += emitHessianGlsl(formula.graph, gradient(formula.graph, formula.root));
  // Auto: the method the app would pick (app/pipeline.cpp resolveMethod), without its
  // warnings. Bernstein is taken for any polynomial, above the degree limit too, so tests
  // can measure where that limit lies.
  const std::optional<int> degree = rayPolynomialDegree(formula.graph, formula.root);
  const bool bernstein = degree && (spec.method == TracingMethod::Bernstein ||
                                    (spec.method == TracingMethod::Auto && *degree <= kMaxBernsteinDegree));
  const std::string markers = markerBlock(spec.markers, spec.markerRadius, spec.markerColor);
  const std::string fragment =
      bernstein ? assembleFragmentShader(glsl, *emitRayPolynomialGlsl(formula.graph, formula.root),
                                         markers)
                : assembleFragmentShader(glsl, markers);
  auto tracer = std::make_unique<RayTracer>();
  if (!tracer->build(vertexShaderSource(), fragment, error)) return nullptr;
  if (error = tracer->setHierarchy(packed); !error.empty()) return nullptr;

  std::vector<float> params(spec.params.begin(), spec.params.end());
  tracer->setParams(params);
  return tracer;
}

std::pair<double, double> rayInBox(const Ray& r, const Domain& box) {
  double t0 = 0, t1 = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double a = (box.min[k] - r.origin[k]) / r.direction[k];
    const double b = (box.max[k] - r.origin[k]) / r.direction[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return {t0, t1};
}

RenderSettings testSettings(Vec3 eye) {
  RenderSettings s;
  s.camera.eye = eye;
  return s;
}

std::string sourceDir() {
  const char* env = std::getenv("ZS_SOURCE_DIR");
  return env ? env : ZS_RENDER_TEST_SOURCE_DIR;
}

std::string matchReference(const std::string& name, const Image& image) {
  const std::string path = sourceDir() + "/tests/render/reference/" + name + ".png";
  const char* update = std::getenv("ZS_UPDATE_REFERENCE");
  if (update && std::string(update) == "1") return writePng(path, image);
  Image reference;
  if (std::string error = readPng(path, reference); !error.empty())
    return error + " (run with ZS_UPDATE_REFERENCE=1 to create it)";
  const ImageDiff diff = compareImages(image, reference);
  if (withinTolerance(diff)) return {};
  writePng(name + ".actual.png", image);
  return name + ": differs from " + path + ": " + std::to_string(diff.fractionOver * 100) +
         "% of pixels over threshold, rmse " + std::to_string(diff.rmse) +
         " (render written to " + name + ".actual.png)";
}

bool pixelNear(const Image& image, int x, int y, Vec3 rgb, int tolerance) {
  const std::uint8_t* p = image.pixel(x, y);
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(p[c]) - int(std::lround(rgb[c] * 255))) > tolerance) return false;
  return true;
}

double fractionNear(const Image& image, Vec3 rgb, int tolerance) {
  std::size_t near = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) near += pixelNear(image, x, y, rgb, tolerance);
  return double(near) / (double(image.width) * image.height);
}

}  // namespace zs::test
