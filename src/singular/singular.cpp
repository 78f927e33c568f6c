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

// Tape outputs: F, the gradient, the Hessian row by row, and the third derivatives
// F_ijk for i <= j <= k (kThird + thirdIndex(i, j, k)).
constexpr std::size_t kF = 0, kGrad = 1, kHess = 4, kThird = 13, kOutputs = 23;

// Where F_ijk sits among the ten third derivatives, for any order of i, j, k.
constexpr std::size_t thirdIndex(std::size_t i, std::size_t j, std::size_t k) {
  // Sorted: a <= b <= c; the ten triples in lexicographic order.
  const std::size_t a = std::min({i, j, k}), c = std::max({i, j, k}), b = i + j + k - a - c;
  constexpr std::size_t firstOf[3] = {0, 6, 9};  // triples starting with 0, 1, 2
  constexpr std::size_t second[3][3] = {{0, 3, 5}, {0, 0, 2}, {0, 0, 0}};
  return firstOf[a] + second[a][b] + (c - b);
}

// The output that holds d/dx_j of output o, for F, the gradient and the Hessian.
constexpr std::size_t derivativeOf(std::size_t o, std::size_t j) {
  if (o == kF) return kGrad + j;
  if (o < kHess) return kHess + 3 * (o - kGrad) + j;
  return kThird + thirdIndex((o - kHess) / 3, (o - kHess) % 3, j);
}

