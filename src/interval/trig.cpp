// Enclosure rules for sin, cos and tan: monotone pieces between the extrema (or poles), with
// an extremum counted as inside whenever rounding leaves any doubt.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "interval/interval.hpp"
#include "interval/rounding.hpp"

namespace zs::ia {
using detail::libmDown;
using detail::libmUp;

namespace {

constexpr double kPi = std::numbers::pi;

// May some point phase + k * period (k integer) lie in [lo, hi]? The quotient carries a
// few ulps of error (and pi itself is rounded), so the test is widened generously: a
// false "yes" only loosens the result, a false "no" would lose values.
bool mayHit(double lo, double hi, double phase, double period) {
  const double tLo = (lo - phase) / period;
  const double tHi = (hi - phase) / period;
  const double slack = 1e-9 * (1.0 + std::max(std::fabs(tLo), std::fabs(tHi)));
  return std::floor(tHi + slack) >= std::ceil(tLo - slack);
}

template <class F>
Interval periodic(Interval a, F f, double maxPhase, double minPhase) {
  if (!(a.hi - a.lo < 2 * kPi)) return {-1.0, 1.0};  // also catches infinite endpoints
  const double u = f(a.lo), v = f(a.hi);
  const double lo = mayHit(a.lo, a.hi, minPhase, 2 * kPi) ? -1.0 : libmDown(std::min(u, v), -1.0);
  const double hi = mayHit(a.lo, a.hi, maxPhase, 2 * kPi) ? 1.0 : libmUp(std::max(u, v), 1.0);
  return {lo, hi};
}

}  // namespace

Interval sin(Interval a) {
  return periodic(
      a, [](double v) { return std::sin(v); }, kPi / 2, -kPi / 2);
}

Interval cos(Interval a) {
  return periodic(
      a, [](double v) { return std::cos(v); }, 0.0, kPi);
}

Interval tan(Interval a) {
  // A pole inside (or possibly inside) the box: tan takes every value.
  if (!(a.hi - a.lo < kPi) || mayHit(a.lo, a.hi, kPi / 2, kPi)) return Interval::whole();
  return {libmDown(std::tan(a.lo)), libmUp(std::tan(a.hi))};
}

}  // namespace zs::ia
