#pragma once
// The interval GLSL of one operation: takes an opcode and the GLSL names of its operands'
// intervals (vec2 temporaries or literals), puts out the right-hand side of the vec2 that
// encloses its result; likewise for affine forms along a ray segment (vec3, below). One zsi_* rule
// of shaders/templates/interval_prelude.frag.glsl per opcode, switched over the single opcode table
// like the CPU's applyInterval (src/interval/apply.cpp), so a new opcode fails the build in both
// until it has a rule.
#include <cstdint>
#include <string>
#include <string_view>

#include "expr/opcode.hpp"

namespace zs {

// Not for leaves (Const, VarX/Y/Z, Param): the interval emitter writes those itself.
// `ival` is PowI's exponent; `flag` the bool set where the operation is undefined on the
// whole operand interval (sqrt, log, asin, acos, pow).
std::string glslIntervalOpExpression(Op op, std::string_view a, std::string_view b,
                                     std::int32_t ival, std::string_view flag);

// The same for the affine forms along the ray (vec3, shaders/templates/affine_prelude.frag.glsl):
// a zsa_* rule where the opcode has a first-order one, else its interval rule on the
// operands' ranges, zsa_fromInterval(zsi_<rule>(zsa_range(a), ...)), with the same flags.
std::string glslAffineOpExpression(Op op, std::string_view a, std::string_view b, std::int32_t ival,
                                   std::string_view flag);

// Whether the affine rule of `op` is a polynomial one (neg, add, sub, mul, square), which
// leaves its rounding for zsa_settle (affine_prelude.frag.glsl); every other rule takes
// settled operands and returns a settled form.
bool affineOpIsPolynomial(Op op, std::int32_t ival);

}  // namespace zs
