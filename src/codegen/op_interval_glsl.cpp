#include "codegen/op_interval_glsl.hpp"

#include <stdexcept>

namespace zs {
namespace {

std::string rule(std::string_view fn, std::string_view a, std::string_view b = {},
                 std::string_view flag = {}) {
  std::string s = "zsi_";
  s.append(fn).append("(").append(a);
  if (!b.empty()) s.append(", ").append(b);
  if (!flag.empty()) s.append(", ").append(flag);
  return s + ")";
}

}  // namespace

std::string glslIntervalOpExpression(Op op, std::string_view a, std::string_view b,
                                     std::int32_t ival, std::string_view flag) {
  switch (op) {
    case Op::Const: case Op::VarX: case Op::VarY: case Op::VarZ: case Op::Param:
      throw std::logic_error("glslIntervalOpExpression: leaves are emitted by the emitter");
    case Op::Neg: return rule("neg", a);
    case Op::Add: return rule("add", a, b);
    case Op::Sub: return rule("sub", a, b);
    case Op::Mul: return rule("mul", a, b);
    case Op::Div: return rule("div", a, b);
    case Op::PowI: return rule("powi", a, std::to_string(ival));
    // Undefined on a whole interval: the flag, as the point rules set theirs.
    case Op::Pow: return rule("pow", a, b, flag);
    case Op::Sqrt: return rule("sqrt", a, {}, flag);
    case Op::Log: return rule("log", a, {}, flag);
    case Op::Asin: return rule("asin", a, {}, flag);
    case Op::Acos: return rule("acos", a, {}, flag);
    case Op::Sin: return rule("sin", a);
    case Op::Cos: return rule("cos", a);
    case Op::Tan: return rule("tan", a);
    case Op::Atan: return rule("atan", a);
    case Op::Atan2: return rule("atan2", a, b);
    case Op::Sinh: return rule("sinh", a);
    case Op::Cosh: return rule("cosh", a);
    case Op::Tanh: return rule("tanh", a);
    case Op::Exp: return rule("exp", a);
    case Op::Cbrt: return rule("cbrt", a);
    case Op::Abs: return rule("abs", a);
    case Op::Sign: return rule("sign", a);
    case Op::Floor: return rule("floor", a);
    case Op::Ceil: return rule("ceil", a);
    case Op::Min: return rule("min", a, b);
    case Op::Max: return rule("max", a, b);
  }
  throw std::logic_error("glslIntervalOpExpression: opcode out of range");
}

}  // namespace zs
