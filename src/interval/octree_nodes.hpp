#pragma once
// The octree for the GPU's front-to-back walk: takes an octree's leaves (with their cells),
// puts out its inner nodes only, two 32-bit words each, in breadth-first order:
//   word 0 = existing children (bit k for octant k = x | y << 1 | z << 2, set where the
//            child is a leaf or an inner node) | leaf children << 8
//   word 1 = index of the first inner child; the node's inner children follow it in octant
//            order, so child k is node word1 + popcount(inner children below bit k)
// Leaves and empty cells need no node of their own: the parent's masks say what they are.
// Every word stays below 2^31 (a Mesa 22.3 llvmpipe bug clamps larger RGBA32UI texels).
#include <cstdint>
#include <vector>

#include "interval/octree.hpp"

namespace zs {

struct OctreeNodes {
  Box box;                           // the octree's domain (level 0)
  bool empty = true;                 // no leaf at all: nothing to trace
  bool rootLeaf = false;             // the domain itself is the one leaf
  std::vector<std::uint32_t> words;  // 2 per inner node; node 0 is the root when it is inner
};

OctreeNodes buildOctreeNodes(const Octree& tree);

}  // namespace zs
