#include "expr/batch_eval.hpp"

#include <cmath>

namespace zs {

BatchEvaluator::BatchEvaluator(Tape tape)
    : tape_(std::move(tape)), slots_(tape_.code.size() * kWidth) {}

void BatchEvaluator::eval(std::span<const double> xs, std::span<const double> ys,
                          std::span<const double> zs, std::span<const double> params,
                          std::span<double> out) {
  const double* result = &slots_[std::size_t(tape_.outputs.front()) * kWidth];
  for (std::size_t at = 0; at < out.size(); at += kWidth) {
    const std::size_t count = std::min(kWidth, out.size() - at);
    pass(xs.data() + at, ys.data() + at, zs.data() + at, count, params);
    std::copy(result, result + count, out.data() + at);
  }
}

void BatchEvaluator::evalAll(std::span<const double> xs, std::span<const double> ys,
                             std::span<const double> zs, std::span<const double> params,
                             std::span<double> out) {
  const std::size_t outputs = tape_.outputs.size(), points = out.size() / outputs;
  for (std::size_t at = 0; at < points; at += kWidth) {
    const std::size_t count = std::min(kWidth, points - at);
    pass(xs.data() + at, ys.data() + at, zs.data() + at, count, params);
    for (std::size_t o = 0; o < outputs; ++o) {
      const double* result = &slots_[std::size_t(tape_.outputs[o]) * kWidth];
      for (std::size_t k = 0; k < count; ++k) out[(at + k) * outputs + o] = result[k];
    }
  }
}

void BatchEvaluator::pass(const double* xs, const double* ys, const double* zs, std::size_t count,
                          std::span<const double> params) {
  const std::size_t n = tape_.code.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Instr& in = tape_.code[i];
    double* __restrict s = &slots_[i * kWidth];
    const double* __restrict a = in.a >= 0 ? &slots_[std::size_t(in.a) * kWidth] : nullptr;
    const double* __restrict b = in.b >= 0 ? &slots_[std::size_t(in.b) * kWidth] : nullptr;
    // The common arithmetic gets loops of its own (they vectorize); everything else goes
    // through applyScalar, the single definition of each operation's value.
    switch (in.op) {
      case Op::VarX:
        std::copy(xs, xs + count, s);
        break;
      case Op::VarY:
        std::copy(ys, ys + count, s);
        break;
      case Op::VarZ:
        std::copy(zs, zs + count, s);
        break;
      case Op::Param:
        std::fill(s, s + count,
                  std::size_t(in.ival) < params.size() ? params[std::size_t(in.ival)] : NAN);
        break;
      case Op::Const:
        std::fill(s, s + count, in.value);
        break;
      case Op::Neg:
        for (std::size_t k = 0; k < count; ++k) s[k] = -a[k];
        break;
      case Op::Add:
        for (std::size_t k = 0; k < count; ++k) s[k] = a[k] + b[k];
        break;
      case Op::Sub:
        for (std::size_t k = 0; k < count; ++k) s[k] = a[k] - b[k];
        break;
      case Op::Mul:
        for (std::size_t k = 0; k < count; ++k) s[k] = a[k] * b[k];
        break;
      case Op::Div:
        for (std::size_t k = 0; k < count; ++k) s[k] = a[k] / b[k];
        break;
      case Op::PowI:
        for (std::size_t k = 0; k < count; ++k) s[k] = powInt(a[k], in.ival);
        break;
      default:
        for (std::size_t k = 0; k < count; ++k)
          s[k] = applyScalar(in.op, a ? a[k] : 0.0, b ? b[k] : 0.0, in.ival, in.value);
    }
  }
}

}  // namespace zs
