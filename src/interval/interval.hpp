#pragma once
// The Interval type and one enclosure rule per operation of the formula language: takes
// intervals of the operands, puts out an interval that contains the result of the operation
// at every point of its operands, both in exact real arithmetic and as computed in double
// precision (every endpoint is rounded outward; docs/interval.md gives the argument).
//
// "Undefined" (the empty interval) means: at no point of the operands is the operation
// defined (sqrt of a negative box, log of a box below 0, asin outside [-1,1], ...). It
// propagates through every operation, so an empty F(box) means F is defined nowhere in the
// box, which therefore holds no surface point. Points of a box that lie outside an
// operation's domain contribute nothing to its result.
#include <cmath>
#include <cstdint>
#include <limits>

#include "expr/opcode.hpp"

namespace zs {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;

  static constexpr Interval point(double v) { return {v, v}; }
  static constexpr Interval whole() {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  static constexpr Interval empty() {
    return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  }
  // NaN endpoints count as empty as well, so no rule can ever hand on a NaN unnoticed.
  constexpr bool isEmpty() const { return !(lo <= hi); }
  constexpr bool contains(double v) const { return lo <= v && v <= hi; }
  constexpr bool containsZero() const { return lo <= 0.0 && 0.0 <= hi; }
  constexpr bool isPoint() const { return lo == hi; }
};

constexpr bool operator==(Interval a, Interval b) {
  return a.lo == b.lo && a.hi == b.hi;
}

// Smallest interval holding both (the empty interval is the identity).
Interval hull(Interval a, Interval b);
// Largest interval inside both; empty when they do not meet.
Interval intersect(Interval a, Interval b);

namespace ia {
Interval neg(Interval a);
Interval add(Interval a, Interval b);
Interval sub(Interval a, Interval b);
Interval mul(Interval a, Interval b);
Interval div(Interval a, Interval b);
Interval powi(Interval a, int n);
Interval pow(Interval a, Interval b);
Interval sqrt(Interval a);
Interval cbrt(Interval a);
Interval exp(Interval a);
Interval log(Interval a);
Interval sin(Interval a);
Interval cos(Interval a);
Interval tan(Interval a);
Interval asin(Interval a);
Interval acos(Interval a);
Interval atan(Interval a);
Interval atan2(Interval y, Interval x);
Interval sinh(Interval a);
Interval cosh(Interval a);
Interval tanh(Interval a);
Interval abs(Interval a);
Interval sign(Interval a);
Interval floor(Interval a);
Interval ceil(Interval a);
Interval min(Interval a, Interval b);
Interval max(Interval a, Interval b);
}  // namespace ia

// The rule for one tape instruction. `value` is a Const's value, `ival` a PowI exponent;
// Param and the variables are resolved by the tape evaluator, not here. An empty operand
// gives an empty result.
Interval applyInterval(Op op, Interval a, Interval b, std::int32_t ival, double value);

}  // namespace zs
