#pragma once
// The flat tape: the reachable part of a graph for a set of roots (F, or F and its gradient),
// as a straight-line program of instructions. Slot i holds the result of instruction i,
// operands always refer to earlier slots. Point and interval evaluators both run it.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

struct Instr {
  Op op;
  std::int32_t a = -1;  // operand slots
  std::int32_t b = -1;
  double value = 0.0;     // Const
  std::int32_t ival = 0;  // PowI exponent / Param index
};

struct Tape {
  std::vector<Instr> code;
  std::vector<std::int32_t> outputs;  // slot of each root, in the order given
  std::size_t paramCount = 0;
};

Tape compileTape(const Graph& g, const std::vector<NodeId>& roots);

// base^n by repeated squaring: the same association the GLSL emitter uses.
inline double powInt(double base, std::int32_t n) {
  std::uint32_t k = n < 0 ? static_cast<std::uint32_t>(-static_cast<std::int64_t>(n))
                          : static_cast<std::uint32_t>(n);
  double result = 1.0, square = base;
  while (k) {
    if (k & 1u) result *= square;
    k >>= 1u;
    if (k) square *= square;
  }
  return n < 0 ? 1.0 / result : result;
}

// Double-precision scalar semantics of one operation (NaN outside the domain).
double applyScalar(Op op, double a, double b, std::int32_t ival, double value);

// Evaluates a tape at a point. Owns a copy of the tape and reuses its scratch buffer between
// calls; not thread-safe, make one per thread.
class PointEvaluator {
 public:
  explicit PointEvaluator(Tape tape) : tape_(std::move(tape)), slots_(tape_.code.size()) {}
  // Fills `out` (one value per tape output). params: one value per graph parameter.
  void eval(double x, double y, double z, std::span<const double> params, std::span<double> out);
  double eval1(double x, double y, double z, std::span<const double> params = {});

 private:
  Tape tape_;
  std::vector<double> slots_;
};

}  // namespace zs
