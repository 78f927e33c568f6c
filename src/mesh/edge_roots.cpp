// The vertices' roots, refined a batch of edges at a time: each step evaluates the field at
// the next guess of every edge still unsettled in one batch evaluator call, which costs a
// fraction of the same evaluations one point at a time.
#include <algorithm>
#include <cmath>

#include "mesh/field.hpp"

namespace zs::mesh {

namespace {

// One edge's bracket [lo, hi] (in the edge's parameter) with value(lo) < 0 <= value(hi).
struct Bracket {
  double lo = 0, hi = 1, flo = 0, fhi = 0, t = 0.5, scale = 0;
  double last = 0;  // the value at t
  int side = 0;     // which end moved last: -1 lo, 1 hi
};

// Where the refined bracket ends with the field far from 0, the sign changed without a
// root: at a pole |F| grows without bound, at a jump or at the edge of F's domain it stays
// away from 0. A root of a continuous F leaves |F| at 10^-10 of the change along the edge,
// or the bracket 10^-12 of the edge wide.
constexpr double kRootTolerance = 1e-3;

// Illinois while both ends are finite, bisection while an end is undefined or infinite.
double nextGuess(const Bracket& k) {
  if (!std::isfinite(k.flo) || !std::isfinite(k.fhi)) return 0.5 * (k.lo + k.hi);
  const double t = k.lo + (k.hi - k.lo) * (k.flo / (k.flo - k.fhi));
  return t > k.lo && t < k.hi ? t : 0.5 * (k.lo + k.hi);
}

// Takes the value at the guess; false when the edge is settled.
bool update(Bracket& k, double v) {
  k.last = v;
  if (v < 0) {
    k.lo = k.t;
    k.flo = v;
    if (k.side == -1) k.fhi *= 0.5;  // Illinois: the stale end's value is halved
    k.side = -1;
  } else {
    k.hi = k.t;
    k.fhi = v;
    if (k.side == 1) k.flo *= 0.5;
    k.side = 1;
  }
  return !(std::abs(v) <= 1e-10 * k.scale);
}

P3 along(const FieldEvaluator::Edge& e, double t) {
  return {e.a[0] + (e.b[0] - e.a[0]) * t, e.a[1] + (e.b[1] - e.a[1]) * t,
          e.a[2] + (e.b[2] - e.a[2]) * t};
}

constexpr int kMaxSteps = 100;
constexpr double kSettled = 1e-12;  // of the edge

}  // namespace

void FieldEvaluator::rootsOnEdges(std::span<const Edge> edges, std::span<Root> roots) {
  constexpr std::size_t kWidth = BatchEvaluator::kWidth;
  std::array<Bracket, kWidth> brackets;
  std::array<std::uint32_t, kWidth> active;
  std::array<double, kWidth> xs, ys, zs, fieldValues;
  std::array<double, 4 * kWidth> fg;
  for (std::size_t at = 0; at < edges.size(); at += kWidth) {
    const std::size_t count = std::min(kWidth, edges.size() - at);
    const Edge* e = &edges[at];
    std::size_t live = 0;
    for (std::size_t k = 0; k < count; ++k) {
      // The change of F along the edge, from its finite ends (an infinite end is a pole).
      const double scale = (std::isfinite(e[k].va) ? std::abs(e[k].va) : 0.0) +
                           (std::isfinite(e[k].vb) ? std::abs(e[k].vb) : 0.0);
      brackets[k] = Bracket{0, 1, e[k].va, e[k].vb, 0.5, scale, e[k].va, 0};
      active[live++] = std::uint32_t(k);
    }
    for (int step = 0; step < kMaxSteps && live > 0; ++step) {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < live; ++i) {
        Bracket& b = brackets[active[i]];
        if (!(b.hi - b.lo > kSettled)) continue;
        b.t = nextGuess(b);
        const P3 p = along(e[active[i]], b.t);
        xs[kept] = p[0], ys[kept] = p[1], zs[kept] = p[2];
        active[kept++] = active[i];
      }
      live = kept;
      values(std::span(xs).first(live), std::span(ys).first(live), std::span(zs).first(live),
             std::span(fieldValues).first(live));
      kept = 0;
      for (std::size_t i = 0; i < live; ++i)
        if (update(brackets[active[i]], fieldValues[i])) active[kept++] = active[i];
      live = kept;
    }
    for (std::size_t k = 0; k < count; ++k) {
      const P3 p = along(e[k], std::clamp(brackets[k].t, kEdgeMargin, 1 - kEdgeMargin));
      xs[k] = p[0], ys[k] = p[1], zs[k] = p[2];
    }
    batchGradient_.evalAll(std::span(xs).first(count), std::span(ys).first(count),
                           std::span(zs).first(count), params_, std::span(fg).first(4 * count));
    for (std::size_t k = 0; k < count; ++k) {
      Root& r = roots[at + k];
      r.position = {xs[k], ys[k], zs[k]};
      const double* g = &fg[4 * k];
      if (capBall_ && ballDistance(r.position) >= (std::isnan(g[0]) ? -1.0 : g[0])) {
        // The ball's sphere is the nearer piece here: its gradient is the radial direction.
        r.onBall = true;
        for (std::size_t a = 0; a < 3; ++a) r.gradient[a] = r.position[a] - capBall_->center[a];
        continue;
      }
      r.pole = !(std::abs(brackets[k].last) <= kRootTolerance * brackets[k].scale);
      r.gradient = {g[1], g[2], g[3]};
      const double len = std::sqrt(g[1] * g[1] + g[2] * g[2] + g[3] * g[3]);
      r.residual = len > 0 ? std::abs(g[0]) / len : (g[0] == 0 ? 0.0 : INFINITY);
    }
  }
}

}  // namespace zs::mesh
