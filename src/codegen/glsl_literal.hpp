#pragma once
// GLSL float literals: takes a double constant of the expression graph, puts out the text of
// a GLSL float literal for the float nearest to it, with the fewest digits that read back to
// exactly that float. Values that have no float counterpart are mapped deliberately:
//   |v| > FLT_MAX (and +-inf)    -> +-FLT_MAX   (GLSL need not support infinities)
//   0 < |v| < FLT_MIN            -> +-FLT_MIN   (stays non-zero with its sign; GPUs flush
//                                                denormals, so those are not used either)
//   -0.0                         -> 0.0
//   NaN                          -> 0.0, marked NotANumber: the emitter flags F undefined
// The text of a negative value starts with '-'; callers parenthesize it where needed.
#include <string>

namespace zs {

enum class LiteralKind {
  Nearest,      // the float nearest to the value (exact when the value is a float)
  ClampedHuge,  // magnitude too large for a float
  ClampedTiny,  // non-zero magnitude below the smallest normal float
  NotANumber,
};

struct GlslLiteral {
  std::string text;
  LiteralKind kind = LiteralKind::Nearest;
};

GlslLiteral glslFloatLiteral(double value);

}  // namespace zs
