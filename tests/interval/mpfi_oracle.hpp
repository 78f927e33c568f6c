#pragma once
// A high-precision reference for the interval rules: MPFI (128-bit interval arithmetic with
// correct outward rounding) applied to one operation or a whole tape, converted back to
// doubles outward. The interval rules must contain what it returns.
#include <optional>
#include <span>
#include <vector>

#include "expr/tape.hpp"
#include "interval/hierarchy.hpp"
#include "interval/interval.hpp"

namespace zs::test {

// Nothing for operations MPFI has no counterpart for (sign, floor, ceil, min, max are exact
// in double and checked at points only), for pow with a negative base and a non-integer or
// non-point exponent, and for division by an interval holding 0 (the rule answers the whole line
// there).
std::optional<Interval> mpfiApply(Op op, Interval a, Interval b, int ival, double value);

// MPFI run of a whole tape over a box; nothing when some instruction has no MPFI rule.
std::optional<std::vector<Interval>> mpfiTape(const Tape& tape, const Box& box,
                                              std::span<const double> params);

}  // namespace zs::test
