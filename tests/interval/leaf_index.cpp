#include "leaf_index.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace zs::test {

LeafIndex::LeafIndex(const Octree& tree) : tree_(tree) {
  assert(tree.settings.level < 16);  // the key packs the level into 4 bits
  leaves_.reserve(tree.leaves.size());
  for (std::size_t i = 0; i < tree.leaves.size(); ++i) {
    const OctreeLeaf& l = tree.leaves[i];
    leaves_.emplace(key(l.level, l.cell[0], l.cell[1], l.cell[2]), i);
  }
}

bool LeafIndex::meets(const Box& q) const {
  const Box& d = tree_.domain;
  for (int level = 0; level <= tree_.settings.level; ++level) {
    const double n = std::ldexp(1.0, level);
    std::int64_t lo[3], hi[3];
    for (std::size_t a = 0; a < 3; ++a) {
      // Cells whose index range could meet q; one cell of slack covers rounding at faces.
      const double w = d.max[a] - d.min[a];
      const double u0 = (q.min[a] - d.min[a]) / w * n, u1 = (q.max[a] - d.min[a]) / w * n;
      const double eps = 1e-9 * n;
      lo[a] = std::max<std::int64_t>(0, std::int64_t(std::floor(u0 - eps)));
      hi[a] = std::min<std::int64_t>(std::int64_t(n) - 1, std::int64_t(std::floor(u1 + eps)));
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const auto it =
              leaves_.find(key(level, std::uint64_t(x), std::uint64_t(y), std::uint64_t(z)));
          if (it == leaves_.end()) continue;
          const Box& b = tree_.leaves[it->second].box;
          bool overlap = true;
          for (std::size_t a = 0; a < 3; ++a)
            overlap = overlap && b.min[a] <= q.max[a] && q.min[a] <= b.max[a];
          if (overlap) return true;
        }
  }
  return false;
}

}  // namespace zs::test
