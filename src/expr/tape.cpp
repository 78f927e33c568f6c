#include "expr/tape.hpp"

#include <cassert>
#include <cmath>

namespace zs {

double applyScalar(Op op, double a, double b, std::int32_t ival, double value) {
  switch (op) {
    case Op::Const:
      return value;
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
      assert(false && "leaves are loaded by the evaluator");
      return NAN;
    case Op::Neg:
      return -a;
    case Op::Add:
      return a + b;
    case Op::Sub:
      return a - b;
    case Op::Mul:
      return a * b;
    case Op::Div:
      return a / b;
    case Op::PowI:
      return powInt(a, ival);
    case Op::Pow:
      return std::pow(a, b);
    case Op::Sin:
      return std::sin(a);
    case Op::Cos:
      return std::cos(a);
    case Op::Tan:
      return std::tan(a);
    case Op::Asin:
      return std::asin(a);
    case Op::Acos:
      return std::acos(a);
    case Op::Atan:
      return std::atan(a);
    case Op::Atan2:
      return std::atan2(a, b);
    case Op::Sinh:
      return std::sinh(a);
    case Op::Cosh:
      return std::cosh(a);
    case Op::Tanh:
      return std::tanh(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return a < 0 ? NAN : std::log(a);
    case Op::Sqrt:
      return std::sqrt(a);
    case Op::Cbrt:
      return std::cbrt(a);
    case Op::Abs:
      return std::fabs(a);
    case Op::Sign:
      return std::isnan(a) ? a : double((a > 0) - (a < 0));
    case Op::Floor:
      return std::floor(a);
    case Op::Ceil:
      return std::ceil(a);
    case Op::Min:
      return std::isnan(a) || std::isnan(b) ? NAN : std::fmin(a, b);
    case Op::Max:
      return std::isnan(a) || std::isnan(b) ? NAN : std::fmax(a, b);
    case Op::IfDefined:
      return std::isnan(a) ? 0.0 : b;
  }
  return NAN;
}

Tape compileTape(const Graph& g, const std::vector<NodeId>& roots) {
  Tape tape;
  tape.paramCount = g.params().size();
  const std::vector<NodeId> order = reachable(g, roots);
  std::vector<std::int32_t> slotOf(g.size(), -1);
  tape.code.reserve(order.size());
  for (NodeId id : order) {
    const Node& n = g[id];
    Instr in{n.op};
    const int arity = opInfo(n.op).arity;
    if (arity >= 1) in.a = slotOf[static_cast<std::size_t>(n.a)];
    if (arity >= 2) in.b = slotOf[static_cast<std::size_t>(n.b)];
    in.value = n.value;
    in.ival = n.ival;
    slotOf[static_cast<std::size_t>(id)] = static_cast<std::int32_t>(tape.code.size());
    tape.code.push_back(in);
  }
  for (NodeId r : roots) tape.outputs.push_back(slotOf[static_cast<std::size_t>(r)]);
  return tape;
}

void PointEvaluator::eval(double x, double y, double z, std::span<const double> params,
                          std::span<double> out) {
  double* s = slots_.data();
  const Instr* code = tape_.code.data();
  const std::size_t n = tape_.code.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Instr& in = code[i];
    switch (in.op) {
      case Op::VarX:
        s[i] = x;
        break;
      case Op::VarY:
        s[i] = y;
        break;
      case Op::VarZ:
        s[i] = z;
        break;
      case Op::Param:
        s[i] = static_cast<std::size_t>(in.ival) < params.size() ? params[in.ival] : NAN;
        break;
      default:
        s[i] = applyScalar(in.op, in.a >= 0 ? s[in.a] : 0.0, in.b >= 0 ? s[in.b] : 0.0, in.ival,
                           in.value);
    }
  }
  for (std::size_t k = 0; k < tape_.outputs.size() && k < out.size(); ++k) {
    out[k] = s[tape_.outputs[k]];
  }
}

double PointEvaluator::eval1(double x, double y, double z, std::span<const double> params) {
  double v = NAN;
  eval(x, y, z, params, std::span<double>(&v, 1));
  return v;
}

}  // namespace zs
