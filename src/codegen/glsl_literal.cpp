#include "codegen/glsl_literal.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "expr/number_text.hpp"

namespace zs {
namespace {

// Shortest decimal that reads back (as a double, then rounded to float, which is what
// glslang and the drivers do) to exactly f; made into a GLSL float literal, which needs a
// '.' or an exponent ("2" would be an int).
std::string shortestFloatText(float f) {
  std::string text = shortestText(f);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

}  // namespace

GlslLiteral glslFloatLiteral(double value) {
  constexpr double kMax = std::numeric_limits<float>::max();
  constexpr double kMin = std::numeric_limits<float>::min();  // smallest normal
  if (std::isnan(value)) return {"0.0", LiteralKind::NotANumber};
  if (value == 0.0) return {"0.0", LiteralKind::Nearest};
  const double magnitude = std::fabs(value);
  const float sign = value < 0 ? -1.0f : 1.0f;
  // Checked before the cast: converting a double beyond float range is undefined in C++.
  if (magnitude > kMax) {
    return {shortestFloatText(sign * std::numeric_limits<float>::max()), LiteralKind::ClampedHuge};
  }
  if (magnitude < kMin) {
    // Values between FLT_MIN/2 and FLT_MIN would round to FLT_MIN anyway; below they would
    // become denormals or zero. Either way the literal says FLT_MIN.
    return {shortestFloatText(sign * std::numeric_limits<float>::min()), LiteralKind::ClampedTiny};
  }
  return {shortestFloatText(static_cast<float>(value)), LiteralKind::Nearest};
}

}  // namespace zs
