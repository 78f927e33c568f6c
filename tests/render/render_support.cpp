#include "render_support.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <variant>

#include "parser/parser.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"

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
  // The scene the spec describes, traced by the app's own pipeline (pipeline/pipeline.hpp).
  Scene scene;
  scene.formula = spec.formula;
  scene.domain = spec.domain;
  scene.octree.level = spec.octreeLevel;
  scene.octree.criteria = spec.criteria;
  scene.render.tracing.method = spec.method;
  // The parameters come by position: their names are the formula's, in the graph's order.
  ParseResult parsed = parseFormula(spec.formula);
  if (auto* e = std::get_if<ParseError>(&parsed)) {
    error = formatError(spec.formula, *e);
    return nullptr;
  }
  const std::vector<std::string>& names = std::get<Formula>(parsed).graph.params();
  for (std::size_t i = 0; i < names.size() && i < spec.params.size(); ++i)
    scene.params.emplace_back(names[i], spec.params[i]);
  // The Hessian is emitted for the colorings that show curvature; the coloring itself is
  // the render settings' (a variant of the same program).
  if (spec.hessian) scene.render.shading.color = ColorMode::Gauss;
  scene.render.shading.contours = spec.contours;
  scene.moreSurfaces = spec.moreSurfaces;
  if (spec.intersection) scene.render.intersection = *spec.intersection;
  PrepareOptions options;
  options.validate = false;  // the driver compiles it anyway; glslang has tests of its own
  options.bernsteinAboveLimit = spec.method == TracingMethod::Bernstein;
  if (!spec.markers.empty()) {
    scene.render.singular.enabled = true;
    scene.render.singular.threshold = spec.markerRadius;
    scene.render.singular.color = spec.markerColor;
    options.markedPoints = spec.markers;
  }
  auto prepared = prepareSurface(scene, options);
  if (auto* message = std::get_if<std::string>(&prepared)) {
    error = *message;
    return nullptr;
  }
  auto tracer = spec.frameStorage ? std::make_unique<RayTracer>(*spec.frameStorage)
                                  : std::make_unique<RayTracer>();
  if (error = loadSurface(*tracer, std::get<PreparedSurface>(prepared), scene.render);
      !error.empty())
    return nullptr;
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
  return sampledFirstHit(
      [&](double x, double y, double z, double out[4]) {
        f.eval(x, y, z, params, {out, 4});
      },
      r, t0, t1, samples);
}

double sampledFirstHit(const FieldWithGradient& f, const Ray& r, double t0, double t1,
                       int samples) {
  double out[4];
  auto at = [&](double t) {  // (f, f')
    f(r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
      r.origin[2] + t * r.direction[2], out);
    return std::pair{out[0],
                     out[1] * r.direction[0] + out[2] * r.direction[1] + out[3] * r.direction[2]};
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

bool stableWithinHalfAPixel(const std::function<double(double, double)>& firstHit, int i, int j,
                            bool hit) {
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
         "% of pixels over threshold, rmse " + std::to_string(diff.rmse) + " (render written to " +
         name + ".actual.png)";
}

bool pixelNear(const Image& image, int x, int y, Vec3 rgb, int tolerance) {
  const std::uint8_t* p = image.pixel(x, y);
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(p[c]) - int(std::lround(rgb[c] * 255))) > tolerance) return false;
  return true;
}

std::optional<Vec3> hitPoint(const Frame& frame, const Camera& camera, int i, int j) {
  const float t = frame.depth.at(i, j);
  if (!std::isfinite(t)) return std::nullopt;
  const Ray ray = primaryRay(camera, frame.depth.width, frame.depth.height, i, j);
  return Vec3{ray.origin[0] + t * ray.direction[0], ray.origin[1] + t * ray.direction[1],
              ray.origin[2] + t * ray.direction[2]};
}

std::vector<Vec3> hitPoints(const Frame& frame, const Camera& camera) {
  std::vector<Vec3> points;
  for (int j = 0; j < frame.depth.height; ++j)
    for (int i = 0; i < frame.depth.width; ++i)
      if (const std::optional<Vec3> p = hitPoint(frame, camera, i, j)) points.push_back(*p);
  return points;
}

double fractionNear(const Image& image, Vec3 rgb, int tolerance) {
  std::size_t near = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) near += pixelNear(image, x, y, rgb, tolerance);
  return double(near) / (double(image.width) * image.height);
}

}  // namespace zs::test
