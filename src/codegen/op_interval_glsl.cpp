#include "codegen/op_interval_glsl.hpp"

#include <stdexcept>

namespace zs {
namespace {

// prefix + fn(a[, b][, flag]): zsi_ for the interval rules, zsa_ for the affine ones.
std::string call(std::string_view prefix, std::string_view fn, std::string_view a,
                 std::string_view b = {}, std::string_view flag = {}) {
  std::string s(prefix);
  s.append(fn).append("(").append(a);
  if (!b.empty()) s.append(", ").append(b);
  if (!flag.empty()) s.append(", ").append(flag);
  return s + ")";
}
std::string rule(std::string_view fn, std::string_view a, std::string_view b = {},
                 std::string_view flag = {}) {
  return call("zsi_", fn, a, b, flag);
}
std::string affineRule(std::string_view fn, std::string_view a, std::string_view b = {},
                       std::string_view flag = {}) {
  return call("zsa_", fn, a, b, flag);
}

// An opcode with no first-order rule: its interval rule over the operands' ranges.
std::string viaInterval(Op op, std::string_view a, std::string_view b, std::int32_t ival,
                        std::string_view flag) {
  const std::string ra = "zsa_range(" + std::string(a) + ")";
  const std::string rb = b.empty() ? std::string() : "zsa_range(" + std::string(b) + ")";
  return "zsa_fromInterval(" + glslIntervalOpExpression(op, ra, rb, ival, flag) + ")";
}

}  // namespace

std::string glslAffineOpExpression(Op op, std::string_view a, std::string_view b, std::int32_t ival,
                                   std::string_view flag) {
  switch (op) {
    case Op::Const:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
      throw std::logic_error("glslAffineOpExpression: leaves are emitted by the emitter");
    case Op::Neg:
      return affineRule("neg", a);
    case Op::Add:
      return affineRule("add", a, b);
    case Op::Sub:
      return affineRule("sub", a, b);
    case Op::Mul:
      return affineRule("mul", a, b);
    case Op::Div:
      return affineRule("div", a, b);
    case Op::PowI:
      return ival == 2 ? affineRule("sqr", a) : affineRule("powi", a, std::to_string(ival));
    case Op::Sqrt:
      return affineRule("sqrt", a, {}, flag);
    case Op::Log:
      return affineRule("log", a, {}, flag);
    case Op::Sin:
      return affineRule("sin", a);
    case Op::Cos:
      return affineRule("cos", a);
    case Op::Exp:
      return affineRule("exp", a);
    case Op::Abs:
      return affineRule("abs", a);
    case Op::Min:
      return affineRule("min", a, b);
    case Op::Max:
      return affineRule("max", a, b);
    // No first-order rule (yet): rarer functions, and the steps and jumps, which have none.
    case Op::Pow:
    case Op::Asin:
    case Op::Acos:
    case Op::Tan:
    case Op::Atan:
    case Op::Atan2:
    case Op::Sinh:
    case Op::Cosh:
    case Op::Tanh:
    case Op::Cbrt:
    case Op::Sign:
    case Op::Floor:
    case Op::Ceil:
      return viaInterval(op, a, b, ival, flag);
    case Op::IfDefined:
      throw std::logic_error("glslAffineOpExpression: IfDefined is emitted with its flags");
  }
  throw std::logic_error("glslAffineOpExpression: opcode out of range");
}

bool affineOpIsPolynomial(Op op, std::int32_t ival) {
  return op == Op::Neg || op == Op::Add || op == Op::Sub || op == Op::Mul ||
         (op == Op::PowI && ival == 2);
}

std::string glslIntervalOpExpression(Op op, std::string_view a, std::string_view b,
                                     std::int32_t ival, std::string_view flag) {
  switch (op) {
    case Op::Const:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
      throw std::logic_error("glslIntervalOpExpression: leaves are emitted by the emitter");
    case Op::Neg:
      return rule("neg", a);
    case Op::Add:
      return rule("add", a, b);
    case Op::Sub:
      return rule("sub", a, b);
    case Op::Mul:
      return rule("mul", a, b);
    case Op::Div:
      return rule("div", a, b);
    case Op::PowI:
      return rule("powi", a, std::to_string(ival));
    // Undefined on a whole interval: the flag, as the point rules set theirs.
    case Op::Pow:
      return rule("pow", a, b, flag);
    case Op::Sqrt:
      return rule("sqrt", a, {}, flag);
    case Op::Log:
      return rule("log", a, {}, flag);
    case Op::Asin:
      return rule("asin", a, {}, flag);
    case Op::Acos:
      return rule("acos", a, {}, flag);
    case Op::Sin:
      return rule("sin", a);
    case Op::Cos:
      return rule("cos", a);
    case Op::Tan:
      return rule("tan", a);
    case Op::Atan:
      return rule("atan", a);
    case Op::Atan2:
      return rule("atan2", a, b);
    case Op::Sinh:
      return rule("sinh", a);
    case Op::Cosh:
      return rule("cosh", a);
    case Op::Tanh:
      return rule("tanh", a);
    case Op::Exp:
      return rule("exp", a);
    case Op::Cbrt:
      return rule("cbrt", a);
    case Op::Abs:
      return rule("abs", a);
    case Op::Sign:
      return rule("sign", a);
    case Op::Floor:
      return rule("floor", a);
    case Op::Ceil:
      return rule("ceil", a);
    case Op::Min:
      return rule("min", a, b);
    case Op::Max:
      return rule("max", a, b);
    case Op::IfDefined:
      throw std::logic_error("glslIntervalOpExpression: IfDefined is emitted with its flags");
  }
  throw std::logic_error("glslIntervalOpExpression: opcode out of range");
}

}  // namespace zs