// F, grad F and the Hessian of one formula, as intervals over boxes and as doubles at points;
// over boxes also the third derivatives, which only the Taylor forms need (a second tape
// without them keeps the many evaluations at points cheap).
class Problem {
 public:
  Problem(const Formula& formula, std::span<const double> params)
      : params_(params.begin(), params.end()) {
    Graph g = formula.graph;
    const std::array<NodeId, 3> grad = gradient(g, formula.root);
    std::vector<NodeId> roots{formula.root, grad[0], grad[1], grad[2]};
    std::array<std::array<NodeId, 3>, 3> hessian;
    for (std::size_t i = 0; i < 3; ++i) {
      hessian[i] = gradient(g, grad[i]);
      roots.insert(roots.end(), hessian[i].begin(), hessian[i].end());
    }
    base_ = compileTape(g, roots);
    // The third derivatives, each once: d/dk of H_ij for i <= j <= k.
    roots.resize(kOutputs, kNoNode);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = i; j < 3; ++j) {
        const std::array<NodeId, 3> d = gradient(g, hessian[i][j]);
        for (std::size_t k = j; k < 3; ++k) roots[kThird + thirdIndex(i, j, k)] = d[k];
      }
    // Where a piecewise operation switches, its derivative (as expr/derivative.cpp writes
    // it: sign' = floor' = 0, min/max through sign) misses the jump, so the derivatives of
    // the next order do not bound the change over a box that holds the switch. Each
    // switch's argument is evaluated with the rest; a box where one may switch is not smooth.
    // (The kink's argument is the next output; atan2's x follows its y.)
    auto watch = [&](Kink kind, NodeId argument) {
      kinks_.push_back({kind, roots.size()});
      roots.push_back(argument);
    };
    for (NodeId id : reachable(g, roots)) {
      const Node& n = g[id];
      switch (n.op) {
        case Op::Abs:
        case Op::Sign:
          watch(Kink::AtZero, n.a);
          break;
        case Op::Floor:
        case Op::Ceil:
          watch(Kink::AtInteger, n.a);
          break;
        case Op::Min:
        case Op::Max:
          watch(Kink::AtZero, g.binary(Op::Sub, n.a, n.b));
          break;
        case Op::Atan2:  // the cut: y = 0, x < 0
          watch(Kink::BranchCut, n.a);
          roots.push_back(n.b);
          break;
        default:
          break;
      }
    }
    full_ = compileTape(g, roots);
    overBoxes_.emplace(full_);
    outputs_.resize(roots.size());
    overPoints_.emplace(base_);
    points_.emplace(base_);
  }

  // Everything, third derivatives included, over a box; `smooth` is false where a piecewise
  // operation may switch inside it.
  struct OverBox {
    std::array<Interval, kOutputs> v;
    bool smooth = true;
  };
  OverBox over(const Box& box) {
    overBoxes_->eval(box, params_, outputs_);
    OverBox out;
    std::copy_n(outputs_.begin(), kOutputs, out.v.begin());
    for (const auto& [kind, at] : kinks_) out.smooth = out.smooth && !maySwitch(kind, at);
    return out;
  }
  // F, grad F and the Hessian at a point, enclosed (the third derivatives are left empty).
  std::array<Interval, kOutputs> enclosedAt(const std::array<double, 3>& p) {
    std::array<Interval, kOutputs> out;
    out.fill(Interval::empty());
    overPoints_->eval(Box{p, p}, params_, std::span(out).first(kThird));
    return out;
  }
  std::array<double, kOutputs> at(const std::array<double, 3>& p) {
    std::array<double, kOutputs> out{};
    points_->eval(p[0], p[1], p[2], params_, std::span(out).first(kThird));
    return out;
  }

 private:
  enum class Kink { AtZero, AtInteger, BranchCut };

  // Whether the operation whose argument is output `at` may switch over the last box (an
  // empty argument: it may).
  bool maySwitch(Kink kind, std::size_t at) const {
    const Interval a = outputs_[at];
    if (a.isEmpty()) return true;
    switch (kind) {
      case Kink::AtZero:
        return a.containsZero();
      case Kink::AtInteger:
        return std::floor(a.lo) != std::floor(a.hi) || std::floor(a.lo) == a.lo;
      case Kink::BranchCut:
        return a.containsZero() && !(outputs_[at + 1].lo > 0);
    }
    return true;
  }

  std::vector<double> params_;
  std::vector<std::pair<Kink, std::size_t>> kinks_;  // and the output of its argument
  std::vector<Interval> outputs_;                    // every output of the full tape
  Tape base_, full_;
  std::optional<IntervalEvaluator> overBoxes_, overPoints_;
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
             const std::array<Interval, kOutputs>& atM,
             const std::array<Interval, kOutputs>& overX) {
  Box k;
  for (std::size_t i = 0; i < 3; ++i) {
    Interval acc = Interval::point(m[i]);
    for (std::size_t c = 0; c < 3; ++c)
      acc = ia::sub(acc, ia::mul(Interval::point(y[i][c]), atM[kGrad + c]));
    for (std::size_t j = 0; j < 3; ++j) {
      Interval row = Interval::point(i == j ? 1.0 : 0.0);
      for (std::size_t c = 0; c < 3; ++c)
        row = ia::sub(row, ia::mul(Interval::point(y[i][c]), overX[kHess + 3 * c + j]));
      acc =
          ia::add(acc, ia::mul(row, ia::sub(Interval{x.min[j], x.max[j]}, Interval::point(m[j]))));
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

bool within(const Box& inner, const Box& outer) {
  for (std::size_t a = 0; a < 3; ++a)
    if (!(inner.min[a] >= outer.min[a] && inner.max[a] <= outer.max[a])) return false;
  return true;
}

bool holds(const Box& b, const std::array<double, 3>& p) {
  return within(Box{p, p}, b);
}

Mat3 hessianAt(const std::array<double, kOutputs>& v) {
  Mat3 h;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) h[i][j] = v[kHess + 3 * i + j];
  return h;
}

// One Newton step on grad F = 0 at p: H(p)^-1 grad F(p); nothing where H(p) is singular.
std::optional<std::array<double, 3>> newtonStep(Problem& problem, const std::array<double, 3>& p) {
  const auto v = problem.at(p);
  const std::optional<Mat3> inv = inverse(hessianAt(v));
  if (!inv) return std::nullopt;
  std::array<double, 3> d{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t c = 0; c < 3; ++c) d[i] += (*inv)[i][c] * v[kGrad + c];
  return d;
}

double scaleOf(const std::array<double, 3>& p) {
  return 1 + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]);
}

// Newton's method on grad F = 0 from m, kept inside `box` (which holds exactly one zero).
std::array<double, 3> refine(Problem& problem, std::array<double, 3> p, const Box& box) {
  for (int it = 0; it < 60; ++it) {
    const std::optional<std::array<double, 3>> d = newtonStep(problem, p);
    if (!d) break;
    double step = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double next = std::clamp(p[i] - (*d)[i], box.min[i], box.max[i]);
      step = std::max(step, std::abs(next - p[i]));
      p[i] = next;
    }
    if (step <= 1e-15 * scaleOf(p)) break;
  }
  return p;
}

// Newton's method on grad F = 0 from m, free to leave the box; nothing when it does not settle
// within a few steps (no critical point near m, or a degenerate one).
std::optional<std::array<double, 3>> newtonPoint(Problem& problem, std::array<double, 3> p) {
  for (int it = 0; it < 12; ++it) {
    const std::optional<std::array<double, 3>> d = newtonStep(problem, p);
    if (!d) return std::nullopt;
    double step = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      p[i] -= (*d)[i];
      step = std::max(step, std::abs((*d)[i]));
    }
    if (!std::isfinite(step)) return std::nullopt;
    if (step <= 1e-13 * scaleOf(p)) return p;
  }
  return std::nullopt;
}

