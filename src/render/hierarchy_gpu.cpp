#include "render/hierarchy_gpu.hpp"

#include <algorithm>
#include <cmath>

namespace zs {

std::string toGpuHierarchy(std::span<const float> packed, GpuHierarchy& out) {
  out = GpuHierarchy{};
  if (packed.size() % 12 != 0)
    return "hierarchy: " + std::to_string(packed.size()) + " floats is not 12 per node";
  const std::size_t count = packed.size() / 12;
  if (count == 0) return {};
  if (count >= GpuHierarchy::kMaxNodes)
    return "hierarchy: " + std::to_string(count) + " nodes exceed the GPU layout's limit";
  for (float v : packed)
    if (!std::isfinite(v)) return "hierarchy: non-finite number";

  // Node i: t0 = packed[12i..] (center, radius), t1 = (boxMin, escape), t2 = (boxMax, leaf).
  auto boxMin = [&](std::size_t i, int a) { return double(packed[12 * i + 4 + a]); };
  auto boxMax = [&](std::size_t i, int a) { return double(packed[12 * i + 8 + a]); };
  const double cells = std::ldexp(1.0, GpuHierarchy::kGridBits);
  std::array<double, 3> origin{}, cell{};
  double scale = 0;
  for (int a = 0; a < 3; ++a) {
    origin[a] = boxMin(0, a);
    cell[a] = (boxMax(0, a) - boxMin(0, a)) / cells;
    out.rootMin[a] = float(origin[a]);
    out.rootMax[a] = float(boxMax(0, a));
    out.cell[a] = float(cell[a]);
    scale = std::max({scale, std::abs(boxMin(0, a)), std::abs(boxMax(0, a))});
  }
  // Rounding of box corners in float can open a hair-thin crack between neighbour leaves
  // that a ray along a shared face slips through; a pad relative to the coordinates closes
  // it (float resolves about 6e-8 relative).
  out.pad = float(1e-6 * std::max(scale, 1e-30));
  out.count = int(count);
  out.rootIsLeaf = packed[11] != 0;
  out.texels.resize(count * 4);

  // Grid coordinate of x, rounded outward, clamped to the root grid.
  auto quantize = [&](double x, int a, bool up) -> std::uint32_t {
    if (!(cell[a] > 0)) return 0;
    const double q = (x - origin[a]) / cell[a];
    // Values within a tiny tolerance of a grid line are on it: exact octree cells stay exact.
    const double r = std::round(q);
    const double snapped = std::abs(q - r) < 1e-6 ? r : (up ? std::ceil(q) : std::floor(q));
    return std::uint32_t(std::clamp(snapped, 0.0, cells));
  };
  for (std::size_t i = 0; i < count; ++i) {
    const double escape = packed[12 * i + 7], leaf = packed[12 * i + 11];
    if (escape != std::floor(escape) || escape <= double(i) || escape > double(count))
      return "hierarchy: node " + std::to_string(i) + " has an invalid escape index";
    if (leaf != 0 && leaf != 1)
      return "hierarchy: node " + std::to_string(i) + " has isLeaf not 0 or 1";
    std::array<std::uint32_t, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      if (boxMin(i, a) > boxMax(i, a))
        return "hierarchy: node " + std::to_string(i) + " has min > max";
      lo[a] = quantize(boxMin(i, a), a, false);
      hi[a] = quantize(boxMax(i, a), a, true);
    }
    std::uint32_t* t = &out.texels[4 * i];
    t[0] = lo[0] | lo[1] << 16;
    t[1] = lo[2] | hi[0] << 16;
    t[2] = hi[1] | hi[2] << 16;
    t[3] = std::uint32_t(escape) << 1 | std::uint32_t(leaf);
  }
  return {};
}

}  // namespace zs
