// Every opcode on 100000 random operand boxes: the interval rule must hold the double
// result at sampled points (endpoints, midpoint, random) and MPFI's enclosure.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "expr/tape.hpp"
#include "interval/interval.hpp"
#include "mpfi_oracle.hpp"
#include "random_boxes.hpp"

namespace zs {
namespace {

constexpr int kBoxes = 100000;
constexpr int kPointsPerAxis = 4;  // unary: 4 points, binary: 16 pairs per box

bool isLeaf(Op op) {
  return opInfo(op).kind == OpKind::Leaf;
}

std::string show(Interval i) {
  return "[" + std::to_string(i.lo) + ", " + std::to_string(i.hi) + "]";
}

class OpcodeInclusion : public ::testing::TestWithParam<Op> {};

TEST_P(OpcodeInclusion, HoldsSampledPointsAndMpfiEnclosure) {
  const Op op = GetParam();
  const int arity = opInfo(op).arity;
  test::IntervalSampler s(1234u + unsigned(op));
  const int exponents[] = {1, 2, 3, 4, 5, 7, 8, 17, 64, -1, -2, -3, -4, -7};
  long pointChecks = 0, mpfiChecks = 0, failures = 0;
  for (int n = 0; n < kBoxes && failures < 10; ++n) {
    const Interval a = s.interval();
    // Atan2/Pow/Min/Max also see equal operands and integer exponents now and then.
    Interval b = arity == 2 ? (s.pick(8) == 0 ? a : s.interval()) : Interval{};
    if (op == Op::Pow && s.pick(4) == 0) b = Interval::point(double(s.pick(9) - 4));
    const int ival = exponents[s.pick(14)];
    const Interval r = applyInterval(op, a, b, ival, 0.0);
    for (int i = 0; i < kPointsPerAxis; ++i) {
      for (int j = 0; j < (arity == 2 ? kPointsPerAxis : 1); ++j) {
        const double x = s.pointIn(a, i), y = arity == 2 ? s.pointIn(b, j) : 0.0;
        const double v = applyScalar(op, x, y, ival, 0.0);
        if (std::isnan(v)) continue;  // outside the domain: no value to hold
        ++pointChecks;
        if (!r.contains(v) && ++failures <= 10)
          ADD_FAILURE() << opInfo(op).enumName << " n=" << ival << " a=" << show(a)
                        << " b=" << show(b) << " x=" << x << " y=" << y << " value " << v
                        << " not in " << show(r);
      }
    }
    if (const auto ref = test::mpfiApply(op, a, b, ival, 0.0); ref && !ref->isEmpty()) {
      ++mpfiChecks;
      if (!(r.lo <= ref->lo && ref->hi <= r.hi) && ++failures <= 10)
        ADD_FAILURE() << opInfo(op).enumName << " n=" << ival << " a=" << show(a)
                      << " b=" << show(b) << " result " << show(r) << " misses MPFI " << show(*ref);
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(pointChecks, kBoxes);  // most boxes give defined values to check
  RecordProperty("mpfi_checks", std::to_string(mpfiChecks));
}

std::vector<Op> nonLeafOps() {
  std::vector<Op> ops;
  for (int i = 0; i < kOpCount; ++i)
    if (!isLeaf(Op(i))) ops.push_back(Op(i));
  return ops;
}

INSTANTIATE_TEST_SUITE_P(AllOps, OpcodeInclusion, ::testing::ValuesIn(nonLeafOps()),
                         [](const ::testing::TestParamInfo<Op>& info) {
                           return std::string(opInfo(info.param).enumName);
                         });

// Ops with an MPFI counterpart must really be checked against it on most boxes.
TEST(OpcodeInclusion, MpfiCoversTheTranscendentalOps) {
  for (Op op : {Op::Sin, Op::Cos, Op::Tan, Op::Exp, Op::Log, Op::Sqrt, Op::Atan2, Op::Cosh}) {
    const auto ref = test::mpfiApply(op, {0.5, 0.75}, {0.25, 1.0}, 0, 0.0);
    ASSERT_TRUE(ref.has_value()) << opInfo(op).enumName;
    EXPECT_FALSE(ref->isEmpty()) << opInfo(op).enumName;
  }
}

}  // namespace
}  // namespace zs
