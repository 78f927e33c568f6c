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
#include "render_support.hpp"

namespace zs::test {
namespace {

// The part [t0, t1] of the ray inside the domain (box, then ball), in double.
std::pair<double, double> clip(const Ray& r, const Domain& domain) {
  auto [t0, t1] = rayInBox(r, boundingBox(domain));
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

ReferenceCounts compareWithReference(const Scene& scene, const PreparedSurface& surface,
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
  const double depthSlack = std::max(10 * scene.render.tracing.epsilon, 1e-4 * std::sqrt(diagonal));

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
        return t0 <= t1 ? sampledFirstHit(point, r, t0, t1, samples, surface.params) : NAN;
      };
      for (int j = int(w); j < size; j += int(threads)) {
        for (int i = 0; i < size; ++i) {
          const double want = reference(i, j);
          const bool hit = !std::isnan(want);
          if (!stableWithinHalfAPixel(reference, i, j, hit)) {
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
            std::snprintf(line, sizeof line,
                          "  missed at pixel %d,%d: depth %.6g, reference %.6g\n", i, j, got, want);
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
