#include "probe/probe.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "interval/tape_eval.hpp"
#include "scene/scene_io.hpp"

namespace zs {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Interval evaluations one ray may spend before the probe gives up.
constexpr int kBudget = 2'000'000;

Vec3 at(const Ray& r, double t) {
  return {r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
          r.origin[2] + t * r.direction[2]};
}

// The ray's parameters inside the domain; empty (lo > hi) when it misses.
std::pair<double, double> domainSpan(const Domain& domain, const Ray& r) {
  const Domain box = boundingBox(domain);
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double inv = 1.0 / r.direction[a];
    double t0 = (box.min[a] - r.origin[a]) * inv, t1 = (box.max[a] - r.origin[a]) * inv;
    if (std::isnan(t0) || std::isnan(t1)) {  // parallel to the slab and on its edge
      t0 = -std::numeric_limits<double>::infinity();
      t1 = std::numeric_limits<double>::infinity();
    }
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
  }
  if (domain.shape == DomainShape::Sphere) {
    Vec3 oc;
    for (int a = 0; a < 3; ++a) oc[a] = r.origin[a] - domain.center[a];
    const double b = oc[0] * r.direction[0] + oc[1] * r.direction[1] + oc[2] * r.direction[2];
    const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - domain.radius * domain.radius;
    const double disc = b * b - c;
    if (disc < 0) return {1, 0};
    lo = std::max(lo, -b - std::sqrt(disc));
    hi = std::min(hi, -b + std::sqrt(disc));
  }
  return {lo, hi};
}

double diagonal(const Domain& domain) {
  const Domain box = boundingBox(domain);
  return std::hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]);
}

}  // namespace

namespace {

// The tapes the probe runs, compiled from F with its gradient and Hessian added.
struct Tapes {
  Tape value, slope, all;
};

Tapes compileProbeTapes(const Formula& formula) {
  Graph g = formula.graph;
  const NodeId f = formula.root;
  const std::array<NodeId, 3> grad = gradient(g, f);
  std::vector<NodeId> outputs{f, grad[0], grad[1], grad[2]};
  for (int i = 0; i < 3; ++i) {
    const std::array<NodeId, 3> row = gradient(g, grad[std::size_t(i)]);
    outputs.insert(outputs.end(), row.begin(), row.end());
  }
  // F alone; F and grad F, for the slope along the ray on the last, smallest segments; and
  // F, grad F and the Hessian at the point found.
  return {compileTape(g, {f}), compileTape(g, {f, grad[0], grad[1], grad[2]}),
          compileTape(g, outputs)};
}

}  // namespace

struct SurfaceProbe::Evaluators {
  explicit Evaluators(Tapes t)
      : tapes(std::move(t)),
        intervals(tapes.value),
        values(tapes.value),
        slopes(tapes.slope),
        all(tapes.all) {}
  Tapes tapes;  // before the evaluators: the interval ones hold references into it
  IntervalEvaluator intervals;
  PointEvaluator values;
  IntervalEvaluator slopes;
  PointEvaluator all;
};

SurfaceProbe::SurfaceProbe(const Formula& formula)
    : eval_(std::make_unique<Evaluators>(compileProbeTapes(formula))) {}

SurfaceProbe::~SurfaceProbe() = default;

