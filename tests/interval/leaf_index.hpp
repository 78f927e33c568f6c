#pragma once
// Answers "does some kept leaf of this octree meet this (small) box?" in a few hash
// lookups per level, for the octree safety tests.
#include <cstdint>
#include <unordered_map>

#include "interval/octree.hpp"

namespace zs::test {

class LeafIndex {
 public:
  explicit LeafIndex(const Octree& tree);
  // True when a kept leaf's closed box intersects the closed box q.
  bool meets(const Box& q) const;

 private:
  static std::uint64_t key(int level, std::uint64_t x, std::uint64_t y, std::uint64_t z) {
    return std::uint64_t(level) << 60 | x << 40 | y << 20 | z;
  }
  const Octree& tree_;
  std::unordered_map<std::uint64_t, std::size_t> leaves_;  // key -> index in tree.leaves
};

}  // namespace zs::test
