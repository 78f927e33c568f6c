// zs_reference_compare: a scene's picture as zeroset draws it against an independent
// reference in double precision (not a test: docs/renderer.md quotes what it prints).
//
//   zs_reference_compare SCENE... [--size N] [--box] [--set KEY=VALUE]...
//
// SCENE is a .surf or .jsurf file or a formula. Each is prepared and traced by the app's own
// pipeline at N x N (default 96) with the scene's camera and settings; --box replaces a
// sphere domain by the box of the same half-width (SURFER's clipping radius as a box, which
// leaves the far parts of the surface in the picture). The reference samples f(t) and f'(t)
// in double along each pixel ray (32 D samples) and bisects its first root; where the render
// draws nearer than that, outward-rounded interval arithmetic decides whether F has a root
// within the tangent tolerance (or tracing.epsilon) of the point drawn.
//
// Per scene it prints one line: the reference's hits, and the pixels where the render
//   ghost:  hits nearer than the reference's first root (or where it has none) at a point
//           whose tangent-tolerance box provably holds no root of F;
//   missed: shows nothing, or something deeper, where the reference hits;
//   left out: the reference's answer changes within half a pixel (either answer is right).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "app/load_surface.hpp"
#include "app/pipeline.hpp"
#include "app/scene_args.hpp"
#include "expr/tape.hpp"
#include "codegen/emit_ray_polynomial.hpp"
#include "interval/tape_eval.hpp"
#include "parser/parser.hpp"
#include "render/camera.hpp"

namespace zs {
namespace {

struct Counts {
  int hits = 0, ghost = 0, missed = 0, leftOut = 0;
};

// The part [t0, t1] of the ray inside the domain (box, then ball), in double.
std::pair<double, double> clip(const Ray& r, const Domain& domain) {
  const Domain box = boundingBox(domain);
  double t0 = 0, t1 = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double a = (box.min[k] - r.origin[k]) / r.direction[k];
    const double b = (box.max[k] - r.origin[k]) / r.direction[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (domain.shape == DomainShape::Sphere) {
    double oc[3], b = 0, c = -domain.radius * domain.radius;
    for (int k = 0; k < 3; ++k) {
      oc[k] = r.origin[k] - domain.center[k];
      b += oc[k] * r.direction[k];
      c += oc[k] * oc[k];
    }
    const double disc = b * b - c;
    if (disc < 0) return {1, 0};
    t0 = std::max(t0, -b - std::sqrt(disc));
    t1 = std::min(t1, -b + std::sqrt(disc));
  }
  return {t0, t1};
}

// The box of half-width `reach` about the point at t on r, rounded outward.
Box boxAround(const Ray& r, double t, double reach) {
  Box box;
  for (int k = 0; k < 3; ++k) {
    const double p = r.origin[k] + t * r.direction[k];
    box.min[k] = std::nextafter(p - reach, -INFINITY);
    box.max[k] = std::nextafter(p + reach, INFINITY);
  }
  return box;
}

// The first root of f(t) = F(o + t d) in [t0, t1] in double, or NaN: f and f' = grad F . d
// are sampled `samples` times; the first step where f changes sign, or where f' changes sign
// and f at that extremum has the other sign, holds it, and bisection finds it. Two roots
// closer than a step are found as long as a step holds at most one extremum of f.
double firstHit(PointEvaluator& f, std::span<const double> params, const Ray& r, double t0,
                double t1, int samples) {
  if (!(t0 <= t1)) return NAN;
  double out[4];
  auto at = [&](double t) {
    f.eval(r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
           r.origin[2] + t * r.direction[2], params, out);
    return std::pair{out[0], out[1] * r.direction[0] + out[2] * r.direction[1] +
                                 out[3] * r.direction[2]};
  };
  auto bisect = [](auto&& g, double lo, double hi) {  // a sign change of g on [lo, hi]
    const bool negLo = g(lo) < 0;
    for (int i = 0; i < 64; ++i) {
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
    if ((ga < 0) != (gb < 0)) {
      const double e = bisect(slope, a, b);
      if ((value(e) < 0) != (fa < 0)) return bisect(value, a, e);
    }
    a = b, fa = fb, ga = gb;
  }
  return NAN;
}

int run(int argc, char** argv) {
  int size = 96;
  bool box = false, verbose = false;
  std::vector<std::string> scenes, sets;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc) size = std::atoi(argv[++i]);
    else if (a == "--box") box = true;
    else if (a == "--verbose") verbose = true;
    else if (a == "--set" && i + 1 < argc) sets.push_back(argv[++i]);
    else scenes.push_back(a);
  }
  if (scenes.empty()) {
    std::fprintf(stderr, "usage: zs_reference_compare SCENE... [--size N] [--box] [--set K=V]...\n");
    return 2;
  }
  int failures = 0;
  for (const std::string& path : scenes) {
    std::optional<Scene> loaded = app::loadSceneArgs({path, sets});
    if (!loaded) return 1;
    Scene scene = std::move(*loaded);
    if (box && scene.domain.shape == DomainShape::Sphere) {
      const double r = scene.domain.radius;
      scene.domain.shape = DomainShape::Box;
      for (int k = 0; k < 3; ++k) {
        scene.domain.min[k] = scene.domain.center[k] - r;
        scene.domain.max[k] = scene.domain.center[k] + r;
      }
    }
    scene.render.samples = 1;  // the depth of the pixel's centre ray
    auto prepared = app::prepareSurface(scene, false);
    if (auto* e = std::get_if<std::string>(&prepared)) {
      std::fprintf(stderr, "%s: %s", path.c_str(), e->c_str());
      return 1;
    }
    const app::PreparedSurface& surface = std::get<app::PreparedSurface>(prepared);
    app::HeadlessTracer gl = app::openHeadlessTracer(Backend::Egl, surface);
    if (!gl.tracer) return 1;
    const Frame frame = gl.tracer->render(scene.render, scene.domain, size, size);
    if (!frame.error.empty()) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), frame.error.c_str());
      return 1;
    }

