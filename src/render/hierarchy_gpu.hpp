#pragma once
// Repacks the box hierarchy for the fragment shader: takes the 12-float-per-node layout
// of interval/hierarchy.hpp (pre-order, escape indices), puts out ONE uvec4 texel per
// node. The node's box is stored as integer corners on a grid of 2^14 cells per
// axis spanning the root box (16 bits each, min rounded down and max up, so the stored box
// always contains the real one and is exact for octree cells down to level 14):
//   x = qmin.x | qmin.y << 16,  y = qmin.z | qmax.x << 16,  z = qmax.y | qmax.z << 16,
//   w = escape << 1 | isLeaf.
// Why: on llvmpipe each dependent texelFetch costs about as much as a dozen evaluations of
// a quartic (docs/renderer.md) and the traversal is fetch-bound; one texel instead of three
// per visited node. The sphere is not uploaded: the box is a tighter bound than its
// circumscribed sphere and its slab test costs the same arithmetic.
// Why 2^14 and not 2^15: Mesa 22.3 llvmpipe returned 0x7FFFFFFF for RGBA32UI buffer texels
// with the top bit set (a signed saturation), so no stored word may reach 2^31.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zs {

struct GpuHierarchy {
  static constexpr int kGridBits = 14;
  static constexpr std::uint32_t kMaxNodes = 1u << 30;  // escape << 1 stays below 2^31 (see above)

  std::vector<std::uint32_t> texels;  // 4 per node
  std::array<float, 3> rootMin{};     // node 0's box minimum
  std::array<float, 3> rootMax{};     // and maximum: every leaf lies inside
  std::array<float, 3> cell{};        // root extent / 2^kGridBits per axis
  float pad = 0;                      // widens every box: closes float cracks between leaves
  int count = 0;                      // nodes
  bool rootIsLeaf = false;            // else the walk may start at node 1 (root box pre-clipped)
};

// Validates and converts. Returns "" on success, else what is wrong with the input (wrong
// length, non-finite numbers, min > max, an escape that does not move forward, a flag that
// is not 0/1). An empty span is valid: nothing to trace.
std::string toGpuHierarchy(std::span<const float> packed, GpuHierarchy& out);

}  // namespace zs