std::variant<ProbeResult, std::string> SurfaceProbe::ray(std::span<const double> params,
                                                         const Domain& domain, const Ray& ray,
                                                         std::span<const ClipPlane> clip) {
  IntervalEvaluator& intervals = eval_->intervals;
  PointEvaluator& values = eval_->values;
  IntervalEvaluator& slopes = eval_->slopes;
  std::array<Interval, 4> withGradient;
  auto valueAt = [&](double t) {
    const Vec3 p = at(ray, t);
    return values.eval1(p[0], p[1], p[2], params);
  };

  ProbeResult result;
  auto [ta, tb] = domainSpan(domain, ray);
  // Each enabled clip plane keeps normal . p <= offset (render/settings.hpp ClipPlane).
  for (const ClipPlane& plane : clip) {
    if (!plane.enabled) continue;
    double nd = 0, no = 0;
    for (int a = 0; a < 3; ++a) {
      nd += plane.normal[a] * ray.direction[a];
      no += plane.normal[a] * ray.origin[a];
    }
    const double room = plane.offset - no;
    if (nd > 0)
      tb = std::min(tb, room / nd);
    else if (nd < 0)
      ta = std::max(ta, room / nd);
    else if (room < 0)
      return result;
  }
  if (!(ta <= tb)) return result;
  // The tracer's tangent tolerance (1e-5 of the domain's diagonal): a stretch that short on
  // which F may still vanish and is bounded is a hit, as on the GPU.
  const double tolerance = 1e-5 * std::max(diagonal(domain), 1e-6);
  std::vector<std::pair<double, double>> stack{{ta, tb}};
  int budget = kBudget;
  double tHit = kNaN;
  while (!stack.empty()) {
    if (--budget < 0) return std::string("the probe ran out of its budget on this ray");
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Vec3 pa = at(ray, a), pb = at(ray, b);
    Box box;
    for (int k = 0; k < 3; ++k) {
      box.min[std::size_t(k)] = std::min(pa[k], pb[k]);
      box.max[std::size_t(k)] = std::max(pa[k], pb[k]);
    }
    const Interval range = intervals.eval1(box, params);
    if (range.isEmpty() || !range.containsZero()) continue;  // no root here, proven
    if (b - a > tolerance) {
      const double m = 0.5 * (a + b);
      stack.push_back({m, b});  // the nearer half is searched first
      stack.push_back({a, m});
      continue;
    }
    if (!std::isfinite(range.lo) || !std::isfinite(range.hi)) continue;  // a pole, no surface
    // Where F is monotone along the segment (its slope d . grad F keeps one sign), the signs
    // at the ends decide: the enclosure alone is too wide near a simple root to tell. Only
    // where the slope may vanish too (a tangency, a root of even multiplicity) is a segment
    // this short that may hold a zero a hit, as on the GPU.
    slopes.eval(box, params, withGradient);
    Interval slope = Interval::point(0);
    for (int k = 0; k < 3; ++k)
      slope = ia::add(slope,
                      ia::mul(withGradient[std::size_t(k + 1)], Interval::point(ray.direction[k])));
    double lo = a, hi = b, flo = valueAt(a), fhi = valueAt(b);
    const bool signChange = std::isfinite(flo) && std::isfinite(fhi) && (flo > 0) != (fhi > 0);
    const bool monotone = !slope.isEmpty() && !slope.containsZero();
    if (monotone && !signChange && flo != 0 && fhi != 0) continue;  // no root, proven
    // A sign change brackets the root: bisect it down to double precision.
    if (signChange && flo != 0) {
      for (int i = 0; i < 80 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++i) {
        const double m = 0.5 * (lo + hi), fm = valueAt(m);
        if (fm == 0) {
          lo = hi = m;
          break;
        }
        if ((fm > 0) == (flo > 0)) {
          lo = m;
          flo = fm;
        } else {
          hi = m;
        }
      }
    }
    if (flo == 0) hi = lo;  // F exactly 0 at the segment's start: that is the root
    tHit = 0.5 * (lo + hi);
    break;
  }
  if (std::isnan(tHit)) return result;

  result.hit = true;
  result.t = tHit;
  result.point = at(ray, tHit);
  std::vector<double> v(eval_->tapes.all.outputs.size());
  eval_->all.eval(result.point[0], result.point[1], result.point[2], params, v);
  result.value = v[0];
  const Vec3 gr{v[1], v[2], v[3]};
  result.gradient = gr;
  double h[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) h[i][j] = v[std::size_t(4 + 3 * i + j)];
  // Symmetrize: the two mixed derivatives are the same function, evaluated apart.
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) h[i][j] = h[j][i] = 0.5 * (h[i][j] + h[j][i]);
  const double g2 = gr[0] * gr[0] + gr[1] * gr[1] + gr[2] * gr[2], gn = std::sqrt(g2);
  if (!(gn > 0)) {
    result.normal = {kNaN, kNaN, kNaN};
    result.gaussian = result.mean = result.k1 = result.k2 = kNaN;
    return result;
  }
  for (int k = 0; k < 3; ++k) result.normal[k] = gr[k] / gn;
  // docs/curvature.md: K = g^T adj(H) g / |g|^4, H = (|g|^2 tr(H) - g^T H g) / (2 |g|^3).
  const double adj[3][3] = {
      {h[1][1] * h[2][2] - h[1][2] * h[2][1], h[0][2] * h[2][1] - h[0][1] * h[2][2],
       h[0][1] * h[1][2] - h[0][2] * h[1][1]},
      {h[1][2] * h[2][0] - h[1][0] * h[2][2], h[0][0] * h[2][2] - h[0][2] * h[2][0],
       h[0][2] * h[1][0] - h[0][0] * h[1][2]},
      {h[1][0] * h[2][1] - h[1][1] * h[2][0], h[0][1] * h[2][0] - h[0][0] * h[2][1],
       h[0][0] * h[1][1] - h[0][1] * h[1][0]}};
  double gAg = 0, gHg = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      gAg += gr[i] * adj[i][j] * gr[j];
      gHg += gr[i] * h[i][j] * gr[j];
    }
  const double trace = h[0][0] + h[1][1] + h[2][2];
  result.gaussian = gAg / (g2 * g2);
  result.mean = (g2 * trace - gHg) / (2 * g2 * gn);
  const double spread = std::sqrt(std::max(result.mean * result.mean - result.gaussian, 0.0));
  result.k1 = result.mean + spread;
  result.k2 = result.mean - spread;
  return result;
}