    const Formula& formula = surface.formula;
    const Tape tape = compileTape(formula.graph, {formula.root});
    const Tape withGradient = compileTape(
        formula.graph, {formula.root, surface.gradient[0], surface.gradient[1], surface.gradient[2]});
    const int samples = 32 * std::max(rayPolynomialDegree(formula.graph, formula.root).value_or(8), 2);
    const Domain bb = boundingBox(scene.domain);
    double diagonal = 0;
    for (int k = 0; k < 3; ++k) diagonal += std::pow(bb.max[k] - bb.min[k], 2);
    const double tolerance = 1e-5 * std::sqrt(diagonal);  // the tracer's tangent tolerance
    const double depthSlack = std::max(10 * scene.render.tracing.epsilon, 1e-4 * std::sqrt(diagonal));

    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<Counts> perThread(threads);
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < threads; ++w) {
      pool.emplace_back([&, w] {
        IntervalEvaluator eval(tape);
        PointEvaluator point(withGradient);
        Counts& c = perThread[w];
        auto reference = [&](double i, double j) {
          const Ray r = primaryRay(scene.render.camera, size, size, i, j);
          const auto [t0, t1] = clip(r, scene.domain);
          return firstHit(point, surface.params, r, t0, t1, samples);
        };
        for (int j = int(w); j < size; j += int(threads)) {
          for (int i = 0; i < size; ++i) {
            const double want = reference(i, j);
            const bool hit = !std::isnan(want);
            bool stable = true;
            for (auto [di, dj] : {std::pair{-0.5, 0.0}, {0.5, 0.0}, {0.0, -0.5}, {0.0, 0.5}})
              stable = stable && !std::isnan(reference(i + di, j + dj)) == hit;
            if (!stable) {
              ++c.leftOut;
              continue;
            }
            const float got = frame.depth.at(i, j);
            c.hits += hit;
            if (std::isfinite(got) && (!hit || got < want - depthSlack)) {
              // Nearer than the first root the samples found: a ghost unless F provably has a
              // root within the tolerance of the point drawn.
              const Ray r = primaryRay(scene.render.camera, size, size, i, j);
              const double reach = std::max(tolerance, scene.render.tracing.epsilon);
              const Box near = boxAround(r, got, reach);
              const bool ghost = !eval.eval1(near, surface.params).containsZero();
              c.ghost += ghost;
              if (ghost && verbose) {
                double v[4];
                point.eval(r.origin[0] + got * r.direction[0], r.origin[1] + got * r.direction[1],
                           r.origin[2] + got * r.direction[2], surface.params, v);
                std::printf("  ghost at pixel %d,%d: depth %.6g, reference %.6g, F %.3g, |grad F| %.3g\n",
                            i, j, got, want, v[0], std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]));
              }
            }
            const bool missed = hit && (!std::isfinite(got) || got > want + depthSlack);
            c.missed += missed;
            if (missed && verbose)
              std::printf("  missed at pixel %d,%d: depth %.6g, reference %.6g\n", i, j, got, want);
          }
        }
      });
    }
    for (std::thread& t : pool) t.join();
    Counts c;
    for (const Counts& p : perThread) {
      c.hits += p.hits, c.ghost += p.ghost, c.missed += p.missed, c.leftOut += p.leftOut;
    }
    const char* method = surface.method == TracingMethod::Bernstein ? "bernstein"
                         : surface.method == TracingMethod::Interval ? "interval"
                                                                      : "sampling";
    std::printf("%-40s %-9s hits %5d  ghost %4d (%.2f %%)  missed %4d (%.2f %%)  left out %4d\n",
                path.substr(path.find_last_of('/') + 1).c_str(), method, c.hits, c.ghost,
                100.0 * c.ghost / std::max(c.hits, 1), c.missed,
                100.0 * c.missed / std::max(c.hits, 1), c.leftOut);
    std::fflush(stdout);
    failures += c.ghost + c.missed > 0;
  }
  return failures > 0 ? 3 : 0;
}

}  // namespace
}  // namespace zs

int main(int argc, char** argv) { return zs::run(argc, argv); }
