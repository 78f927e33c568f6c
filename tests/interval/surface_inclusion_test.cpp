// F and its interval gradient, evaluated in one pass, for the seven thesis surfaces on
// 100000 random boxes each: every sampled point value and MPFI's enclosure of the same
// tape must lie in the result.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "interval/tape_eval.hpp"
#include "mpfi_oracle.hpp"
#include "random_boxes.hpp"
#include "surfaces.hpp"

namespace zs {
namespace {

constexpr int kBoxes = 100000;
constexpr int kPoints = 6;  // per box: two corners, the center, three random points

class SurfaceInclusion : public ::testing::TestWithParam<int> {};

TEST_P(SurfaceInclusion, FAndGradientHoldPointsAndMpfi) {
  const std::string_view text = test::kThesisSurfaces[std::size_t(GetParam())];
  Formula f = test::parseOrDie(text);
  const std::array<NodeId, 3> g = gradient(f.graph, f.root);
  const Tape tape = compileTape(f.graph, {f.root, g[0], g[1], g[2]});
  IntervalEvaluator ie(tape);
  PointEvaluator pe(tape);
  test::IntervalSampler s(99u + unsigned(GetParam()));
  std::array<Interval, 4> r;
  std::array<double, 4> v;
  long failures = 0, pointChecks = 0;
  for (int n = 0; n < kBoxes && failures < 10; ++n) {
    const Box box = s.box();
    ie.eval(box, {}, r);
    auto axis = [&box](int i) {
      return Interval{box.min[std::size_t(i)], box.max[std::size_t(i)]};
    };
    for (int k = 0; k < kPoints; ++k) {
      // k = 0, 1: the min and max corners; 2: the center; then random points
      pe.eval(s.pointIn(axis(0), k), s.pointIn(axis(1), k), s.pointIn(axis(2), k), {}, v);
      for (std::size_t o = 0; o < 4; ++o) {
        if (std::isnan(v[o])) continue;  // inf - inf at huge points: no value to hold
        ++pointChecks;
        if (!r[o].contains(v[o]) && ++failures <= 5)
          ADD_FAILURE() << text << " output " << o << ": point value " << v[o] << " not in ["
                        << r[o].lo << ", " << r[o].hi << "]";
      }
    }
    const auto ref = test::mpfiTape(tape, box, {});
    ASSERT_TRUE(ref.has_value()) << "polynomials always have an MPFI enclosure";
    for (std::size_t o = 0; o < 4; ++o) {
      const Interval m = (*ref)[o];
      if (!(r[o].lo <= m.lo && m.hi <= r[o].hi) && ++failures <= 5)
        ADD_FAILURE() << text << " output " << o << ": [" << r[o].lo << ", " << r[o].hi
                      << "] misses MPFI [" << m.lo << ", " << m.hi << "]";
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(pointChecks, long(kBoxes) * kPoints * 3);
}

INSTANTIATE_TEST_SUITE_P(Thesis, SurfaceInclusion, ::testing::Range(0, 7));

}  // namespace
}  // namespace zs
