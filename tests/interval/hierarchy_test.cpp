// The box hierarchy: structure (pre-order, escapes, tight boxes, pruning), the packed
// GPU layout, and a stackless walk that must find exactly the leaves a ray meets.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "interval/hierarchy_builder.hpp"
#include "interval/octree.hpp"
#include "surfaces.hpp"

namespace zs {
namespace {

Octree build(const std::string& formula, int level, Criteria c) {
  OctreeSettings st;
  st.level = level;
  st.criteria = c;
  return std::get<Octree>(
      buildOctree(test::parseOrDie(formula), {}, {{-2, -2, -2}, {2, 2, 2}}, st));
}

bool inside(const Box& inner, const Box& outer) {
  for (std::size_t a = 0; a < 3; ++a)
    if (inner.min[a] < outer.min[a] || inner.max[a] > outer.max[a]) return false;
  return true;
}

void checkStructure(const Octree& tree, const BoxHierarchy& h) {
  std::size_t leaves = 0;
  for (std::size_t i = 0; i < h.nodes.size(); ++i) {
    const BoxNode& n = h.nodes[i];
    ASSERT_GT(std::size_t(n.escape), i);
    ASSERT_LE(std::size_t(n.escape), h.nodes.size());
    if (n.leaf) {
      EXPECT_EQ(std::size_t(n.escape), i + 1);
      EXPECT_EQ(n.box.min, tree.leaves[leaves].box.min);  // leaves keep the octree's order
      EXPECT_EQ(n.box.max, tree.leaves[leaves].box.max);
      ++leaves;
    } else {
      // No empty inner node, and no inner node with one child (collapsed).
      ASSERT_GT(std::size_t(n.escape), i + 2);
      EXPECT_NE(std::size_t(h.nodes[i + 1].escape), std::size_t(n.escape));
    }
    // Descendants lie in the node's box; the box is the tight union of its children.
    Box u{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (std::size_t j = i + 1; j < std::size_t(n.escape); j = std::size_t(h.nodes[j].escape)) {
      EXPECT_TRUE(inside(h.nodes[j].box, n.box));
      for (std::size_t a = 0; a < 3; ++a) {
        u.min[a] = std::min(u.min[a], h.nodes[j].box.min[a]);
        u.max[a] = std::max(u.max[a], h.nodes[j].box.max[a]);
      }
    }
    if (!n.leaf) EXPECT_EQ(u.min, n.box.min);
    // The sphere holds every corner; its radius is half the diagonal (not the thesis' full one).
    double diag2 = 0;
    for (std::size_t a = 0; a < 3; ++a) diag2 += std::pow(n.box.max[a] - n.box.min[a], 2);
    EXPECT_NEAR(n.radius, 0.5 * std::sqrt(diag2), 1e-12 * (1 + n.radius));
    for (int c = 0; c < 8; ++c) {
      double d2 = 0;
      for (std::size_t a = 0; a < 3; ++a)
        d2 += std::pow(((c >> a) & 1 ? n.box.max[a] : n.box.min[a]) - n.center[a], 2);
      EXPECT_LE(std::sqrt(d2), n.radius);
    }
  }
  EXPECT_EQ(leaves, tree.leaves.size());
}

TEST(Hierarchy, StructureForBothCriteria) {
  for (Criteria c : {Criteria::Thesis, Criteria::Uniform}) {
    const Octree tree = build(std::string(test::kThesisSurfaces[6]), 5, c);
    const BoxHierarchy h = buildBoxHierarchy(tree);
    checkStructure(tree, h);
    EXPECT_EQ(std::size_t(h.nodes.front().escape), h.nodes.size());  // one root
  }
}

TEST(Hierarchy, EmptyAndSingleLeaf) {
  EXPECT_TRUE(buildBoxHierarchy(build("x^2+y^2+z^2+1", 4, Criteria::Thesis)).nodes.empty());
  const BoxHierarchy one = buildBoxHierarchy(build("x^2+y^2+z^2-1", 0, Criteria::Thesis));
  ASSERT_EQ(one.nodes.size(), 1u);
  EXPECT_TRUE(one.nodes[0].leaf);
}

TEST(Hierarchy, PackedLayoutHoldsTheDoubleBoxes) {
  const Octree tree = build("x^2+y^2+z^2-1.3", 4, Criteria::Uniform);
  const BoxHierarchy h = buildBoxHierarchy(tree);
  const std::vector<float> p = h.packed();
  ASSERT_EQ(p.size(), h.nodes.size() * 12);
  for (std::size_t i = 0; i < h.nodes.size(); ++i) {
    const float* t = &p[i * 12];
    const BoxNode& n = h.nodes[i];
    EXPECT_EQ(t[7], float(n.escape));
    EXPECT_EQ(t[11], n.leaf ? 1.0f : 0.0f);
    for (std::size_t a = 0; a < 3; ++a) {
      EXPECT_LE(double(t[4 + a]), n.box.min[a]);
      EXPECT_GE(double(t[8 + a]), n.box.max[a]);
    }
    for (int c = 0; c < 8; ++c) {  // the float sphere holds the float box
      double d2 = 0;
      for (std::size_t a = 0; a < 3; ++a)
        d2 += std::pow(double((c >> a) & 1 ? t[8 + a] : t[4 + a]) - t[a], 2);
      EXPECT_LE(std::sqrt(d2), double(t[3]));
    }
  }
}

// Slab test of a ray against a box, the test the shader does.
bool hitsBox(const std::array<double, 3>& o, const std::array<double, 3>& d, const Box& b) {
  double t0 = 0, t1 = INFINITY;
  for (std::size_t a = 0; a < 3; ++a) {
    double u = (b.min[a] - o[a]) / d[a], v = (b.max[a] - o[a]) / d[a];
    if (u > v) std::swap(u, v);
    t0 = std::max(t0, u);
    t1 = std::min(t1, v);
  }
  return t0 <= t1;
}

TEST(Hierarchy, StacklessWalkFindsExactlyTheLeavesARayMeets) {
  const Octree tree = build(std::string(test::kThesisSurfaces[2]), 5, Criteria::Thesis);
  const BoxHierarchy h = buildBoxHierarchy(tree);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int ray = 0; ray < 2000; ++ray) {
    const std::array<double, 3> o{5 * u(rng), 5 * u(rng), 5 + u(rng)};
    const std::array<double, 3> d{u(rng) - o[0] / 5, u(rng) - o[1] / 5, -1.0};
    std::vector<std::size_t> walked, brute;
    for (std::size_t i = 0; i < h.nodes.size();) {
      const BoxNode& n = h.nodes[i];
      if (hitsBox(o, d, n.box)) {
        if (n.leaf) walked.push_back(i);
        i = n.leaf ? std::size_t(n.escape) : i + 1;
      } else {
        i = std::size_t(n.escape);
      }
    }
    for (std::size_t i = 0; i < h.nodes.size(); ++i)
      if (h.nodes[i].leaf && hitsBox(o, d, h.nodes[i].box)) brute.push_back(i);
    ASSERT_EQ(walked, brute) << "ray " << ray;
  }
}

}  // namespace
}  // namespace zs
