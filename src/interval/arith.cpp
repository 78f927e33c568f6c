// Enclosure rules for arithmetic, integer powers and the piecewise functions.
#include <algorithm>
#include <cmath>

#include "interval/interval.hpp"
#include "interval/rounding.hpp"

namespace zs {
using detail::down;
using detail::kInf;
using detail::up;

Interval hull(Interval a, Interval b) {
  if (a.isEmpty()) return b;
  if (b.isEmpty()) return a;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

Interval intersect(Interval a, Interval b) {
  if (a.isEmpty() || b.isEmpty()) return Interval::empty();
  Interval r{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
  return r.isEmpty() ? Interval::empty() : r;
}

namespace {

// A NaN endpoint only comes from inf - inf: the sum is then unbounded both ways.
Interval finite(Interval r) {
  return (std::isnan(r.lo) || std::isnan(r.hi)) ? Interval::whole() : r;
}

// x^n for x >= 0, n >= 1, by binary powering with every product rounded the same way, so
// powUp(x, n) >= the exact x^n and powDown(x, n) <= it.
template <bool Up>
double powDirected(double x, unsigned n) {
  double result = 1.0;
  bool first = true;
  double base = x;
  for (;;) {
    if (n & 1u) {
      if (first) {
        result = base;  // the first factor needs no product, hence no rounding
        first = false;
      } else {
        result = Up ? up(result * base) : std::max(0.0, down(result * base));
      }
    }
    n >>= 1u;
    if (n == 0) return result;
    base = Up ? up(base * base) : std::max(0.0, down(base * base));
  }
}

}  // namespace

namespace ia {

Interval neg(Interval a) {
  return {-a.hi, -a.lo};
}

Interval add(Interval a, Interval b) {
  return finite({down(a.lo + b.lo), up(a.hi + b.hi)});
}

Interval sub(Interval a, Interval b) {
  return finite({down(a.lo - b.hi), up(a.hi - b.lo)});
}

Interval mul(Interval a, Interval b) {
  // A corner 0 * inf is the limit of products whose value is 0 at every finite point.
  auto p = [](double u, double v) {
    double r = u * v;
    return std::isnan(r) ? 0.0 : r;
  };
  const double c[4] = {p(a.lo, b.lo), p(a.lo, b.hi), p(a.hi, b.lo), p(a.hi, b.hi)};
  return {down(std::min({c[0], c[1], c[2], c[3]})), up(std::max({c[0], c[1], c[2], c[3]}))};
}

Interval div(Interval a, Interval b) {
  if (b.containsZero()) return Interval::whole();
  // inf / inf corners are NaN; fmin/fmax skip them, and the other corners already reach
  // the limits that corner stands for.
  const double c[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  double lo = kInf, hi = -kInf;
  for (double v : c) {
    lo = std::fmin(lo, v);
    hi = std::fmax(hi, v);
  }
  Interval r{down(lo), up(hi)};
  return r.isEmpty() ? Interval::whole() : r;
}

Interval powi(Interval a, int n) {
  if (n == 0) return Interval::point(1.0);  // pow(x, 0) == 1 for every x
  const unsigned m = n < 0 ? 0u - static_cast<unsigned>(n) : static_cast<unsigned>(n);
  Interval p;
  if (m % 2 == 0) {
    // Even powers depend on |x| only, so they are tight around 0: [-1,2]^2 = [0,4].
    const double magLo = a.containsZero() ? 0.0 : std::min(std::fabs(a.lo), std::fabs(a.hi));
    const double magHi = std::max(std::fabs(a.lo), std::fabs(a.hi));
    p = {powDirected<false>(magLo, m), powDirected<true>(magHi, m)};
  } else {
    auto lower = [m](double x) {
      return x >= 0 ? powDirected<false>(x, m) : -powDirected<true>(-x, m);
    };
    auto upper = [m](double x) {
      return x >= 0 ? powDirected<true>(x, m) : -powDirected<false>(-x, m);
    };
    p = {lower(a.lo), upper(a.hi)};
  }
  if (n > 0) return p;
  if (m % 2 != 0) return div(Interval::point(1.0), p);
  // Even negative power: p >= 0, and 1/p is non-negative even where p reaches 0 (+inf).
  const double lo = p.hi == kInf ? 0.0 : std::max(0.0, down(1.0 / p.hi));
  const double hi = p.lo <= 0.0 ? kInf : up(1.0 / p.lo);
  return {lo, hi};
}

Interval abs(Interval a) {
  if (a.lo >= 0) return a;
  if (a.hi <= 0) return neg(a);
  return {0.0, std::max(-a.lo, a.hi)};
}

// sign, floor and ceil are non-decreasing and exact in double, so endpoints map exactly.
Interval sign(Interval a) {
  auto s = [](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); };
  return {s(a.lo), s(a.hi)};
}
Interval floor(Interval a) {
  return {std::floor(a.lo), std::floor(a.hi)};
}
Interval ceil(Interval a) {
  return {std::ceil(a.lo), std::ceil(a.hi)};
}

Interval min(Interval a, Interval b) {
  return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}
Interval max(Interval a, Interval b) {
  return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

}  // namespace ia
}  // namespace zs
