// Enclosure rules for the monotone elementary functions, the domain-restricted ones
// (sqrt, log, asin, acos, pow) and atan2. Domain restriction: the operand is first
// intersected with the domain, so points outside it contribute nothing; an operand wholly
// outside gives the empty ("undefined") interval.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "interval/interval.hpp"
#include "interval/rounding.hpp"

namespace zs::ia {
using detail::down;
using detail::kInf;
using detail::libmDown;
using detail::libmUp;
using detail::up;

namespace {

// Upper bounds of pi and pi/2 that also hold every double-precision atan/asin/acos result.
const double kPiUp = up(std::numbers::pi);
const double kHalfPiUp = up(std::numbers::pi / 2);

// Non-decreasing f: endpoints map to endpoints, each kLibmUlps outward, clamped to f's range.
template <class F>
Interval increasing(Interval a, F f, double rangeLo = -kInf, double rangeHi = kInf) {
  return {libmDown(f(a.lo), rangeLo), libmUp(f(a.hi), rangeHi)};
}

// pow over a box with x >= 0: for fixed y it is monotone in x, for fixed x monotone in y,
// so its extremes over the box are at the four corners (std::pow gives the limits there,
// e.g. pow(0, -1) = inf, pow(0, 0) = 1).
Interval powCorners(Interval x, Interval y) {
  const double xs[2] = {x.lo <= 0.0 ? 0.0 : x.lo, x.hi};  // never -0.0: pow(-0.0, -1) = -inf
  double lo = kInf, hi = -kInf;
  for (double u : xs) {
    for (double v : {y.lo, y.hi}) {
      const double p = std::pow(u, v);
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
  }
  return {libmDown(lo, 0.0), libmUp(hi)};
}

}  // namespace

Interval sqrt(Interval a) {
  const Interval d = intersect(a, {0.0, kInf});
  if (d.isEmpty()) return d;
  return {std::max(0.0, down(std::sqrt(d.lo))), up(std::sqrt(d.hi))};
}

Interval cbrt(Interval a) {
  return increasing(a, [](double v) { return std::cbrt(v); });
}

Interval exp(Interval a) {
  return increasing(
      a, [](double v) { return std::exp(v); }, 0.0);
}

Interval log(Interval a) {
  const Interval d = intersect(a, {0.0, kInf});
  if (d.isEmpty()) return d;
  return increasing(d, [](double v) { return std::log(v); });  // log(0) = -inf
}

Interval sinh(Interval a) {
  return increasing(a, [](double v) { return std::sinh(v); });
}

Interval cosh(Interval a) {
  const Interval m = abs(a);
  return {std::max(1.0, libmDown(std::cosh(m.lo))), libmUp(std::cosh(m.hi))};
}

Interval tanh(Interval a) {
  return increasing(
      a, [](double v) { return std::tanh(v); }, -1.0, 1.0);
}

Interval asin(Interval a) {
  const Interval d = intersect(a, {-1.0, 1.0});
  if (d.isEmpty()) return d;
  return increasing(
      d, [](double v) { return std::asin(v); }, -kHalfPiUp, kHalfPiUp);
}

Interval acos(Interval a) {
  const Interval d = intersect(a, {-1.0, 1.0});
  if (d.isEmpty()) return d;
  return {libmDown(std::acos(d.hi), 0.0), libmUp(std::acos(d.lo), kPiUp)};
}

Interval atan(Interval a) {
  return increasing(
      a, [](double v) { return std::atan(v); }, -kHalfPiUp, kHalfPiUp);
}

Interval atan2(Interval y, Interval x) {
  // atan2 jumps from pi to -pi across the negative x axis (and the sign of a zero y picks
  // the side), and every angle occurs next to the origin: both give the full range.
  if (y.containsZero() && x.lo <= 0.0) return {-kPiUp, kPiUp};
  // Elsewhere atan2 is the continuous angle of a convex box that misses the origin, whose
  // extremes are attained at corners.
  double lo = kInf, hi = -kInf;
  for (double u : {y.lo, y.hi}) {
    for (double v : {x.lo, x.hi}) {
      const double t = std::atan2(u, v);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
  }
  return {libmDown(lo, -kPiUp), libmUp(hi, kPiUp)};
}

Interval pow(Interval a, Interval b) {
  if (b.isPoint() && std::floor(b.lo) == b.lo) {
    if (std::fabs(b.lo) <= 1 << 30) return powi(a, static_cast<int>(b.lo));
    // Huge integer exponent: pow(-x, n) = +-pow(x, n).
    const Interval r = powCorners(abs(a), b);
    return a.lo < 0 ? hull(r, neg(r)) : r;
  }
  // Negative bases are outside the domain of a non-integer exponent...
  Interval r = intersect(a, {0.0, kInf});
  if (!r.isEmpty()) r = powCorners(r, b);
  // ...but std::pow defines them at integer exponents, which a non-degenerate exponent
  // interval may hold: then |pow(x, n)| = pow(|x|, n) bounds them.
  if (a.lo < 0.0 && std::ceil(b.lo) <= b.hi) {
    const Interval m = powCorners(abs(intersect(a, {-kInf, 0.0})), b);
    r = hull(r, {-m.hi, m.hi});
  }
  return r;
}

}  // namespace zs::ia
