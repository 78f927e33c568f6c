#include "reference_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <thread>
#include <vector>

#include "codegen/emit_ray_polynomial.hpp"
#include "expr/tape.hpp"
#include "interval/tape_eval.hpp"
#include "render/camera.hpp"

namespace zs::test {
namespace {

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

}  // namespace

Domain boxOfBall(const Domain& ball) {
  if (ball.shape != DomainShape::Sphere) return ball;
  Domain box = ball;
  box.shape = DomainShape::Box;
  for (int k = 0; k < 3; ++k) {
    box.min[k] = ball.center[k] - ball.radius;
    box.max[k] = ball.center[k] + ball.radius;
  }
  return box;
}

ReferenceCounts compareWithReference(const Scene& scene, const app::PreparedSurface& surface,
                                     const Frame& frame, int size) {
  const Formula& formula = surface.formula;
  const Tape tape = compileTape(formula.graph, {formula.root});
  const Tape withGradient = compileTape(
      formula.graph, {formula.root, surface.gradient[0], surface.gradient[1], surface.gradient[2]});
  const int samples =
      32 * std::max(rayPolynomialDegree(formula.graph, formula.root).value_or(8), 2);
  const Domain bb = boundingBox(scene.domain);
  double diagonal = 0;
  for (int k = 0; k < 3; ++k) diagonal += std::pow(bb.max[k] - bb.min[k], 2);
  const double tolerance = 1e-5 * std::sqrt(diagonal);  // the tracer's tangent tolerance
  const double depthSlack =
      std::max(10 * scene.render.tracing.epsilon, 1e-4 * std::sqrt(diagonal));

  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<ReferenceCounts> perThread(threads);
  std::vector<std::thread> pool;
  for (unsigned w = 0; w < threads; ++w) {
    pool.emplace_back([&, w] {
      IntervalEvaluator eval(tape);
      PointEvaluator point(withGradient);
      ReferenceCounts& c = perThread[w];
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
            if (ghost) {
              double v[4];
              point.eval(r.origin[0] + got * r.direction[0], r.origin[1] + got * r.direction[1],
                         r.origin[2] + got * r.direction[2], surface.params, v);
              char line[200];
              std::snprintf(line, sizeof line,
                            "  ghost at pixel %d,%d: depth %.6g, reference %.6g, F %.3g, "
                            "|grad F| %.3g\n",
                            i, j, got, want, v[0],
                            std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]));
              c.details += line;
            }
          }
          const bool missed = hit && (!std::isfinite(got) || got > want + depthSlack);
          c.missed += missed;
          if (missed) {
            char line[200];
            std::snprintf(line, sizeof line, "  missed at pixel %d,%d: depth %.6g, reference %.6g\n",
                          i, j, got, want);
            c.details += line;
          }
        }
      }
    });
  }
  for (std::thread& t : pool) t.join();
  ReferenceCounts c;
  for (const ReferenceCounts& p : perThread) {
    c.hits += p.hits, c.ghost += p.ghost, c.missed += p.missed, c.leftOut += p.leftOut;
    c.details += p.details;
  }
  return c;
}

}  // namespace zs::test
