#pragma once
#include <cstddef>

namespace zs {

// thesis:  subdivide while 0 may be in F(box) and 0 may be in every gradient component
// uniform: subdivide every box where 0 may be in F(box), down to the maximum level
enum class Criteria { Thesis, Uniform };

struct OctreeSettings {
  int level = 1;  // maximum subdivision level; the domain box is level 0
  Criteria criteria = Criteria::Thesis;
  std::size_t nodeBudget = 20'000'000;  // stop with an error instead of exhausting memory
  unsigned threads = 0;                 // worker threads for the octree; 0 = every core

  bool operator==(const OctreeSettings&) const = default;
};

}  // namespace zs
