// Octree safety: no surface point may lie outside the kept leaves. Surface points are found
// by dense sampling (F on a 256^3 grid, sign changes along the grid lines of all three
// axes, each bracket narrowed by bisection); each bracket must meet a kept leaf, for both
// criteria. The squared sphere never changes sign and gets its own test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "expr/tape.hpp"
#include "interval/octree.hpp"
#include "leaf_index.hpp"
#include "surfaces.hpp"

namespace zs {
namespace {

constexpr int kGrid = 256;
// Each bracket is narrowed to a billionth of the grid's spacing (2^-30), far below any leaf's
// size, so a bracket meets a kept leaf only where its sign change does.
constexpr int kBisections = 30;

struct Case {
  std::string name;
  std::string formula;
  Box domain;
};

// Names the case in test listings instead of gtest's byte dump of the struct.
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.formula;
}

Box cube(double lo, double hi) {
  return {{lo, lo, lo}, {hi, hi, hi}};
}

std::vector<Case> cases() {
  std::vector<Case> out;
  const Box skewed{{-1.9, -1.7, -2.1}, {2.2, 1.8, 1.95}};  // faces avoid the symmetric points
  // Alternate the two domains: symmetric puts special points on cell faces, skewed does not.
  for (std::size_t i = 0; i < test::kThesisSurfaces.size(); ++i) {
    const bool sym = i % 2 == 0;
    out.push_back({"thesis" + std::to_string(i + 1) + (sym ? "" : "_skewed"),
                   std::string(test::kThesisSurfaces[i]), sym ? cube(-2, 2) : skewed});
  }
  // Cayley's nodal cubic: its four singular points (+-1/2, ...) lie on cell faces of [-1,1]^3.
  out.push_back({"cayley", "4*(x^2+y^2+z^2)+16*x*y*z-1", cube(-1, 1)});
  out.push_back({"double_cone", "x^2+y^2-z^2", cube(-1, 1)});  // apex at a cell corner
  out.push_back({"thin_shell", "(x^2+y^2+z^2-1)^2-1e-6", cube(-1.5, 1.5)});
  return out;
}

// Small boxes (segments along grid lines, narrowed by bisection) that hold a sign change of
// F as computed in double precision, or a grid point where F is exactly 0.
std::vector<Box> signChangeBrackets(const Formula& f, const Box& d) {
  const Tape tape = compileTape(f.graph, {f.root});
  auto coord = [&d](std::size_t a, int i) {
    return d.min[a] + (d.max[a] - d.min[a]) * double(i) / double(kGrid - 1);
  };
  auto sgn = [](double v) { return std::isnan(v) ? 2 : (v > 0) - (v < 0); };
  std::vector<std::int8_t> s(std::size_t(kGrid) * kGrid * kGrid);
  auto idx = [](int i, int j, int k) { return (std::size_t(i) * kGrid + j) * kGrid + k; };
  {  // 16.7 million samples: split the slabs over both cores
    auto slab = [&](int first, int step) {
      PointEvaluator pe(tape);
      for (int i = first; i < kGrid; i += step)
        for (int j = 0; j < kGrid; ++j)
          for (int k = 0; k < kGrid; ++k)
            s[idx(i, j, k)] = std::int8_t(sgn(pe.eval1(coord(0, i), coord(1, j), coord(2, k))));
    };
    std::jthread other(slab, 1, 2);
    slab(0, 2);
  }
  PointEvaluator pe(tape);
  auto at = [&](const std::array<double, 3>& p) { return pe.eval1(p[0], p[1], p[2]); };

  // Every pair of neighbours along each axis, in the grid's own order (the neighbour along
  // `axis` lies `stride` entries further on), so each pass reads the grid front to back.
  std::vector<Box> brackets;
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t stride = axis == 0 ? std::size_t(kGrid) * kGrid : axis == 1 ? kGrid : 1;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j)
        for (int k = 0; k < kGrid; ++k) {
          const int e0[3] = {i, j, k};
          const int w = e0[axis];
          if (w + 1 >= kGrid) continue;
          const std::size_t n = idx(i, j, k);
          const int s0 = s[n], s1 = s[n + stride];
          if (s0 == 2 || s1 == 2) continue;
          if (s0 == 0) {
            const std::array<double, 3> p0{coord(0, i), coord(1, j), coord(2, k)};
            brackets.push_back({p0, p0});
          }
          if (s0 * s1 >= 0) continue;
          const std::array<double, 3> p0{coord(0, i), coord(1, j), coord(2, k)};
          double lo = p0[std::size_t(axis)], hi = coord(std::size_t(axis), w + 1);
          for (int step = 0; step < kBisections; ++step) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            std::array<double, 3> m = p0;
            m[std::size_t(axis)] = mid;
            const int sm = sgn(at(m));
            if (sm == 0 || sm == 2) {
              lo = hi = mid;
              break;
            }
            (sm == s0 ? lo : hi) = mid;
          }
          Box b{p0, p0};
          b.min[std::size_t(axis)] = lo;
          b.max[std::size_t(axis)] = hi;
          brackets.push_back(b);
        }
  }
  return brackets;
}

