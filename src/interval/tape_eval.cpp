#include "interval/tape_eval.hpp"

#include <cassert>

namespace zs {

IntervalEvaluator::IntervalEvaluator(const Tape& tape) : tape_(tape), slots_(tape.code.size()) {
  firstEnd_ = tape.outputs.empty() ? 0 : static_cast<std::size_t>(tape.outputs.front()) + 1;
}

void IntervalEvaluator::run(std::size_t begin, std::size_t end, std::span<const double> params) {
  assert(params.size() >= tape_.paramCount);
  for (std::size_t i = begin; i < end; ++i) {
    const Instr& in = tape_.code[i];
    Interval a{}, b{};
    switch (opInfo(in.op).arity) {
      case 2:
        b = slots_[static_cast<std::size_t>(in.b)];
        [[fallthrough]];
      case 1:
        a = slots_[static_cast<std::size_t>(in.a)];
        break;
      default:
        break;
    }
    if (in.op == Op::VarX)
      a = {box_.min[0], box_.max[0]};
    else if (in.op == Op::VarY)
      a = {box_.min[1], box_.max[1]};
    else if (in.op == Op::VarZ)
      a = {box_.min[2], box_.max[2]};
    else if (in.op == Op::Param)
      a = Interval::point(params[static_cast<std::size_t>(in.ival)]);
    slots_[i] = applyInterval(in.op, a, b, in.ival, in.value);
  }
}

Interval IntervalEvaluator::evalFirst(const Box& box, std::span<const double> params) {
  box_ = box;
  run(0, firstEnd_, params);
  return firstEnd_ == 0 ? Interval::empty() : slots_[firstEnd_ - 1];
}

void IntervalEvaluator::evalRest(std::span<const double> params, std::span<Interval> out) {
  run(firstEnd_, slots_.size(), params);
  assert(out.size() >= tape_.outputs.size());
  for (std::size_t k = 0; k < tape_.outputs.size(); ++k)
    out[k] = slots_[static_cast<std::size_t>(tape_.outputs[k])];
}

void IntervalEvaluator::eval(const Box& box, std::span<const double> params,
                             std::span<Interval> out) {
  evalFirst(box, params);
  evalRest(params, out);
}

Interval IntervalEvaluator::eval1(const Box& box, std::span<const double> params) {
  return evalFirst(box, params);
}

}  // namespace zs
