#pragma once
// A hash map from 64-bit grid keys to dense 32-bit indices (open addressing, linear
// probing): the grid's corners and edges number in the millions, and std::unordered_map's
// node per entry costs more than the evaluations it indexes.
#include <cstdint>
#include <vector>

#include "mesh/huge_pages.hpp"

namespace zs::mesh {

class FlatIndex {
 public:
  static constexpr std::uint32_t kAbsent = 0xffffffffu;

  explicit FlatIndex(std::size_t expected = 1024) { rehash(capacityFor(expected)); }

  std::uint32_t find(std::uint64_t key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key + 1) return values_[i];
      if (keys_[i] == 0) return kAbsent;
    }
  }

  // The index of `key`, inserting `next` when absent; `inserted` says which happened.
  std::uint32_t insert(std::uint64_t key, std::uint32_t next, bool& inserted) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key + 1) {
        inserted = false;
        return values_[i];
      }
      if (keys_[i] == 0) {
        keys_[i] = key + 1;  // 0 marks an empty slot; keys never reach 2^64 - 1
        values_[i] = next;
        ++size_;
        inserted = true;
        return next;
      }
    }
  }

  std::size_t size() const { return size_; }
  void reserve(std::size_t n) {
    if (2 * n > keys_.size()) rehash(capacityFor(n));
  }

 private:
  static std::size_t capacityFor(std::size_t n) {
    std::size_t c = 64;
    while (c < 2 * n) c *= 2;
    return c;
  }
  std::size_t slot(std::uint64_t key) const {
    return std::size_t((key * 0x9E3779B97F4A7C15ull) >> 17) & mask_;
  }
  void rehash(std::size_t capacity) {
    std::vector<std::uint64_t> oldKeys = std::move(keys_);
    std::vector<std::uint32_t> oldValues = std::move(values_);
    keys_ = hugeVector<std::uint64_t>(capacity, 0);
    values_ = hugeVector<std::uint32_t>(capacity, 0);
    mask_ = capacity - 1;
    size_ = 0;
    for (std::size_t i = 0; i < oldKeys.size(); ++i) {
      if (oldKeys[i] == 0) continue;
      bool ignored;
      insert(oldKeys[i] - 1, oldValues[i], ignored);
    }
  }
  void grow() { rehash(keys_.size() * 2); }

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace zs::mesh
