#pragma once
// The GLSL spelling of one operation: takes an opcode and the GLSL text of its operands
// (temporary names or literals, never compound expressions), puts out the right-hand side of
// the temporary that holds its result. Operations with a restricted domain call a prelude
// helper (shaders/templates/raytrace_prelude.frag.glsl) that also sets the bool `flag`
// where the operation is undefined; see docs/codegen.md for the rules.
#include <string>
#include <string_view>

#include "expr/opcode.hpp"

namespace zs {

// Not for leaves (Const, VarX/Y/Z, Param) or PowI: the emitter writes those itself.
std::string glslOpExpression(Op op, std::string_view a, std::string_view b, std::string_view flag);

// True when the operation's helper takes the undefined flag (sqrt, log, asin, acos, pow, /).
bool opCanBeUndefined(Op op);

}  // namespace zs
