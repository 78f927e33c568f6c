#include "singular/singular.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "interval/tape_eval.hpp"
#include "singular/symmetric3.hpp"

namespace zs {

namespace {

// Tape outputs: F, the gradient, the Hessian row by row.
constexpr std::size_t kF = 0, kGrad = 1, kHess = 4, kOutputs = 13;

// F, grad F and the Hessian of one formula, as intervals over boxes and as doubles at points.
class Problem {
 public:
  Problem(const Formula& formula, std::span<const double> params)
      : params_(params.begin(), params.end()) {
    Graph g = formula.graph;
    const std::array<NodeId, 3> grad = gradient(g, formula.root);
    std::vector<NodeId> roots{formula.root, grad[0], grad[1], grad[2]};
    for (NodeId gi : grad) {
      const std::array<NodeId, 3> row = gradient(g, gi);
      roots.insert(roots.end(), row.begin(), row.end());
    }
    tape_ = compileTape(g, roots);
    intervals_.emplace(tape_);
    points_.emplace(tape_);
  }

  std::array<Interval, kOutputs> over(const Box& box) {
    std::array<Interval, kOutputs> out;
    intervals_->eval(box, params_, out);
    return out;
  }
  std::array<double, kOutputs> at(const std::array<double, 3>& p) {
    std::array<double, kOutputs> out;
    points_->eval(p[0], p[1], p[2], params_, out);
    return out;
  }

 private:
  std::vector<double> params_;
  Tape tape_;
  std::optional<IntervalEvaluator> intervals_;
  std::optional<PointEvaluator> points_;
};

Box inflate(const Box& b, double fraction) {
  Box r = b;
  for (std::size_t a = 0; a < 3; ++a) {
    const double w = (b.max[a] - b.min[a]) * fraction;
    r.min[a] -= w;
    r.max[a] += w;
  }
  return r;
}

std::array<double, 3> middle(const Box& b) {
  return {0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1]), 0.5 * (b.min[2] + b.max[2])};
}

double widest(const Box& b) {
  return std::max({b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]});
}

// The Krawczyk operator of grad F on X with preconditioner Y (an approximate inverse of the
// Hessian at m): K = m - Y g(m) + (I - Y H(X)) (X - m). Every zero of grad F in X lies in K;
// K inside the interior of X proves exactly one (Krawczyk 1969, Moore 1977).
Box krawczyk(const Box& x, const std::array<double, 3>& m, const Mat3& y,
             const std::array<Interval, kOutputs>& atM, const std::array<Interval, kOutputs>& overX) {
  Box k;
  for (std::size_t i = 0; i < 3; ++i) {
    Interval acc = Interval::point(m[i]);
    for (std::size_t c = 0; c < 3; ++c)
      acc = ia::sub(acc, ia::mul(Interval::point(y[i][c]), atM[kGrad + c]));
    for (std::size_t j = 0; j < 3; ++j) {
      Interval row = Interval::point(i == j ? 1.0 : 0.0);
      for (std::size_t c = 0; c < 3; ++c)
        row = ia::sub(row, ia::mul(Interval::point(y[i][c]), overX[kHess + 3 * c + j]));
      acc = ia::add(acc, ia::mul(row, ia::sub(Interval{x.min[j], x.max[j]}, Interval::point(m[j]))));
    }
    k.min[i] = acc.lo;
    k.max[i] = acc.hi;
  }
  return k;
}

bool strictlyInside(const Box& inner, const Box& outer) {
  for (std::size_t a = 0; a < 3; ++a)
    if (!(inner.min[a] > outer.min[a] && inner.max[a] < outer.max[a])) return false;
  return true;
}

Mat3 hessianAt(const std::array<double, kOutputs>& v) {
  Mat3 h;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) h[i][j] = v[kHess + 3 * i + j];
  return h;
}

// Newton's method on grad F = 0 from m, kept inside `box` (which holds exactly one zero).
std::array<double, 3> refine(Problem& problem, std::array<double, 3> p, const Box& box) {
  for (int it = 0; it < 60; ++it) {
    const auto v = problem.at(p);
    const std::optional<Mat3> inv = inverse(hessianAt(v));
    if (!inv) break;
    double step = 0;
    std::array<double, 3> next = p;
    for (std::size_t i = 0; i < 3; ++i) {
      double d = 0;
      for (std::size_t c = 0; c < 3; ++c) d += (*inv)[i][c] * v[kGrad + c];
      next[i] = std::clamp(p[i] - d, box.min[i], box.max[i]);
      step = std::max(step, std::abs(next[i] - p[i]));
    }
    p = next;
    if (step <= 1e-15 * (1 + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]))) break;
  }
  return p;
}

// False when interval arithmetic proves F or a component of grad F has no zero in x. Each
// is bounded twice, directly and by its mean-value form about the middle m of x,
// f(x) in f(m) + f'(x) (x - m), which the derivatives at hand make cheap and which is far
// tighter on small boxes, where the direct bound suffers from dependency; the intersection of
// two enclosures is an enclosure.
bool mayHoldSingularPoint(Problem& problem, const Box& x) {
  const auto over = problem.over(x);
  const std::array<double, 3> m = middle(x);
  const auto atM = problem.over(Box{m, m});
  std::array<Interval, 3> dx;
  for (std::size_t j = 0; j < 3; ++j)
    dx[j] = ia::sub(Interval{x.min[j], x.max[j]}, Interval::point(m[j]));
  auto meanValue = [&](std::size_t value, std::size_t firstDerivative) {
    Interval mv = atM[value];
    for (std::size_t j = 0; j < 3; ++j) mv = ia::add(mv, ia::mul(over[firstDerivative + j], dx[j]));
    return intersect(over[value], mv);
  };
  auto holdsZero = [](Interval v) { return !v.isEmpty() && v.containsZero(); };
  if (!holdsZero(meanValue(kF, kGrad))) return false;
  for (std::size_t c = 0; c < 3; ++c)
    if (!holdsZero(meanValue(kGrad + c, kHess + 3 * c))) return false;
  return true;
}

}  // namespace