// F, grad F and the Hessian over x, each the intersection of enclosures (an intersection of
// enclosures is an enclosure): the direct interval evaluation, the mean-value form
// f(m) + f'(x) d, and the second-order Taylor form f(m) + f'(m) d + d' f''(x) d / 2, with m
// the middle of x and d = x - m. The direct bound of a polynomial of high degree suffers
// from dependency and cancellation (the Sarti dodecic is a difference of two terms of size
// |p|^12); the Taylor forms bound only what varies over x, and each order higher leaves an
// excess that shrinks one power of the box's width faster. The Hessian gets the mean-value
// form with the third derivatives. The forms need F smooth over x: where a piecewise
// operation may switch, only the direct bounds are used.
Problem::OverBox tightened(Problem& problem, const Box& x, const std::array<double, 3>& m) {
  const Problem::OverBox direct = problem.over(x);
  // Where a piecewise operation may switch, only the direct bounds hold.
  if (!direct.smooth) return direct;
  const std::array<Interval, kOutputs>& over = direct.v;
  const auto atM = problem.enclosedAt(m);
  std::array<Interval, 3> d;
  for (std::size_t j = 0; j < 3; ++j)
    d[j] = ia::sub(Interval{x.min[j], x.max[j]}, Interval::point(m[j]));
  // A form that comes out empty (an infinite derivative times a zero width) proves nothing.
  auto narrowed = [](Interval bound, Interval form) {
    return form.isEmpty() ? bound : intersect(bound, form);
  };
  Problem::OverBox out = direct;
  for (std::size_t o = 0; o < kThird; ++o) {
    Interval mean = atM[o];  // f(m) + f'(x) d
    for (std::size_t j = 0; j < 3; ++j)
      mean = ia::add(mean, ia::mul(over[derivativeOf(o, j)], d[j]));
    out.v[o] = narrowed(over[o], mean);
    if (o >= kHess) continue;  // the Hessian's own second derivatives are not on the tape
    // f(m) + f'(m) d + d' f''(x) d / 2: the squares are non-negative, cross terms count twice.
    Interval taylor = atM[o];
    for (std::size_t j = 0; j < 3; ++j) {
      taylor = ia::add(taylor, ia::mul(atM[derivativeOf(o, j)], d[j]));
      const Interval square = ia::mul(Interval::point(0.5), ia::powi(d[j], 2));
      taylor = ia::add(taylor, ia::mul(over[derivativeOf(derivativeOf(o, j), j)], square));
      for (std::size_t k = j + 1; k < 3; ++k)
        taylor = ia::add(taylor,
                         ia::mul(over[derivativeOf(derivativeOf(o, j), k)], ia::mul(d[j], d[k])));
    }
    out.v[o] = narrowed(out.v[o], taylor);
  }
  return out;
}

Box cubeAround(const std::array<double, 3>& p, double radius) {
  return Box{{p[0] - radius, p[1] - radius, p[2] - radius},
             {p[0] + radius, p[1] + radius, p[2] + radius}};
}

// Krawczyk on cubes centred on a Newton point p. A box met by the octree holds its critical
// point anywhere, often near a face, where K pokes out of the box long after K has become
// small; a cube centred on the point has the whole margin on every side. The first radius
// that certifies is doubled while it still certifies, so that the region proven to hold no
// other zero of grad F is as large as the Hessian's interval allows: the search then drops
// every box inside it. Nothing when no radius certifies (a degenerate Hessian).
std::optional<Box> uniquenessCube(Problem& problem, const std::array<double, 3>& p, double width) {
  const std::optional<Mat3> y = inverse(hessianAt(problem.at(p)));
  if (!y) return std::nullopt;
  const auto atP = problem.enclosedAt(p);
  auto certifies = [&](double radius) {
    const Box b = cubeAround(p, radius);
    const Problem::OverBox bounds = tightened(problem, b, p);
    return bounds.smooth && strictlyInside(krawczyk(b, p, *y, atP, bounds.v), b);
  };
  const double floor = 1e-12 * scaleOf(p);
  double radius = width / 64;
  while (radius > floor && !certifies(radius)) radius /= 16;
  if (!(radius > floor)) return std::nullopt;
  while (2 * radius <= width && certifies(2 * radius)) radius *= 2;
  return cubeAround(p, radius);
}

