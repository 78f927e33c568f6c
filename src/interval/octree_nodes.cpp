#include "interval/octree_nodes.hpp"

#include <algorithm>
#include <unordered_map>

namespace zs {
namespace {

using Cell = std::array<std::uint32_t, 3>;

std::uint64_t key(const Cell& c) {
  return std::uint64_t{c[0]} | std::uint64_t{c[1]} << 21 | std::uint64_t{c[2]} << 42;
}

Cell parentOf(const Cell& c) { return {c[0] >> 1, c[1] >> 1, c[2] >> 1}; }

std::uint32_t octantOf(const Cell& c) { return (c[0] & 1u) | (c[1] & 1u) << 1 | (c[2] & 1u) << 2; }

struct Inner {
  Cell cell{};
  int level = 0;
  std::uint32_t exist = 0, leaf = 0;
};

}  // namespace

OctreeNodes buildOctreeNodes(const Octree& tree) {
  OctreeNodes out;
  out.box = tree.domain;
  out.empty = tree.leaves.empty();
  if (out.empty) return out;
  int depth = 0;
  for (const OctreeLeaf& leaf : tree.leaves) depth = std::max(depth, leaf.level);
  if (depth == 0) {
    out.rootLeaf = true;
    return out;
  }
  // Inner nodes per level, keyed by cell: every ancestor of a leaf.
  std::vector<std::unordered_map<std::uint64_t, Inner>> levels(static_cast<std::size_t>(depth));
  for (const OctreeLeaf& leaf : tree.leaves) {
    Cell cell = leaf.cell;
    bool isLeaf = true;
    for (int level = leaf.level - 1; level >= 0; --level) {
      const Cell parent = parentOf(cell);
      Inner& node = levels[std::size_t(level)][key(parent)];
      node.cell = parent;
      node.level = level;
      node.exist |= 1u << octantOf(cell);
      if (isLeaf) node.leaf |= 1u << octantOf(cell);
      cell = parent;
      isLeaf = false;
    }
  }
  // Breadth first: the inner children of each node, in octant order, get consecutive indices.
  std::vector<const Inner*> order{&levels[0].begin()->second};
  out.words.reserve(2 * (tree.leaves.size() + 1));
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Inner& node = *order[i];
    out.words.push_back(node.exist | node.leaf << 8);
    out.words.push_back(std::uint32_t(order.size()));
    const std::uint32_t inner = node.exist & ~node.leaf;
    const std::size_t childLevel = std::size_t(node.level) + 1;
    for (std::uint32_t k = 0; k < 8; ++k) {
      if (!(inner >> k & 1u)) continue;
      const Cell child{2 * node.cell[0] + (k & 1u), 2 * node.cell[1] + (k >> 1 & 1u),
                       2 * node.cell[2] + (k >> 2 & 1u)};
      order.push_back(&levels[childLevel].at(key(child)));
    }
  }
  return out;
}

}  // namespace zs
