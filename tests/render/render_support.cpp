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
  const std::array<NodeId, 3> grad = gradient(formula.graph, formula.root);
  GlslFormula glsl = emitFormulaGlsl(formula.graph, formula.root, grad);
  if (spec.hessian) glsl.source += emitHessianGlsl(formula.graph, grad);
  // Auto: the method the app would pick (app/pipeline.cpp resolveMethod), without its
  // warnings: Bernstein for polynomials up to the degree limit, interval otherwise. Bernstein
  // is taken for any polynomial, above the degree limit too, so tests can measure where that
  // limit lies.
  const std::optional<int> degree = rayPolynomialDegree(formula.graph, formula.root);
  const bool bernstein = degree && (spec.method == TracingMethod::Bernstein ||
                                    (spec.method == TracingMethod::Auto && *degree <= kMaxBernsteinDegree));
  const std::string markers = markerBlock(spec.markers, spec.markerRadius, spec.markerColor);
  const bool interval = !bernstein && spec.method != TracingMethod::Sampling;
  std::string fragment;
  if (bernstein) {
    fragment = assembleFragmentShader(glsl, *emitRayPolynomialGlsl(formula.graph, formula.root),
                                      markers);
  } else if (interval) {
    fragment = assembleFragmentShader(glsl, emitIntervalGlsl(formula.graph, formula.root),
                                      markers);
  } else {
    fragment = assembleFragmentShader(glsl, markers);
  }
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

double sampledFirstHit(PointEvaluator& f, const Ray& r, double t0, double t1, int samples,
                       std::span<const double> params) {
  double out[4];
  auto at = [&](double t) {  // (f, f')
    f.eval(r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
           r.origin[2] + t * r.direction[2], params, out);
    return std::pair{out[0], out[1] * r.direction[0] + out[2] * r.direction[1] +
                                 out[3] * r.direction[2]};
  };
  auto bisect = [](auto&& g, double lo, double hi) {  // a sign change of g on [lo, hi]
    const bool negLo = g(lo) < 0;
    for (int i = 0; i < 60; ++i) {
      const double m = 0.5 * (lo + hi);
      (g(m) < 0) == negLo ? lo = m : hi = m;
    }
    return 0.5 * (lo + hi);
  };
  auto value = [&](double t) { return at(t).first; };
  auto slope = [&](double t) { return at(t).second; };
  double a = t0;
  auto [fa, ga] = at(a);
  for (int k = 1; k <= samples; ++k) {
    const double b = t0 + (t1 - t0) * k / samples;
    const auto [fb, gb] = at(b);
    if (fa == 0) return a;
    if ((fa < 0) != (fb < 0)) return bisect(value, a, b);
    if ((ga < 0) != (gb < 0)) {  // an extremum inside: does f reach the other sign there?
      const double e = bisect(slope, a, b);
      if ((value(e) < 0) != (fa < 0)) return bisect(value, a, e);
    }
    a = b, fa = fb, ga = gb;
  }
  return NAN;
}

bool stableWithinHalfAPixel(const std::function<double(double, double)>& firstHit, int i,
                            int j, bool hit) {
  for (auto [di, dj] : {std::pair{-0.5, 0.0}, {0.5, 0.0}, {0.0, -0.5}, {0.0, 0.5}})
    if (std::isnan(firstHit(i + di, j + dj)) == hit) return false;
  return true;
}

DepthComparison compareDepth(const DepthMap& depth, const Camera& camera, int size,
                             PointEvaluator& shown,
                             const std::function<double(const Ray&)>& firstHit,
                             const std::function<double(double)>& touchDistance) {
  DepthComparison m;
  // The ray through (i, j), its direction turned by (turnX, turnY) radians about the
  // camera's vertical and horizontal axes.
  const CameraBasis basis = cameraBasis(camera);
  auto reference = [&](double i, double j, double turnX = 0, double turnY = 0) {
    Ray r = primaryRay(camera, size, size, i, j);
    for (int k = 0; k < 3; ++k) r.direction[k] += turnX * basis.right[k] + turnY * basis.up[k];
    return firstHit(r);
  };
  auto touching = [&](double t, int i, int j) {
    const Ray r = primaryRay(camera, size, size, i, j);
    double v[4];
    shown.eval(r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
               r.origin[2] + t * r.direction[2], {}, v);
    return std::abs(v[0]) <= touchDistance(t) * std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
  };
  auto same = [](double a, double b) {
    return std::isnan(a) ? std::isnan(b) : !std::isnan(b) && std::abs(a - b) <= 1e-3;
  };
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double want = reference(i, j);
      const bool hit = !std::isnan(want);
      if (!stableWithinHalfAPixel([&](double x, double y) { return reference(x, y); }, i, j, hit))
        continue;
      // The shader builds its rays in float: directions within ~1e-7 of these.
      bool grazing = false;
      for (auto [tx, ty] : {std::pair{1e-6, 0.0}, {-1e-6, 0.0}, {0.0, 1e-6}, {0.0, -1e-6}})
        grazing = grazing || !same(reference(i, j, tx, ty), want);
      if (grazing) {
        ++m.grazing;
        continue;
      }
      const float got = depth.at(i, j);
      if (std::isfinite(got) && (!hit || got < want - 1e-3) && touching(got, i, j)) {
        ++m.touching;
        continue;
      }
      m.hits += hit;
      m.missed += hit && !std::isfinite(got);
      m.extra += !hit && std::isfinite(got);
      if (hit && std::isfinite(got)) m.worstDepth = std::max(m.worstDepth, std::abs(got - want));
    }
  }
  return m;
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
