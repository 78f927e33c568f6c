#include "codegen/op_glsl.hpp"

#include <stdexcept>

namespace zs {
namespace {

std::string infix(std::string_view a, std::string_view op, std::string_view b) {
  std::string s;
  s.append(a).append(" ").append(op).append(" ").append(b);
  return s;
}

std::string call(std::string_view fn, std::string_view a) {
  std::string s;
  s.append(fn).append("(").append(a).append(")");
  return s;
}

std::string call(std::string_view fn, std::string_view a, std::string_view b) {
  std::string s;
  s.append(fn).append("(").append(a).append(", ").append(b).append(")");
  return s;
}

// A helper with an undefined flag as its last (inout) argument; b empty for unary helpers.
std::string flagged(std::string_view fn, std::string_view a, std::string_view b,
                    std::string_view flag) {
  std::string s;
  s.append(fn).append("(").append(a);
  if (!b.empty()) s.append(", ").append(b);
  s.append(", ").append(flag).append(")");
  return s;
}

}  // namespace

bool opCanBeUndefined(Op op) {
  switch (op) {
    case Op::Div:
    case Op::Pow:
    case Op::Asin:
    case Op::Acos:
    case Op::Log:
    case Op::Sqrt:
      return true;
    case Op::Const:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::PowI:
    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Atan:
    case Op::Atan2:
    case Op::Sinh:
    case Op::Cosh:
    case Op::Tanh:
    case Op::Exp:
    case Op::Cbrt:
    case Op::Abs:
    case Op::Sign:
    case Op::Floor:
    case Op::Ceil:
    case Op::Min:
    case Op::Max:
    case Op::IfDefined:  // it stops undefinedness (body_writer.cpp)
      return false;
  }
  return false;
}

std::string glslOpExpression(Op op, std::string_view a, std::string_view b, std::string_view flag) {
  const std::string_view glsl = opInfo(op).glsl;
  switch (op) {
    case Op::Const:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
    case Op::PowI:
      throw std::logic_error("glslOpExpression: leaves and PowI are emitted by the emitter");

    // Operands are names or (parenthesized when negative) literals, so no precedence issue.
    case Op::Neg:
      return std::string("-").append(a);
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
      return infix(a, glsl, b);

    // GLSL leaves all of these undefined somewhere (x/0, pow(x<0, y), sqrt(x<0), log(x<=0),
    // asin/acos(|x|>1)); the helpers give them fixed values and report the domain.
    case Op::Div:
      return flagged("zs_div", a, b, flag);
    case Op::Pow:
      return flagged("zs_pow", a, b, flag);
    case Op::Asin:
      return flagged("zs_asin", a, {}, flag);
    case Op::Acos:
      return flagged("zs_acos", a, {}, flag);
    case Op::Log:
      return flagged("zs_log", a, {}, flag);
    case Op::Sqrt:
      return flagged("zs_sqrt", a, {}, flag);

    // atan(y, x) is undefined at (0, 0) in GLSL (atan2 gives 0 in C); cbrt has no GLSL
    // built-in; tanh overflows to inf/inf in naive driver implementations.
    case Op::Atan2:
      return call("zs_atan2", a, b);
    case Op::Cbrt:
      return call("zs_cbrt", a);
    case Op::Tanh:
      return call("zs_tanh", a);

    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Atan:
    case Op::Sinh:
    case Op::Cosh:
    case Op::Exp:
    case Op::Abs:
    case Op::Sign:
    case Op::Floor:
    case Op::Ceil:
      return call(glsl, a);
    case Op::Min:
    case Op::Max:
      return call(glsl, a, b);
    case Op::IfDefined:
      throw std::logic_error("glslOpExpression: IfDefined is emitted by the body writer");
  }
  throw std::logic_error("glslOpExpression: opcode out of range");
}

}  // namespace zs
