// The batch evaluator gives, point by point, exactly the point evaluator's value: the mesher
// fills its grid with one and places vertices with the other, and a corner's sign must not
// depend on which one saw it.
#include "expr/batch_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "expr/tape.hpp"
#include "parsed.hpp"

namespace zs {
namespace {

using test::parsed;

bool sameBits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

class BatchEvalTest : public ::testing::TestWithParam<const char*> {};

TEST_P(BatchEvalTest, MatchesThePointEvaluatorBitForBit) {
  const Formula f = parsed(GetParam());
  const Tape tape = compileTape(f.graph, {f.root});
  const std::vector<double> params{0.3, -1.25, 2.0};
  // A count that is not a multiple of the pass width, so the last pass is partial.
  const std::size_t count = 3 * BatchEvaluator::kWidth + 17;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-2.5, 2.5);
  std::vector<double> xs(count), ys(count), zs(count), out(count);
  for (std::size_t k = 0; k < count; ++k)
    xs[k] = coord(rng), ys[k] = coord(rng), zs[k] = coord(rng);
  xs[5] = 0, ys[5] = 0, zs[5] = 0;  // poles and domain edges at the origin
  BatchEvaluator batch(tape);
  batch.eval(xs, ys, zs, params, out);
  PointEvaluator point(tape);
  for (std::size_t k = 0; k < count; ++k) {
    const double expected = point.eval1(xs[k], ys[k], zs[k], params);
    ASSERT_TRUE(sameBits(out[k], expected))
        << GetParam() << " at (" << xs[k] << ", " << ys[k] << ", " << zs[k] << "): batch " << out[k]
        << ", point " << expected;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Formulas, BatchEvalTest,
    ::testing::Values(
        "x^2 + y^2 + z^2 - 1", "x^3*y + y^3*z + z^3*x", "(x + y + z)^7 - x^-3",
        "4*(2.618*x^2 - y^2)*(2.618*y^2 - z^2)*(2.618*z^2 - x^2) - 4.236*(x^2 + y^2 + z^2 - 1)^2",
        "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", "1/x - 1", "sqrt(x) - 0.5",
        "log(x^2 + y^2 + z^2)", "exp(-4*(x^2 + y^2)) - 0.6 + a*z",
        "atan2(y, x) + min(x, b) - max(y, c) + abs(z)", "pow(y^2 + 2, x) + x^y^2",
        "tan(x) + asin(y) + acos(z) + sinh(x) + cosh(y) + tanh(z) + cbrt(x)",
        "sign(x) + floor(y) + ceil(z) - 7"));

}  // namespace
}  // namespace zs