class OctreeSafety : public ::testing::TestWithParam<Case> {};

TEST_P(OctreeSafety, EverySignChangeLiesInAKeptLeaf) {
  const Case& c = GetParam();
  const Formula f = test::parseOrDie(c.formula);
  const std::vector<Box> brackets = signChangeBrackets(f, c.domain);
  ASSERT_GT(brackets.size(), 1000u) << "the sampling must find the surface";
  for (auto [criteria, level] : {std::pair{Criteria::Thesis, 8}, std::pair{Criteria::Uniform, 6}}) {
    OctreeSettings st;
    st.level = level;
    st.criteria = criteria;
    OctreeResult r = buildOctree(f, {}, c.domain, st);
    ASSERT_TRUE(std::holds_alternative<Octree>(r)) << std::get<OctreeError>(r).message;
    const Octree& tree = std::get<Octree>(r);
    const test::LeafIndex index(tree);
    int missed = 0;
    for (const Box& b : brackets) {
      if (index.meets(b)) continue;
      if (++missed <= 5)
        ADD_FAILURE() << c.name << (criteria == Criteria::Thesis ? " thesis" : " uniform")
                      << ": sign change near (" << b.min[0] << ", " << b.min[1] << ", " << b.min[2]
                      << ") is in no kept leaf";
    }
    EXPECT_EQ(missed, 0) << "of " << brackets.size() << " brackets, " << tree.leaves.size()
                         << " leaves";
  }
}

INSTANTIATE_TEST_SUITE_P(Surfaces, OctreeSafety, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.name;
                         });

void expectPointsKept(const std::string& formula, const Box& domain,
                      const std::vector<std::array<double, 3>>& points, double tolerance) {
  const Formula f = test::parseOrDie(formula);
  for (Criteria criteria : {Criteria::Thesis, Criteria::Uniform}) {
    OctreeSettings st;
    st.level = 7;
    st.criteria = criteria;
    OctreeResult r = buildOctree(f, {}, domain, st);
    ASSERT_TRUE(std::holds_alternative<Octree>(r));
    const test::LeafIndex index(std::get<Octree>(r));
    int missed = 0;
    for (const auto& p : points) {
      const Box q{{p[0] - tolerance, p[1] - tolerance, p[2] - tolerance},
                  {p[0] + tolerance, p[1] + tolerance, p[2] + tolerance}};
      if (!index.meets(q) && ++missed <= 5)
        ADD_FAILURE() << formula << ": (" << p[0] << ", " << p[1] << ", " << p[2]
                      << ") is in no kept leaf";
    }
    EXPECT_EQ(missed, 0);
  }
}

// (x^2+y^2+z^2-1)^2 touches 0 without changing sign: sampling signs finds nothing, so
// points are taken on the unit sphere itself (within rounding of the sphere: 1e-12).
TEST(OctreeSafety, SquaredSphereKeepsEveryPointOfTheSphere) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < 100000; ++i) {
    const double x = g(rng), y = g(rng), z = g(rng), n = std::sqrt(x * x + y * y + z * z);
    points.push_back({x / n, y / n, z / n});
  }
  expectPointsKept("(x^2+y^2+z^2-1)^2", cube(-1.5, 1.5), points, 1e-12);
  expectPointsKept("(x^2+y^2+z^2-1)^2", Box{{-1.3, -1.1, -1.7}, {1.2, 1.9, 1.4}}, points, 1e-12);
}

TEST(OctreeSafety, SingularPointsAreKept) {
  expectPointsKept("4*(x^2+y^2+z^2)+16*x*y*z-1", cube(-1, 1),
                   {{-0.5, -0.5, -0.5}, {0.5, 0.5, -0.5}, {0.5, -0.5, 0.5}, {-0.5, 0.5, 0.5}}, 0.0);
  expectPointsKept("x^2+y^2-z^2", cube(-1, 1), {{0, 0, 0}}, 0.0);
}

}  // namespace
}  // namespace zs
