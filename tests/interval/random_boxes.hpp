#pragma once
// Random intervals and boxes for the inclusion tests: a mix of boxes touching or straddling
// 0, huge, tiny, degenerate and ordinary ones, plus sample points inside them.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "interval/hierarchy.hpp"
#include "interval/interval.hpp"

namespace zs::test {

class IntervalSampler {
 public:
  explicit IntervalSampler(unsigned seed) : rng_(seed) {}

  // A magnitude 10^e with e uniform in [lo, hi].
  double magnitude(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double signedMagnitude(double lo, double hi) {
    return coin() ? magnitude(lo, hi) : -magnitude(lo, hi);
  }
  bool coin() { return std::uniform_int_distribution<int>(0, 1)(rng_) == 1; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  Interval interval() {
    switch (pick(8)) {
      case 0: {  // one endpoint exactly 0
        const double m = magnitude(-6, 3);
        return coin() ? Interval{0.0, m} : Interval{-m, 0.0};
      }
      case 1:
        return {-magnitude(-6, 3), magnitude(-6, 3)};  // straddles 0
      case 2:
        return ordered(signedMagnitude(30, 308), signedMagnitude(30, 308));  // huge
      case 3: {  // tiny: a few ulps to 1e-9 relative around an ordinary or subnormal center
        const double c = pick(4) == 0 ? signedMagnitude(-320, -300) : signedMagnitude(-4, 4);
        const double w = std::fabs(c) * magnitude(-16, -9);
        return {c, c + w};
      }
      case 4: {  // degenerate
        const double c = pick(10) == 0 ? 0.0 : signedMagnitude(-8, 8);
        return {c, c};
      }
      case 5: {  // around the special points of the periodic and domain-restricted rules
        const double specials[] = {0.0,
                                   1.0,
                                   -1.0,
                                   2.0,
                                   std::numbers::pi / 2,
                                   std::numbers::pi,
                                   -std::numbers::pi / 2,
                                   3 * std::numbers::pi / 2};
        const double c = specials[pick(8)] * (pick(3) == 0 ? double(1 + pick(9)) : 1.0);
        const double w = magnitude(-15, 0);
        return ordered(c - w * uniform(0, 1), c + w * uniform(0, 1));
      }
      default:
        return ordered(signedMagnitude(-3, 3), signedMagnitude(-3, 3));  // ordinary
    }
  }

  Box box() {
    Box b;
    for (std::size_t i = 0; i < 3; ++i) {
      const Interval v = interval();
      b.min[i] = v.lo;
      b.max[i] = v.hi;
    }
    return b;
  }

  // Points of [lo, hi]: k = 0, 1 the endpoints, 2 the midpoint, then uniform ones.
  double pointIn(Interval a, int k) {
    if (k == 0) return a.lo;
    if (k == 1) return a.hi;
    const double t = k == 2 ? 0.5 : uniform(0, 1);
    // Convex combination without forming hi - lo, which may overflow for huge boxes.
    return std::clamp(a.lo * (1 - t) + a.hi * t, a.lo, a.hi);
  }

 private:
  static Interval ordered(double u, double v) { return {std::min(u, v), std::max(u, v)}; }
  std::mt19937_64 rng_;
};

}  // namespace zs::test