// False when interval arithmetic proves F or a component of grad F has no zero in x.
bool mayHoldSingularPoint(Problem& problem, const Box& x) {
  const auto bounds = tightened(problem, x, middle(x)).v;
  for (std::size_t c = kF; c < kHess; ++c)
    if (!bounds[c].containsZero()) return false;  // false for an empty interval too
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

  // Boxes proven to hold exactly one zero of grad F, whose zero has been dealt with.
  std::vector<Box> unique;
  auto claimedBy = [&](const Box& x) {
    return std::any_of(unique.begin(), unique.end(), [&](const Box& u) { return within(x, u); });
  };
  // A certified zero p of grad F, unique in `box`: a singular point when F vanishes there.
  auto accept = [&](const std::array<double, 3>& p, const Box& box) {
    const auto v = problem.at(p);
    const Mat3 h = hessianAt(v);
    const std::array<double, 3> lambda = eigenvalues(h);
    const double scale = std::max({1.0, std::abs(lambda[0]), std::abs(lambda[2])});
    if (!(std::abs(v[kF]) <= settings.fTolerance * scale)) return;
    // In the closed domain, to rounding: a node on a face of the domain is kept.
    const double slack = 1e-9 * size;
    if (ball && std::hypot(p[0] - ball->center[0], p[1] - ball->center[1], p[2] - ball->center[2]) >
                    ball->radius + slack)
      return;
    for (std::size_t a = 0; a < 3; ++a)
      if (!(p[a] >= domain.min[a] - slack && p[a] <= domain.max[a] + slack)) return;
    for (const SingularPoint& q : result.points)
      if (std::hypot(q.point[0] - p[0], q.point[1] - p[1], q.point[2] - p[2]) <= 1e-7 * size)
        return;
    SingularPoint sp;
    sp.point = p;
    sp.boxWidth = widest(box);
    sp.f = v[kF];
    sp.eigenvalues = lambda;
    for (double l : lambda) {
      if (std::abs(l) <= 1e-9 * scale)
        ++sp.zero;
      else if (l > 0)
        ++sp.positive;
      else
        ++sp.negative;
    }
    result.points.push_back(sp);
  };

  // Depth-first; boxes are split a little off their middle so that points on symmetry
  // planes of the domain (x = 0 of [-2, 2]^3) do not fall on a split face at once.
  std::vector<std::pair<Box, int>> stack{{domain, 0}};
  while (!stack.empty()) {
    auto [x, depth] = stack.back();
    stack.pop_back();
    if (++result.boxesTested > settings.boxBudget)
      return "singular point search stopped after " + std::to_string(settings.boxBudget) +
             " boxes; shrink the domain, lower --depth or raise --budget";
    if (ball && boxOutsideBall(x, *ball)) continue;
    if (claimedBy(x)) continue;  // its only zero of grad F is a point already found
    if (!mayHoldSingularPoint(problem, x)) continue;

    // Krawczyk on a slightly inflated copy, so a zero on a face of x is certified too (by
    // both neighbours: duplicates are merged below).
    const Box xi = inflate(x, 1e-3);
    const std::array<double, 3> m = middle(xi);
    const std::optional<Mat3> y = inverse(hessianAt(problem.at(m)));
    // Krawczyk needs the Hessian to bound the change of grad F: not where a piecewise
    // operation may switch (such a box is split until the depth ends, then reported).
    const Problem::OverBox overXi = tightened(problem, xi, m);
    if (y && overXi.smooth) {
      const auto atM = problem.enclosedAt(m);
      const Box k = krawczyk(xi, m, *y, atM, overXi.v);
      const std::optional<Box> both = meet(k, xi);
      if (!both) continue;  // no zero of grad F in xi
      if (strictlyInside(k, xi)) {
        unique.push_back(xi);
        const Interval fk = problem.over(k).v[kF];
        if (!fk.containsZero()) continue;  // a critical point off the surface
        accept(refine(problem, m, k), k);
        continue;
      }
      // Every zero of grad F in x lies in k too: keep only the part of x that k covers.
      const std::optional<Box> shrunk = meet(x, k);
      if (!shrunk) continue;
      x = *shrunk;
      if (claimedBy(x)) continue;  // near a found point, k is small and often inside its cube
      // A Newton point in x proven unique in a cube around it: the point is found, and the
      // part of x the cube covers needs no more search.
      const std::optional<std::array<double, 3>> p = newtonPoint(problem, m);
      if (p && holds(xi, *p) && !claimedBy(Box{*p, *p})) {
        if (const std::optional<Box> cube = uniquenessCube(problem, *p, widest(x))) {
          unique.push_back(*cube);
          if (problem.over(*cube).v[kF].containsZero()) accept(*p, *cube);
          if (within(x, *cube)) continue;
        }
      }
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
