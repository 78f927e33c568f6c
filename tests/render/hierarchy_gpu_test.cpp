// The one-texel-per-node repack of the box hierarchy.
#include "render/hierarchy_gpu.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace zs {
namespace {

// 12 floats per node as in interval/hierarchy.hpp.
void addNode(std::vector<float>& out, std::array<float, 3> lo, std::array<float, 3> hi, int escape,
             bool leaf) {
  float r = 0;
  for (int a = 0; a < 3; ++a) r += (hi[a] - lo[a]) * (hi[a] - lo[a]);
  out.insert(out.end(),
             {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2, std::sqrt(r) / 2,
              lo[0], lo[1], lo[2], float(escape), hi[0], hi[1], hi[2], leaf ? 1.0f : 0.0f});
}

TEST(HierarchyGpu, PacksOctreeCellsExactly) {
  std::vector<float> packed;
  addNode(packed, {-2, -1, 0}, {2, 1, 4}, 3, false);
  addNode(packed, {-2, -1, 0}, {0, 0, 2}, 2, true);  // child cell (0,0,0) at level 1
  addNode(packed, {0, 0, 2}, {2, 1, 4}, 3, true);    // child cell (1,1,1)
  GpuHierarchy gpu;
  ASSERT_EQ(toGpuHierarchy(packed, gpu), "");
  ASSERT_EQ(gpu.count, 3);
  EXPECT_EQ(gpu.rootMin, (std::array<float, 3>{-2, -1, 0}));
  EXPECT_FLOAT_EQ(gpu.cell[0], 4.0f / (1 << GpuHierarchy::kGridBits));
  const std::uint32_t full = 1u << GpuHierarchy::kGridBits, half = full / 2;
  // node 1: qmin = (0,0,0), qmax = (half, half, half), escape 2, leaf
  EXPECT_EQ(gpu.texels[4], 0u);
  EXPECT_EQ(gpu.texels[5], half << 16);
  EXPECT_EQ(gpu.texels[6], half | half << 16);
  EXPECT_EQ(gpu.texels[7], 2u << 1 | 1u);
  // node 2: qmin = half, qmax = full
  EXPECT_EQ(gpu.texels[8], half | half << 16);
  EXPECT_EQ(gpu.texels[9], half | full << 16);
  EXPECT_EQ(gpu.texels[11], 3u << 1 | 1u);
  EXPECT_EQ(gpu.texels[3], 3u << 1);  // root: inner node
  EXPECT_GT(gpu.pad, 0.0f);
  EXPECT_FALSE(gpu.rootIsLeaf);  // the walk may skip node 0
  EXPECT_EQ(gpu.rootMax, (std::array<float, 3>{2, 1, 4}));
  for (std::uint32_t word : gpu.texels) EXPECT_LT(word, 1u << 31);  // see hierarchy_gpu.hpp
}

TEST(HierarchyGpu, NonGridBoxesAreRoundedOutward) {
  std::vector<float> packed;
  addNode(packed, {0, 0, 0}, {1, 1, 1}, 2, false);
  addNode(packed, {0.30001f, 0.2f, 0.1f}, {0.70001f, 0.5f, 0.9f}, 2, true);
  GpuHierarchy gpu;
  ASSERT_EQ(toGpuHierarchy(packed, gpu), "");
  const double cell = 1.0 / (1 << GpuHierarchy::kGridBits);
  const std::uint32_t lo = gpu.texels[4] & 0xFFFF, hi = gpu.texels[5] >> 16;
  EXPECT_LE(lo * cell, 0.30001);
  EXPECT_GT((lo + 1) * cell, 0.30001);
  EXPECT_GE(hi * cell, 0.70001);
}

TEST(HierarchyGpu, EmptyIsValidAndMalformedInputIsRejected) {
  GpuHierarchy gpu;
  EXPECT_EQ(toGpuHierarchy({}, gpu), "");
  EXPECT_EQ(gpu.count, 0);

  std::vector<float> good;
  addNode(good, {0, 0, 0}, {1, 1, 1}, 1, true);
  ASSERT_EQ(toGpuHierarchy(good, gpu), "");
  EXPECT_TRUE(gpu.rootIsLeaf);  // a lone leaf must still be fetched
  std::vector<float> bad = good;
  bad.pop_back();
  EXPECT_NE(toGpuHierarchy(bad, gpu), "");  // not 12 per node
  bad = good;
  bad[7] = 0;  // escape does not move forward: would loop forever on the GPU
  EXPECT_NE(toGpuHierarchy(bad, gpu), "");
  bad = good;
  bad[7] = 2;  // escape past the end
  EXPECT_NE(toGpuHierarchy(bad, gpu), "");
  bad = good;
  bad[11] = 0.5f;
  EXPECT_NE(toGpuHierarchy(bad, gpu), "");
  bad = good;
  bad[4] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(toGpuHierarchy(bad, gpu), "");
  bad = good;
  bad[4] = 2;  // min > max
  EXPECT_NE(toGpuHierarchy(bad, gpu), "");
}

}  // namespace
}  // namespace zs
