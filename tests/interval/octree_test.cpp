// Octree behaviour other than safety: statistics, determinism across thread counts, the
// node budget, input errors, the uniform criterion's area-like growth, the report and CSV.
#include "interval/octree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "interval/report.hpp"
#include "surfaces.hpp"

namespace zs {
namespace {

const Box kCube{{-2, -2, -2}, {2, 2, 2}};

Octree build(const std::string& formula, int level, Criteria c, unsigned threads = 0) {
  OctreeSettings st;
  st.level = level;
  st.criteria = c;
  st.threads = threads;
  OctreeResult r = buildOctree(test::parseOrDie(formula), {}, kCube, st);
  EXPECT_TRUE(std::holds_alternative<Octree>(r));
  return std::get<Octree>(std::move(r));
}

TEST(Octree, UniformSphereLeavesGrowLikeTheArea) {
  std::size_t previous = 0;
  for (int level = 2; level <= 9; ++level) {
    const Octree t = build("x^2+y^2+z^2-1", level, Criteria::Uniform);
    EXPECT_EQ(t.levels[std::size_t(level)].leaves, t.leaves.size());
    for (const OctreeLeaf& l : t.leaves) ASSERT_EQ(l.level, level);
    if (level >= 5) {  // past the coarse levels the ratio settles near 4 (area), far from 8
      const double ratio = double(t.leaves.size()) / double(previous);
      EXPECT_GT(ratio, 3.5) << "level " << level;
      EXPECT_LT(ratio, 4.6) << "level " << level;
    }
    previous = t.leaves.size();
  }
}

TEST(Octree, AClippingBallDropsTheBoxesOutsideItAndKeepsEveryOneThatMeetsTheSurfaceInside) {
  // The plane z = 0.3 in the ball of radius 1 (bounding box [-1, 1]^3), uniform to level 6.
  OctreeSettings st;
  st.level = 6;
  st.criteria = Criteria::Uniform;
  const Box bounds{{-1, -1, -1}, {1, 1, 1}};
  const Formula plane = test::parseOrDie("z - 0.3");
  const Octree box = std::get<Octree>(buildOctree(plane, {}, bounds, st));
  const Octree ball = std::get<Octree>(buildOctree(plane, {}, bounds, st, Ball{{0, 0, 0}, 1.0}));
  ASSERT_TRUE(ball.ball);
  EXPECT_LT(ball.leaves.size(), box.leaves.size());
  // The disc of radius sqrt(1 - 0.09) covers about 0.91 pi / 4 of the square: the leaves
  // follow (plus the cells the rim cuts).
  EXPECT_NEAR(double(ball.leaves.size()) / double(box.leaves.size()), 0.91 * M_PI / 4, 0.06);
  const double cell = 2.0 / 64;
  for (const OctreeLeaf& l : ball.leaves) {  // every leaf meets the ball
    double d2 = 0;
    for (std::size_t a = 0; a < 3; ++a) {
      const double g = std::max({l.box.min[a], -l.box.max[a], 0.0});
      d2 += g * g;
    }
    EXPECT_LE(std::sqrt(d2), 1.0 + 1e-12);
  }
  // Every box leaf that holds a point of the disc inside the ball is kept.
  std::size_t insideBoxLeaves = 0;
  for (const OctreeLeaf& l : box.leaves) {
    const double cx = 0.5 * (l.box.min[0] + l.box.max[0]), cy = 0.5 * (l.box.min[1] + l.box.max[1]);
    if (std::hypot(cx, cy) + cell < std::sqrt(1 - 0.09)) ++insideBoxLeaves;
  }
  std::size_t insideBallLeaves = 0;
  for (const OctreeLeaf& l : ball.leaves) {
    const double cx = 0.5 * (l.box.min[0] + l.box.max[0]), cy = 0.5 * (l.box.min[1] + l.box.max[1]);
    if (std::hypot(cx, cy) + cell < std::sqrt(1 - 0.09)) ++insideBallLeaves;
  }
  EXPECT_EQ(insideBallLeaves, insideBoxLeaves);
  EXPECT_NE(octreeReport(ball).find("clipped to the sphere of center (0, 0, 0), radius 1"),
            std::string::npos);
}

TEST(Octree, AClippingBallNeedsAPositiveRadius) {
  OctreeSettings st;
  const OctreeResult r = buildOctree(test::parseOrDie("z"), {}, kCube, st, Ball{{0, 0, 0}, 0.0});
  ASSERT_TRUE(std::holds_alternative<OctreeError>(r));
  EXPECT_NE(std::get<OctreeError>(r).message.find("radius"), std::string::npos);
}

TEST(Octree, StatisticsAddUp) {
  const Octree t = build(std::string(test::kThesisSurfaces[2]), 7, Criteria::Thesis);
  std::size_t leaves = 0;
  for (std::size_t l = 0; l < t.levels.size(); ++l) {
    const LevelStats& s = t.levels[l];
    EXPECT_LE(s.kept, s.tested);
    EXPECT_LE(s.leaves, s.kept);
    // Every kept box that is not a leaf has 8 children tested one level down.
    if (l + 1 < t.levels.size()) EXPECT_EQ(t.levels[l + 1].tested, 8 * (s.kept - s.leaves));
    leaves += s.leaves;
  }
  EXPECT_EQ(leaves, t.leaves.size());
  EXPECT_EQ(t.levels[0].tested, 1u);
  EXPECT_GT(t.buildSeconds, 0.0);
}

TEST(Octree, SameLeavesInTheSameOrderWhateverTheThreadCount) {
  for (Criteria c : {Criteria::Thesis, Criteria::Uniform}) {
    const Octree one = build(std::string(test::kThesisSurfaces[4]), 7, c, 1);
    const Octree two = build(std::string(test::kThesisSurfaces[4]), 7, c, 2);
    ASSERT_EQ(one.leaves.size(), two.leaves.size());
    for (std::size_t i = 0; i < one.leaves.size(); ++i) {
      ASSERT_EQ(one.leaves[i].level, two.leaves[i].level);
      ASSERT_EQ(one.leaves[i].cell, two.leaves[i].cell);
    }
  }
}

TEST(Octree, TheNodeBudgetStopsWithAMessage) {
  OctreeSettings st;
  st.level = 10;
  st.criteria = Criteria::Uniform;
  st.nodeBudget = 100000;
  const OctreeResult r = buildOctree(test::parseOrDie("x^2+y^2+z^2-1"), {}, kCube, st);
  ASSERT_TRUE(std::holds_alternative<OctreeError>(r));
  EXPECT_NE(std::get<OctreeError>(r).message.find("node budget"), std::string::npos);
}

TEST(Octree, BadInputGivesAnErrorNotACrash) {
  const Formula f = test::parseOrDie("x^2+y^2+z^2-a");  // one parameter
  OctreeSettings st;
  st.level = 3;
  EXPECT_TRUE(std::holds_alternative<OctreeError>(buildOctree(f, {}, kCube, st)));
  const double a[] = {1.0};
  EXPECT_TRUE(std::holds_alternative<Octree>(buildOctree(f, a, kCube, st)));
  EXPECT_TRUE(
      std::holds_alternative<OctreeError>(buildOctree(f, a, Box{{1, 0, 0}, {0, 1, 1}}, st)));
  st.level = kMaxOctreeLevel + 1;
  EXPECT_TRUE(std::holds_alternative<OctreeError>(buildOctree(f, a, kCube, st)));
}

TEST(Octree, UndefinedEverywhereKeepsNothing) {
  // sqrt of a negative number is undefined on the whole domain: no surface, no leaves.
  const Octree t = build("sqrt(-1-x^2)", 4, Criteria::Thesis);
  EXPECT_TRUE(t.leaves.empty());
}

TEST(Octree, ParametersReachTheEvaluation) {
  const Formula f = test::parseOrDie("x^2+y^2+z^2-r");
  OctreeSettings st;
  st.level = 5;
  st.criteria = Criteria::Uniform;
  const double small[] = {0.25}, none[] = {-1.0};
  const Octree t = std::get<Octree>(buildOctree(f, small, kCube, st));
  for (const OctreeLeaf& l : t.leaves)
    for (std::size_t a = 0; a < 3; ++a) EXPECT_LE(std::max(-l.box.max[a], l.box.min[a]), 0.5);
  EXPECT_FALSE(t.leaves.empty());
  EXPECT_TRUE(std::get<Octree>(buildOctree(f, none, kCube, st)).leaves.empty());
}

TEST(Octree, ReportAndCsv) {
  const Octree t = build("x^2+y^2+z^2-1", 3, Criteria::Uniform);
  const std::string report = octreeReport(t);
  EXPECT_NE(report.find("leaves: " + std::to_string(t.leaves.size())), std::string::npos);
  EXPECT_NE(report.find("build time"), std::string::npos);
  std::ostringstream csv;
  writeLeafCsv(t, csv);
  std::istringstream in(csv.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "level,xmin,xmax,ymin,ymax,zmin,zmax");
  std::size_t rows = 0;
  for (; std::getline(in, line); ++rows) {
    double v[6];
    int level = -1;
    ASSERT_EQ(std::sscanf(line.c_str(), "%d,%lf,%lf,%lf,%lf,%lf,%lf", &level, &v[0], &v[1], &v[2],
                          &v[3], &v[4], &v[5]),
              7);
    const Box& b = t.leaves[rows].box;
    EXPECT_EQ(level, 3);
    EXPECT_EQ(v[0], b.min[0]);  // 17 digits: bit-exact round trip
    EXPECT_EQ(v[5], b.max[2]);
  }
  EXPECT_EQ(rows, t.leaves.size());
}

}  // namespace
}  // namespace zs
