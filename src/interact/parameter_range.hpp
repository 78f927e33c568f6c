#pragma once
// The range a parameter's slider spans, the same in the desktop viewer and the web page:
// value ± max(1, |value|), fixed when the surface is built (a slider that moved its own
// bounds as it was dragged would run away).
#include <algorithm>
#include <cmath>
#include <utility>

namespace zs::interact {

inline std::pair<double, double> paramRange(double value) {
  const double half = std::max(1.0, std::abs(value));
  return {value - half, value + half};
}

}  // namespace zs::interact