std::variant<ProbeResult, std::string> SurfaceProbe::pixel(std::span<const double> params,
                                                           const Scene& scene, int width,
                                                           int height, int x, int y) {
  if (width <= 0 || height <= 0 || x < 0 || y < 0 || x >= width || y >= height) {
    return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
           std::to_string(width) + "x" + std::to_string(height) + " picture";
  }
  return ray(params, scene.domain, primaryRay(scene.render.camera, width, height, x, y),
             scene.render.clipPlanes);
}

namespace {

std::vector<std::pair<std::string, double>> functionsOf(const Scene& scene) {
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t i = 0; i < surfaceCount(scene); ++i) {
    const SurfaceEntry surface = surfaceAt(scene, i);
    out.emplace_back(surface.formula, surface.level);
  }
  return out;
}

}  // namespace

SceneProbe::SceneProbe(const Scene& scene) : functions_(functionsOf(scene)) {
  for (std::size_t i = 0; i < surfaceCount(scene); ++i) {
    ParseResult parsed = parseSurfaceFormula(scene, i);
    if (auto* err = std::get_if<ParseError>(&parsed)) {
      error_ = formatSceneFormulaError(scene, i, *err);
      probes_.clear();
      return;
    }
    formulas_.push_back(std::get<Formula>(std::move(parsed)));
  }
  for (const Formula& f : formulas_) probes_.push_back(std::make_unique<SurfaceProbe>(f));
}

SceneProbe::~SceneProbe() = default;

bool SceneProbe::sameSurfaces(const Scene& scene) const {
  return functions_ == functionsOf(scene);
}

std::variant<ProbeResult, std::string> SceneProbe::pixel(const Scene& scene, int width, int height,
                                                         int x, int y) {
  if (!error_.empty()) return error_;
  ProbeResult nearest;
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    auto result =
        probes_[i]->pixel(paramValues(scene, formulas_[i].graph), scene, width, height, x, y);
    if (std::holds_alternative<std::string>(result)) return result;
    const ProbeResult& r = std::get<ProbeResult>(result);
    if (r.hit && (!nearest.hit || r.t < nearest.t)) {
      nearest = r;
      nearest.surface = static_cast<int>(i);
    }
  }
  nearest.surfaces = static_cast<int>(probes_.size());
  return nearest;
}

std::variant<ProbeResult, std::string> probeRay(const Formula& formula,
                                                std::span<const double> params,
                                                const Domain& domain, const Ray& ray) {
  return SurfaceProbe(formula).ray(params, domain, ray);
}

std::variant<ProbeResult, std::string> probePixel(const Formula& formula,
                                                  std::span<const double> params,
                                                  const Scene& scene, int width, int height, int x,
                                                  int y) {
  return SurfaceProbe(formula).pixel(params, scene, width, height, x, y);
}

namespace {

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}
std::string vec(const Vec3& v, const char* sep) {
  return number(v[0]) + sep + number(v[1]) + sep + number(v[2]);
}
std::string jsonNumber(double v) {
  return std::isfinite(v) ? number(v) : "null";
}

}  // namespace

std::string probeText(const ProbeResult& r) {
  if (!r.hit) return "hit: false\n";
  const std::string surface =
      r.surfaces > 1 ? "surface: " + std::to_string(r.surface + 1) + "\n" : "";
  return surface + "point: " + vec(r.point, " ") + "\nF: " + number(r.value) +
         "\ngradient: " + vec(r.gradient, " ") + "\nnormal: " + vec(r.normal, " ") +
         "\nK: " + number(r.gaussian) + "\nH: " + number(r.mean) + "\nk1: " + number(r.k1) +
         "\nk2: " + number(r.k2) + "\n";
}

std::string probeJson(const ProbeResult& r) {
  if (!r.hit) return "{\"hit\": false}\n";
  auto arr = [](const Vec3& v) {
    return "[" + jsonNumber(v[0]) + ", " + jsonNumber(v[1]) + ", " + jsonNumber(v[2]) + "]";
  };
  const std::string surface =
      r.surfaces > 1 ? ", \"surface\": " + std::to_string(r.surface + 1) : "";
  return "{\"hit\": true" + surface + ", \"t\": " + jsonNumber(r.t) +
         ", \"point\": " + arr(r.point) + ", \"F\": " + jsonNumber(r.value) +
         ", \"gradient\": " + arr(r.gradient) + ", \"normal\": " + arr(r.normal) +
         ", \"K\": " + jsonNumber(r.gaussian) + ", \"H\": " + jsonNumber(r.mean) +
         ", \"k1\": " + jsonNumber(r.k1) + ", \"k2\": " + jsonNumber(r.k2) + "}\n";
}

}  // namespace zs
