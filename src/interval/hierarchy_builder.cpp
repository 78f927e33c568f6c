#include "interval/hierarchy_builder.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace zs {

namespace {

struct Tmp {
  Box box;
  std::int32_t parent = -1;
  std::int32_t children = 0;
  bool leaf = false;
};

constexpr double kInf = std::numeric_limits<double>::infinity();

Box emptyBox() {
  return {{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
}

void grow(Box& into, const Box& b) {
  for (std::size_t i = 0; i < 3; ++i) {
    into.min[i] = std::min(into.min[i], b.min[i]);
    into.max[i] = std::max(into.max[i], b.max[i]);
  }
}

struct PathEntry {
  int level;
  std::array<std::uint32_t, 3> cell;
  std::int32_t index;
};

bool isAncestor(const PathEntry& p, const OctreeLeaf& leaf) {
  if (p.level >= leaf.level) return false;
  const int shift = leaf.level - p.level;
  for (std::size_t i = 0; i < 3; ++i)
    if ((leaf.cell[i] >> shift) != p.cell[i]) return false;
  return true;
}

// The octree as explicit nodes in pre-order: the leaves' ancestors rebuilt from their cells.
// Leaves are cut to `clip` when given; a leaf that misses it is left out.
std::vector<Tmp> rebuildTree(const Octree& tree, const Box* clip) {
  std::vector<Tmp> nodes;
  std::vector<PathEntry> path;
  for (const OctreeLeaf& leaf : tree.leaves) {
    const std::optional<Box> box = clip ? meet(leaf.box, *clip) : leaf.box;
    if (!box) continue;
    while (!path.empty() && !isAncestor(path.back(), leaf)) path.pop_back();
    for (int level = path.empty() ? 0 : path.back().level + 1; level < leaf.level; ++level) {
      const int shift = leaf.level - level;
      PathEntry e{level,
                  {leaf.cell[0] >> shift, leaf.cell[1] >> shift, leaf.cell[2] >> shift},
                  std::int32_t(nodes.size())};
      nodes.push_back({emptyBox(), path.empty() ? -1 : path.back().index, 0, false});
      path.push_back(e);
    }
    nodes.push_back({*box, path.empty() ? -1 : path.back().index, 0, true});
  }
  // Parents precede children, so one backward sweep accumulates boxes and child counts.
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const std::int32_t p = nodes[i].parent;
    if (p < 0) continue;
    grow(nodes[std::size_t(p)].box, nodes[i].box);
    ++nodes[std::size_t(p)].children;
  }
  return nodes;
}

}  // namespace

BoxNode boxNode(const Box& box) {
  BoxNode n;
  n.box = box;
  double d2 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    n.center[i] = 0.5 * (box.min[i] + box.max[i]);
    const double h = std::max(box.max[i] - n.center[i], n.center[i] - box.min[i]);
    d2 += h * h;
  }
  // Measured from the rounded center to the farther face; one ulp up covers sqrt's rounding.
  n.radius = std::nextafter(std::sqrt(d2), kInf);
  return n;
}

BoxHierarchy buildBoxHierarchy(const Octree& tree, const Box* clip) {
  const std::vector<Tmp> tmp = rebuildTree(tree, clip);
  BoxHierarchy h;
  std::vector<std::int32_t> emitted(tmp.size(), -1);  // nearest emitted ancestor-or-self
  std::vector<std::int32_t> parentOut;
  for (std::size_t i = 0; i < tmp.size(); ++i) {
    const std::int32_t p = tmp[i].parent < 0 ? -1 : emitted[std::size_t(tmp[i].parent)];
    if (!tmp[i].leaf && tmp[i].children == 1) {
      emitted[i] = p;  // a single child has the same box: skip this level
      continue;
    }
    emitted[i] = std::int32_t(h.nodes.size());
    BoxNode n = boxNode(tmp[i].box);
    n.leaf = tmp[i].leaf;
    h.nodes.push_back(n);
    parentOut.push_back(p);
  }
  // Subtree sizes give the escape index: the first node after the subtree.
  std::vector<std::int32_t> size(h.nodes.size(), 1);
  for (std::size_t i = h.nodes.size(); i-- > 0;) {
    if (parentOut[i] >= 0) size[std::size_t(parentOut[i])] += size[i];
    h.nodes[i].escape = std::int32_t(i) + size[i];
  }
  return h;
}

std::vector<float> BoxHierarchy::packed() const {
  auto down = [](double v) {
    float f = float(v);
    return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
  };
  auto up = [](double v) {
    float f = float(v);
    return double(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  };
  // Escape indices travel as floats, exact up to 2^24; the octree's node budget keeps far below.
  assert(nodes.size() < (std::size_t(1) << 24));
  std::vector<float> out;
  out.reserve(nodes.size() * 12);
  for (const BoxNode& n : nodes) {
    // The float box holds the double box; the float sphere holds the float box.
    std::array<float, 3> lo{}, hi{}, c{};
    double d2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = down(n.box.min[i]);
      hi[i] = up(n.box.max[i]);
      c[i] = float(n.center[i]);
      const double h = std::max(double(hi[i]) - c[i], c[i] - double(lo[i]));
      d2 += h * h;
    }
    const float r = std::nextafter(up(std::sqrt(d2)), std::numeric_limits<float>::infinity());
    out.insert(out.end(), {c[0], c[1], c[2], r});
    out.insert(out.end(), {lo[0], lo[1], lo[2], float(n.escape)});
    out.insert(out.end(), {hi[0], hi[1], hi[2], n.leaf ? 1.0f : 0.0f});
  }
  return out;
}

}  // namespace zs
