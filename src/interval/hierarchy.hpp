#pragma once
// The box hierarchy: takes the kept boxes of an octree, puts out a tree of axis-aligned
// boxes as a flat array that the fragment shader walks without a stack. A leaf's box is a
// kept octree cell (maybe cut to the surface's bounds), an inner node's the tight union of
// its children's. Layout (docs/hierarchy.md):
//   nodes in pre-order; each node is 3 vec4 texels
//     t0 = (center.xyz, radius)         the sphere around the box, radius = half the
//                                       diagonal: the thesis' bounding sphere. Only
//                                       tests/interval/hierarchy_test.cpp reads it;
//                                       toGpuHierarchy (render/hierarchy_gpu.hpp) drops it
//     t1 = (boxMin.xyz, escape)         escape = index of the next node when this subtree
//                                       is skipped or finished (== node count at the end)
//     t2 = (boxMax.xyz, isLeaf)         1.0 for a leaf (kept box at the deepest level it
//                                       reached), 0.0 for an inner node
//   Walking: i = 0; while i < count: if the ray meets box(i): if leaf, trace the segment
//   and go to escape, else go to i + 1 (first child); otherwise go to escape.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace zs {

struct Box {
  std::array<double, 3> min{};
  std::array<double, 3> max{};
};

// True when the box holds no point: min > max (or NaN) on some axis.
inline bool isEmpty(const Box& b) {
  for (std::size_t i = 0; i < 3; ++i)
    if (!(b.min[i] <= b.max[i])) return true;
  return false;
}

// The common part of two boxes; none where they do not meet (boxes that touch meet in a face).
inline std::optional<Box> meet(const Box& a, const Box& b) {
  Box r;
  for (std::size_t i = 0; i < 3; ++i) {
    r.min[i] = std::max(a.min[i], b.min[i]);
    r.max[i] = std::min(a.max[i], b.max[i]);
  }
  if (isEmpty(r)) return std::nullopt;
  return r;
}

struct BoxNode {
  std::array<double, 3> center{};  // the sphere around the box (t0 above)
  double radius = 0;
  Box box;
  std::int32_t escape = 0;
  bool leaf = false;
};

struct BoxHierarchy {
  std::vector<BoxNode> nodes;  // pre-order

  // 12 floats per node, in the texel layout above.
  std::vector<float> packed() const;
};

}  // namespace zs
