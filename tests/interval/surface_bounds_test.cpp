// The surface's bounding box (interval/surface_bounds.hpp): it must hold every surface point
// found by dense sampling in double precision (sign changes along the lines of a 96^3 grid,
// narrowed by bisection), also when its search runs out of budget; it must be tight where
// the surface fills a small part of the domain; and the box hierarchy cut to it must keep
// covering the surface.
#include "interval/surface_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "expr/tape.hpp"
#include "interval/hierarchy_builder.hpp"
#include "interval/octree.hpp"
#include "surfaces.hpp"

namespace zs {
namespace {

constexpr int kGrid = 96;

Box cube(double lo, double hi) {
  return {{lo, lo, lo}, {hi, hi, hi}};
}

bool holds(const Box& b, const std::array<double, 3>& p) {
  for (std::size_t a = 0; a < 3; ++a)
    if (!(b.min[a] <= p[a] && p[a] <= b.max[a])) return false;
  return true;
}

// Points within 1e-12 of the domain's scale of a root of F (as double precision computes
// it): sign changes along the grid lines of all three axes, bisected; and grid points where
// F is exactly 0. A sign change across a pole or a domain edge is found too (its bisection
// ends at the pole): the bounds need not hold those, so `defined` drops points where F is
// undefined or farther than 1e-6 from 0.
std::vector<std::array<double, 3>> surfacePoints(const Formula& f, const Box& d) {
  const Tape tape = compileTape(f.graph, {f.root});
  PointEvaluator pe(tape);
  auto F = [&](const std::array<double, 3>& p) { return pe.eval1(p[0], p[1], p[2]); };
  auto coord = [&d](std::size_t a, int i) {
    return d.min[a] + (d.max[a] - d.min[a]) * double(i) / double(kGrid - 1);
  };
  std::vector<std::array<double, 3>> out;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        std::array<double, 3> p{};
        p[u] = coord(u, i);
        p[v] = coord(v, j);
        p[axis] = coord(axis, 0);
        double prev = F(p);
        for (int k = 1; k < kGrid; ++k) {
          std::array<double, 3> q = p;
          q[axis] = coord(axis, k);
          const double cur = F(q);
          if (prev == 0.0) out.push_back(p);
          if (std::isfinite(prev) && std::isfinite(cur) && (prev < 0) != (cur < 0) && cur != 0) {
            double lo = p[axis], hi = q[axis], flo = prev;
            for (int n = 0; n < 60; ++n) {
              std::array<double, 3> m = p;
              m[axis] = 0.5 * (lo + hi);
              const double fm = F(m);
              if ((fm < 0) == (flo < 0)) {
                lo = m[axis];
                flo = fm;
              } else {
                hi = m[axis];
              }
            }
            std::array<double, 3> r = p;
            r[axis] = 0.5 * (lo + hi);
            const double fr = F(r);
            if (std::isfinite(fr) && std::abs(fr) < 1e-6) out.push_back(r);
          }
          p = q;
          prev = cur;
        }
      }
  }
  return out;
}

void expectHoldsEverySurfacePoint(const std::string& formula, const Box& domain,
                                  const SurfaceBoundsSettings& settings = {}) {
  SCOPED_TRACE(formula);
  const Formula f = test::parseOrDie(formula);
  const Box b = surfaceBounds(f, {}, domain, std::nullopt, settings);
  const auto points = surfacePoints(f, domain);
  ASSERT_FALSE(points.empty()) << "the sampling found no surface: the test means nothing";
  ASSERT_FALSE(isEmpty(b));
  int outside = 0;
  for (const auto& p : points)
    if (!holds(b, p) && ++outside <= 5)
      ADD_FAILURE() << "surface point (" << p[0] << ", " << p[1] << ", " << p[2]
                    << ") outside the bounds [" << b.min[0] << ", " << b.max[0] << "] x ["
                    << b.min[1] << ", " << b.max[1] << "] x [" << b.min[2] << ", " << b.max[2]
                    << "]";
}

