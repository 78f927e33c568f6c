#pragma once
// A tape evaluated at many points at once: instruction by instruction over arrays of points,
// so the dispatch on the opcode is paid once per instruction instead of once per point and
// the arithmetic loops vectorize. Each point's value is bit-for-bit what PointEvaluator
// gives (the same scalar operations in the same order), so callers may mix the two. The
// mesher fills its grid with it: millions of points, tens of instructions each.
#include <span>
#include <vector>

#include "expr/tape.hpp"

namespace zs {

// Owns a copy of the tape and its scratch slots; not thread-safe, make one per thread.
class BatchEvaluator {
 public:
  static constexpr std::size_t kWidth = 128;  // points per pass: the slots stay in cache

  explicit BatchEvaluator(Tape tape);

  // out[k] = the tape's first output at (xs[k], ys[k], zs[k]); any number of points.
  void eval(std::span<const double> xs, std::span<const double> ys, std::span<const double> zs,
            std::span<const double> params, std::span<double> out);
  // Every output: out[k * outputs + o] = output o at point k (out holds points x outputs).
  void evalAll(std::span<const double> xs, std::span<const double> ys, std::span<const double> zs,
               std::span<const double> params, std::span<double> out);
  std::size_t outputs() const { return tape_.outputs.size(); }

 private:
  void pass(const double* xs, const double* ys, const double* zs, std::size_t count,
            std::span<const double> params);

  Tape tape_;
  std::vector<double> slots_;  // kWidth per instruction
};

}  // namespace zs
