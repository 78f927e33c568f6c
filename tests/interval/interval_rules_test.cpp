// The tightness and domain rules the issue names, each on a hand-picked case.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "expr/tape.hpp"
#include "interval/interval.hpp"

namespace zs {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Within a few ulps of [lo, hi] and holding it.
void expectNear(Interval r, double lo, double hi) {
  EXPECT_LE(r.lo, lo);
  EXPECT_GE(r.hi, hi);
  if (std::isfinite(lo))
    EXPECT_NEAR(r.lo, lo, 1e-12 * (1 + std::fabs(lo)));
  else
    EXPECT_EQ(r.lo, lo);
  if (std::isfinite(hi))
    EXPECT_NEAR(r.hi, hi, 1e-12 * (1 + std::fabs(hi)));
  else
    EXPECT_EQ(r.hi, hi);
}

TEST(IntervalRules, EvenPowersAreTightAroundZero) {
  expectNear(ia::powi({-1, 2}, 2), 0, 4);
  EXPECT_EQ(ia::powi({-1, 2}, 2).lo, 0.0);
  expectNear(ia::powi({-2, 1}, 4), 0, 16);
  expectNear(ia::powi({-2, -1}, 3), -8, -1);
  expectNear(ia::powi({-2, 3}, -2), 1.0 / 9, kInf);
  expectNear(ia::powi({1, 2}, -1), 0.5, 1);
}

TEST(IntervalRules, DivisionByAnIntervalHoldingZeroIsTheWholeLine) {
  for (Interval b : {Interval{-1, 1}, Interval{0, 1}, Interval{-1, 0}, Interval{0, 0}}) {
    const Interval r = ia::div({1, 2}, b);
    EXPECT_EQ(r, Interval::whole());
  }
  expectNear(ia::div({1, 2}, {4, 8}), 0.125, 0.5);
  const Interval r = ia::div(Interval::whole(), {1, kInf});  // inf / inf corners: no NaN
  EXPECT_FALSE(r.isEmpty());
  EXPECT_EQ(r, Interval::whole());
}

TEST(IntervalRules, DomainRestrictedFunctionsIgnoreTheOutsidePart) {
  expectNear(ia::sqrt({-4, 9}), 0, 3);
  EXPECT_TRUE(ia::sqrt({-4, -1}).isEmpty());
  EXPECT_EQ(ia::log({-1, 1}).lo, -kInf);
  EXPECT_TRUE(ia::log({-3, -1}).isEmpty());
  expectNear(ia::asin({0.5, 7}), std::asin(0.5), std::numbers::pi / 2);
  EXPECT_TRUE(ia::acos({1.5, 2}).isEmpty());
  expectNear(ia::pow({-4, 4}, {0.5, 0.5}), 0, 2);  // negative bases: outside the domain
  EXPECT_TRUE(ia::pow({-4, -1}, {0.5, 0.5}).isEmpty());
  expectNear(ia::pow({-2, -1}, {3, 3}), -8, -1);  // integer exponent: negative bases are fine
}

TEST(IntervalRules, UndefinedPropagatesThroughEveryOperation) {
  const Interval e = Interval::empty();
  for (int i = 0; i < kOpCount; ++i) {
    const Op op = Op(i);
    if (opInfo(op).arity == 0 || op == Op::IfDefined) continue;  // the one that stops it
    EXPECT_TRUE(applyInterval(op, e, {1, 2}, 2, 0).isEmpty()) << opInfo(op).enumName;
    if (opInfo(op).arity == 2) {
      EXPECT_TRUE(applyInterval(op, {1, 2}, e, 2, 0).isEmpty()) << opInfo(op).enumName;
    }
  }
}

// b where a is defined, else 0: an interval does not say whether a was defined on all of the
// box, so 0 joins b wherever a is defined somewhere.
TEST(IntervalRules, IfDefinedIsBWhereAIsDefinedAndZeroElsewhere) {
  const Interval e = Interval::empty();
  EXPECT_EQ(applyInterval(Op::IfDefined, e, {3, 4}, 0, 0), Interval::point(0));
  EXPECT_EQ(applyInterval(Op::IfDefined, {1, 2}, {3, 4}, 0, 0), (Interval{0, 4}));
  EXPECT_EQ(applyInterval(Op::IfDefined, {1, 2}, {-4, -3}, 0, 0), (Interval{-4, 0}));
  EXPECT_EQ(applyInterval(Op::IfDefined, {1, 2}, e, 0, 0), Interval::point(0));
  EXPECT_EQ(applyScalar(Op::IfDefined, NAN, 5, 0, 0), 0.0);
  EXPECT_EQ(applyScalar(Op::IfDefined, 1, 5, 0, 0), 5.0);
  EXPECT_TRUE(std::isnan(applyScalar(Op::IfDefined, 1, NAN, 0, 0)));
}

TEST(IntervalRules, SinAndCosIncludeTheExtremaInside) {
  expectNear(ia::sin({0, 1}), 0, std::sin(1.0));
  expectNear(ia::sin({1, 2}), std::sin(1.0), 1);
  expectNear(ia::sin({4, 5}), -1, std::sin(4.0));
  expectNear(ia::cos({-1, 1}), std::cos(1.0), 1);
  expectNear(ia::cos({3, 3.2}), -1, std::cos(3.0));  // pi is inside
  EXPECT_EQ(ia::sin({0, 100}), (Interval{-1, 1}));
  EXPECT_EQ(ia::cos(Interval::whole()), (Interval{-1, 1}));
}

TEST(IntervalRules, TanIsTheWholeLineAcrossAPole) {
  EXPECT_EQ(ia::tan({1.5, 1.6}), Interval::whole());
  expectNear(ia::tan({-1, 1}), std::tan(-1.0), std::tan(1.0));
}

TEST(IntervalRules, PiecewiseFunctions) {
  EXPECT_EQ(ia::abs({-3, 2}), (Interval{0, 3}));
  EXPECT_EQ(ia::sign({-3, 2}), (Interval{-1, 1}));
  EXPECT_EQ(ia::sign({0, 2}), (Interval{0, 1}));
  EXPECT_EQ(ia::floor({-1.5, 2.5}), (Interval{-2, 2}));
  EXPECT_EQ(ia::ceil({-1.5, 2.5}), (Interval{-1, 3}));
  EXPECT_EQ(ia::min({0, 5}, {1, 2}), (Interval{0, 2}));
  EXPECT_EQ(ia::max({0, 5}, {1, 2}), (Interval{1, 5}));
  expectNear(ia::cosh({-1, 2}), 1, std::cosh(2.0));
}

TEST(IntervalRules, Atan2CoversTheBranchCut) {
  const Interval r = ia::atan2({-1, 1}, {-2, -1});
  EXPECT_LE(r.lo, -std::numbers::pi);
  EXPECT_GE(r.hi, std::numbers::pi);
  expectNear(ia::atan2({1, 2}, {1, 2}), std::atan2(1.0, 2.0), std::atan2(2.0, 1.0));
}

TEST(IntervalRules, EveryEndpointIsRoundedOutward) {
  const Interval r = ia::add({0.1, 0.1}, {0.2, 0.2});
  EXPECT_LT(r.lo, 0.1 + 0.2);
  EXPECT_GT(r.hi, 0.1 + 0.2);
  const Interval big = ia::mul({1e300, 1e300}, {1e300, 1e300});
  EXPECT_EQ(big.lo, std::numeric_limits<double>::max());  // overflow: finite lower bound
  EXPECT_EQ(big.hi, kInf);
}

}  // namespace
}  // namespace zs