TEST(SurfaceBounds, HoldEverySurfacePoint) {
  const Box skewed{{-1.9, -1.7, -2.1}, {2.2, 1.8, 1.95}};
  for (std::string_view s : test::kThesisSurfaces)
    expectHoldsEverySurfacePoint(std::string(s), skewed);
  expectHoldsEverySurfacePoint("sqrt(x^2+y^2+z^2)-1-0.08*sin(10*x)*sin(10*y)*sin(10*z)",
                               cube(-1.5, 1.5));
  expectHoldsEverySurfacePoint(
      "exp(-4*((x-0.5)^2+y^2+z^2))+exp(-4*((x+0.5)^2+y^2+z^2))+exp(-4*(x^2+(y-0.7)^2+z^2))-0.6",
      cube(-1.5, 1.5));
  expectHoldsEverySurfacePoint("sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)", skewed);
  expectHoldsEverySurfacePoint("1/x-1", skewed);        // a pole inside the domain
  expectHoldsEverySurfacePoint("sqrt(x)-0.5", skewed);  // half the domain undefined
  expectHoldsEverySurfacePoint("(x^2+y^2+z^2-1)^2-1e-6", cube(-1.5, 1.5));  // a thin shell
}

TEST(SurfaceBounds, StayConservativeWhenTheBudgetRunsOut) {
  for (std::size_t budget : {1u, 3u, 40u}) {
    SurfaceBoundsSettings s;
    s.faceBudget = budget;
    expectHoldsEverySurfacePoint("sqrt(x^2+y^2+z^2)-1-0.08*sin(10*x)*sin(10*y)*sin(10*z)",
                                 cube(-1.5, 1.5), s);
  }
  // A formula with a tape of thousands of instructions gets a smaller budget: the plane
  // z = 0.3 plus 300 terms of size 1e-6 still lies inside the bounds.
  std::string longFormula = "z-0.3";
  for (int k = 1; k <= 300; ++k)
    longFormula += "+0.000001*sin(" + std::to_string(k) + "*x)*cos(" + std::to_string(k) + "*y)";
  const Box l = surfaceBounds(test::parseOrDie(longFormula), {}, cube(-1, 1), std::nullopt);
  EXPECT_EQ(l.min[0], -1.0);
  EXPECT_EQ(l.max[1], 1.0);
  EXPECT_LE(l.min[2], 0.3 - 3e-4);
  EXPECT_GE(l.max[2], 0.3 + 3e-4);
  EXPECT_LT(l.max[2], 1.0);  // still a bound, not the whole domain
  // One evaluation per face proves nothing: the whole domain.
  SurfaceBoundsSettings one;
  one.faceBudget = 1;
  const Box b =
      surfaceBounds(test::parseOrDie("x^2+y^2+z^2-1"), {}, cube(-2, 2), std::nullopt, one);
  EXPECT_EQ(b.min, cube(-2, 2).min);
  EXPECT_EQ(b.max, cube(-2, 2).max);
}

TEST(SurfaceBounds, AreTightAroundASmallSurface) {
  // A unit sphere in [-2, 2]^3: within two cells (4 / 64 each) of [-1, 1]^3.
  const Box b = surfaceBounds(test::parseOrDie("x^2+y^2+z^2-1"), {}, cube(-2, 2), std::nullopt);
  for (std::size_t a = 0; a < 3; ++a) {
    EXPECT_LE(b.min[a], -1.0);
    EXPECT_GE(b.min[a], -1.0 - 2 * 4.0 / 64);
    EXPECT_GE(b.max[a], 1.0);
    EXPECT_LE(b.max[a], 1.0 + 2 * 4.0 / 64);
  }
  // Off centre and flat: the plane z = 0.3 in a skewed domain. Its lower face costs a whole
  // layer of 64 x 64 cells below the plane, which is the budget: the bound stops a cell short.
  const Box p =
      surfaceBounds(test::parseOrDie("z-0.3"), {}, {{-1, -2, -3}, {1, 2, 3}}, std::nullopt);
  EXPECT_EQ(p.min[0], -1.0);
  EXPECT_EQ(p.max[1], 2.0);
  EXPECT_LE(p.min[2], 0.3);
  EXPECT_GE(p.min[2], 0.3 - 2 * 6.0 / 64);
  EXPECT_GE(p.max[2], 0.3);
  EXPECT_LE(p.max[2], 0.3 + 2 * 6.0 / 64);
}