std::variant<SingularResult, std::string> findSingularPoints(const Formula& formula,
                                                             std::span<const double> params,
                                                             const Box& domain,
                                                             std::optional<Ball> ball,
                                                             const SingularSettings& settings) {
  if (formula.root == kNoNode) return std::string("the formula is empty");
  for (std::size_t a = 0; a < 3; ++a)
    if (!(std::isfinite(domain.min[a]) && std::isfinite(domain.max[a]) &&
          domain.min[a] < domain.max[a]))
      return std::string("the domain must be a box with finite min < max on every axis");
  const auto start = std::chrono::steady_clock::now();
  Problem problem(formula, params);
  SingularResult result;
  const double size = widest(domain);

  // Depth-first; boxes are split a little off their middle so that points on symmetry
  // planes of the domain (x = 0 of [-2, 2]^3) do not fall on a split face at once.
  std::vector<std::pair<Box, int>> stack{{domain, 0}};
  while (!stack.empty()) {
    auto [x, depth] = stack.back();
    stack.pop_back();
    if (++result.boxesTested > settings.boxBudget)
      return "singular point search stopped after " + std::to_string(settings.boxBudget) +
             " boxes; shrink the domain or lower the depth";
    if (ball && boxOutsideBall(x, *ball)) continue;
    if (!mayHoldSingularPoint(problem, x)) continue;

    // Krawczyk on a slightly inflated copy, so a zero on a face of x is certified too (by
    // both neighbours: duplicates are merged below).
    const Box xi = inflate(x, 1e-3);
    const std::array<double, 3> m = middle(xi);
    const std::optional<Mat3> y = inverse(hessianAt(problem.at(m)));
    if (y) {
      const auto atM = problem.over(Box{m, m});
      const auto overXi = problem.over(xi);
      const Box k = krawczyk(xi, m, *y, atM, overXi);
      const std::optional<Box> both = meet(k, xi);
      if (!both) continue;  // no zero of grad F in xi
      if (strictlyInside(k, xi)) {
        const Interval fk = problem.over(k)[kF];
        if (fk.isEmpty() || !fk.containsZero()) continue;  // a critical point off the surface
        const std::array<double, 3> p = refine(problem, m, k);
        const auto v = problem.at(p);
        const Mat3 h = hessianAt(v);
        const std::array<double, 3> lambda = eigenvalues(h);
        const double scale = std::max({1.0, std::abs(lambda[0]), std::abs(lambda[2])});
        if (!(std::abs(v[kF]) <= settings.fTolerance * scale)) continue;
        // In the closed domain, to rounding: a node on a face of the domain is kept.
        const double slack = 1e-9 * size;
        if (ball && std::hypot(p[0] - ball->center[0], p[1] - ball->center[1],
                               p[2] - ball->center[2]) > ball->radius + slack)
          continue;
        bool inDomain = true;
        for (std::size_t a = 0; a < 3; ++a)
          inDomain = inDomain && p[a] >= domain.min[a] - slack && p[a] <= domain.max[a] + slack;
        if (!inDomain) continue;
        bool known = false;
        for (const SingularPoint& q : result.points)
          known = known || std::hypot(q.point[0] - p[0], q.point[1] - p[1], q.point[2] - p[2]) <=
                               1e-7 * size;
        if (known) continue;
        SingularPoint sp;
        sp.point = p;
        sp.boxWidth = widest(k);
        sp.f = v[kF];
        sp.eigenvalues = lambda;
        for (double l : lambda) {
          if (std::abs(l) <= 1e-9 * scale) ++sp.zero;
          else if (l > 0) ++sp.positive;
          else ++sp.negative;
        }
        result.points.push_back(sp);
        continue;
      }
      // Every zero of grad F in x lies in k too: keep only the part of x that k covers.
      const std::optional<Box> shrunk = meet(x, k);
      if (!shrunk) continue;
      x = *shrunk;
    }
    if (depth >= settings.maxDepth) {
      result.uncertified.push_back(x);
      continue;
    }
    std::array<double, 3> cut;
    for (std::size_t a = 0; a < 3; ++a) cut[a] = x.min[a] + 0.4876 * (x.max[a] - x.min[a]);
    for (int child = 7; child >= 0; --child) {
      Box c;
      for (std::size_t a = 0; a < 3; ++a) {
        const bool upper = (child >> a) & 1;
        c.min[a] = upper ? cut[a] : x.min[a];
        c.max[a] = upper ? x.max[a] : cut[a];
      }
      stack.push_back({c, depth + 1});
    }
  }
  std::sort(result.points.begin(), result.points.end(),
            [](const SingularPoint& a, const SingularPoint& b) { return a.point < b.point; });
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace zs
