#pragma once
// Outward rounding helpers for the interval rules (internal to src/interval).
//
// +, -, *, / and sqrt are correctly rounded in IEEE 754, and rounding to nearest is monotone,
// so moving a round-to-nearest endpoint one ulp outward encloses both the exact result and
// every double-precision result at points of the operands. glibc's elementary functions
// are not correctly rounded (its documented errors for double are at most a few ulps), so
// their endpoints move kLibmUlps outward.
#include <cmath>
#include <cstdint>
#include <limits>

#include "expr/bit_cast.hpp"

namespace zs::detail {

inline constexpr int kLibmUlps = 4;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// std::nextafter(v, +-inf), inlined: stepping the bit pattern moves one ulp away from or
// towards zero (the evaluator spends a large share of its time here otherwise).
inline double up(double v) {
  if (!(v < kInf)) return v;  // +inf and NaN stay
  if (v == 0.0) return std::numeric_limits<double>::denorm_min();
  const auto bits = bitCast<std::uint64_t>(v);
  return bitCast<double>(v > 0 ? bits + 1 : bits - 1);
}
inline double down(double v) {
  return -up(-v);
}

inline double down(double v, int ulps) {
  for (int i = 0; i < ulps; ++i) v = down(v);
  return v;
}
inline double up(double v, int ulps) {
  for (int i = 0; i < ulps; ++i) v = up(v);
  return v;
}

// Elementary-function endpoints: kLibmUlps outward, then clamped to the function's range
// (the clamp can only tighten, never lose a true value).
inline double libmDown(double v, double rangeLo = -kInf) {
  return std::fmax(down(v, kLibmUlps), rangeLo);
}
inline double libmUp(double v, double rangeHi = kInf) {
  return std::fmin(up(v, kLibmUlps), rangeHi);
}

}  // namespace zs::detail