TEST(SurfaceBounds, AreEmptyWithoutASurface) {
  EXPECT_TRUE(
      isEmpty(surfaceBounds(test::parseOrDie("x^2+y^2+z^2+1"), {}, cube(-2, 2), std::nullopt)));
  EXPECT_TRUE(isEmpty(surfaceBounds(test::parseOrDie("sqrt(x)"), {}, cube(-3, -1), std::nullopt)));
  // The sphere lies outside the clipping ball.
  const Ball ball{{0, 0, 0}, 0.5};
  EXPECT_TRUE(isEmpty(surfaceBounds(test::parseOrDie("x^2+y^2+z^2-1"), {}, cube(-0.5, 0.5), ball)));
}

TEST(SurfaceBounds, KeepToTheClippingBall) {
  // The plane z = 0.5 cut by the unit ball: a disc of radius sqrt(3)/2.
  const Ball ball{{0, 0, 0}, 1.0};
  const Box b = surfaceBounds(test::parseOrDie("z-0.5"), {}, cube(-1, 1), ball);
  const double cell = 2.0 / 64, r = std::sqrt(3.0) / 2;
  for (std::size_t a = 0; a < 2; ++a) {
    EXPECT_LE(b.min[a], -r);
    EXPECT_GE(b.min[a], -r - 2 * cell);
    EXPECT_GE(b.max[a], r);
    EXPECT_LE(b.max[a], r + 2 * cell);
  }
  EXPECT_LE(b.min[2], 0.5);
  EXPECT_GE(b.max[2], 0.5);
}

TEST(SurfaceBounds, CutTheHierarchyWithoutUncoveringTheSurface) {
  const std::string formula = "x^2+y^2+z^2-1";
  const Formula f = test::parseOrDie(formula);
  OctreeSettings st;
  st.level = 2;
  const Octree tree = std::get<Octree>(buildOctree(f, {}, cube(-2, 2), st));
  const Box bounds = surfaceBounds(f, {}, cube(-2, 2), std::nullopt);
  const BoxHierarchy h = buildBoxHierarchy(tree, &bounds);
  ASSERT_FALSE(h.nodes.empty());
  std::vector<Box> leaves;
  for (const BoxNode& n : h.nodes) {
    for (std::size_t a = 0; a < 3; ++a) {
      EXPECT_GE(n.box.min[a], bounds.min[a]);
      EXPECT_LE(n.box.max[a], bounds.max[a]);
    }
    if (n.leaf) leaves.push_back(n.box);
  }
  EXPECT_EQ(h.nodes[0].box.min, bounds.min);  // the root is the union of the cut leaves
  EXPECT_EQ(h.nodes[0].box.max, bounds.max);
  for (const auto& p : surfacePoints(f, cube(-2, 2))) {
    bool covered = false;
    for (const Box& b : leaves) covered = covered || holds(b, p);
    EXPECT_TRUE(covered) << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    if (!covered) break;
  }
  // A clip box that misses some leaves leaves them out.
  const Box corner{{0.5, 0.5, 0.5}, {2, 2, 2}};
  const BoxHierarchy c = buildBoxHierarchy(tree, &corner);
  std::size_t kept = 0;
  for (const BoxNode& n : c.nodes) kept += n.leaf ? 1 : 0;
  EXPECT_GT(kept, 0u);
  EXPECT_LT(kept, tree.leaves.size());
}

}  // namespace
}  // namespace zs
