#pragma once
// The mesher's big arrays (tens to hundreds of megabytes, filled once) asked to be backed by
// 2 MiB pages: on a virtual machine a first touch of a 4 KiB page costs microseconds, and at
// level 8 those faults were a fifth of the run. Debian enables transparent huge pages "on
// madvise"; where it does not, or madvise fails, the hint changes nothing.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace zs::mesh {

inline void adviseHugePages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const std::uintptr_t lo = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t hi = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
}

// v.reserve(n), the new storage advised before anything touches it.
template <class T>
void reserveHuge(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  std::vector<T> grown;
  grown.reserve(n);
  adviseHugePages(grown.data(), n * sizeof(T));
  grown.insert(grown.end(), v.begin(), v.end());
  v.swap(grown);
}

// A vector of n copies of value, in advised storage.
template <class T>
std::vector<T> hugeVector(std::size_t n, const T& value = T{}) {
  std::vector<T> v;
  reserveHuge(v, n);
  v.assign(n, value);
  return v;
}

}  // namespace zs::mesh
