// The interval rule of every opcode, in one switch with no default: a new row in
// ZS_OPCODES fails the build here (-Werror=switch) until it has a rule.
#include "interval/interval.hpp"

namespace zs {

Interval applyInterval(Op op, Interval a, Interval b, std::int32_t ival, double value) {
  const int arity = opInfo(op).arity;
  // b where a is defined, else 0. An interval does not say whether its operation was defined
  // on the whole box or on a part of it, so 0 joins b wherever a is defined somewhere.
  if (op == Op::IfDefined)
    return a.isEmpty() ? Interval::point(0.0) : hull(b, Interval::point(0.0));
  // Undefined operands make the result undefined: the formula is defined nowhere there.
  if ((arity >= 1 && a.isEmpty()) || (arity >= 2 && b.isEmpty())) return Interval::empty();
  switch (op) {
    case Op::Const:
      return Interval::point(value);
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
      return a;  // resolved by the tape evaluator, which passes the value in a
    case Op::Neg:
      return ia::neg(a);
    case Op::Add:
      return ia::add(a, b);
    case Op::Sub:
      return ia::sub(a, b);
    case Op::Mul:
      return ia::mul(a, b);
    case Op::Div:
      return ia::div(a, b);
    case Op::PowI:
      return ia::powi(a, ival);
    case Op::Pow:
      return ia::pow(a, b);
    case Op::Sin:
      return ia::sin(a);
    case Op::Cos:
      return ia::cos(a);
    case Op::Tan:
      return ia::tan(a);
    case Op::Asin:
      return ia::asin(a);
    case Op::Acos:
      return ia::acos(a);
    case Op::Atan:
      return ia::atan(a);
    case Op::Atan2:
      return ia::atan2(a, b);
    case Op::Sinh:
      return ia::sinh(a);
    case Op::Cosh:
      return ia::cosh(a);
    case Op::Tanh:
      return ia::tanh(a);
    case Op::Exp:
      return ia::exp(a);
    case Op::Log:
      return ia::log(a);
    case Op::Sqrt:
      return ia::sqrt(a);
    case Op::Cbrt:
      return ia::cbrt(a);
    case Op::Abs:
      return ia::abs(a);
    case Op::Sign:
      return ia::sign(a);
    case Op::Floor:
      return ia::floor(a);
    case Op::Ceil:
      return ia::ceil(a);
    case Op::Min:
      return ia::min(a, b);
    case Op::Max:
      return ia::max(a, b);
    case Op::IfDefined:
      break;  // above
  }
  return Interval::whole();  // unreachable for valid ops; whole is the safe answer
}

}  // namespace zs
