#pragma once
// Interval evaluation of a flat tape: takes a box (x, y, z intervals) and the parameter
// values, puts out one interval per tape output. Compile the tape with roots
// {F, dF/dx, dF/dy, dF/dz} to get F and its interval gradient in one pass.
#include <cstddef>
#include <span>
#include <vector>

#include "expr/tape.hpp"
#include "interval/hierarchy.hpp"
#include "interval/interval.hpp"

namespace zs {

// Reuses its slot buffer between calls: not thread-safe, make one per thread.
class IntervalEvaluator {
 public:
  explicit IntervalEvaluator(const Tape& tape);

  // Fills `out` (one interval per tape output). params: one value per graph parameter.
  void eval(const Box& box, std::span<const double> params, std::span<Interval> out);
  Interval eval1(const Box& box, std::span<const double> params = {});

  // Two-step use, so the gradient is only computed where F may vanish: evalFirst() runs the
  // instructions the first output needs (all of them precede it) and returns it;
  // evalRest() runs the remainder and fills `out` with every output.
  Interval evalFirst(const Box& box, std::span<const double> params);
  void evalRest(std::span<const double> params, std::span<Interval> out);

 private:
  void run(std::size_t begin, std::size_t end, std::span<const double> params);

  const Tape& tape_;
  std::vector<Interval> slots_;
  Box box_;
  std::size_t firstEnd_ = 0;  // one past the first output's slot
};

}  // namespace zs
