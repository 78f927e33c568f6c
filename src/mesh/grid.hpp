#pragma once
// The sparse grid: the cells of the uniform 2^level grid that are marched, and the field's
// value at their corners. Cells come from seeds (the octree's leaves) and are closed under
// "the zero set crosses a face shared with a cell not yet taken": the marched zero set then
// never ends on such a face, so the mesh is closed whatever rounding did to the seeds.
#include <cstdint>
#include <span>
#include <vector>

#include "interval/hierarchy.hpp"
#include "mesh/field.hpp"
#include "mesh/flat_index.hpp"

namespace zs::mesh {

// A corner (or a cell, by its lowest corner) packed as x | y << 20 | z << 40.
inline constexpr int kKeyBits = 20;
inline std::uint64_t packKey(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
  return x | (y << kKeyBits) | (z << (2 * kKeyBits));
}
inline std::uint32_t keyAxis(std::uint64_t key, int axis) {
  return std::uint32_t((key >> (kKeyBits * axis)) & ((1u << kKeyBits) - 1));
}
// The offset from a cell's key to its corner c (bit a of c: +1 along axis a).
inline std::uint64_t cornerOffset(int c) {
  return packKey(std::uint64_t(c & 1), std::uint64_t((c >> 1) & 1), std::uint64_t((c >> 2) & 1));
}

class Grid {
 public:
  Grid(const Box& box, int level, std::span<FieldEvaluator> evaluators);

  std::uint32_t cellsPerAxis() const { return n_; }
  P3 position(std::uint64_t vertexKey) const;

  // Evaluates the corners not yet known (in parallel, one evaluator per thread).
  void evaluate(std::span<const std::uint64_t> vertexKeys);
  // Takes the seeds and every cell the closure rule reaches from them.
  void addCells(std::vector<std::uint64_t> seeds);
  // Sizes the tables for about this many cells, so they do not grow step by step.
  void reserve(std::size_t cells);

  std::uint32_t vertex(std::uint64_t key) const { return vertexIndex_.find(key); }
  double value(std::uint32_t vertex) const { return values_[vertex]; }
  bool negative(std::uint32_t vertex) const { return values_[vertex] < 0; }
  const std::vector<std::uint64_t>& cells() const { return cells_; }
  // The corners of cell i (index into cells()), as vertex indices, corner c = bits xyz.
  const std::uint32_t* cellCorners(std::size_t i) const { return &cellCorners_[8 * i]; }
  std::size_t valueCount() const { return values_.size(); }

 private:
  void evaluateNew(std::size_t from);

  Box box_;
  int level_;
  std::uint32_t n_;
  std::span<FieldEvaluator> evaluators_;
  FlatIndex vertexIndex_{1 << 16};
  std::vector<std::uint64_t> vertexKeys_;
  std::vector<double> values_;
  FlatIndex cellIndex_{1 << 16};
  std::vector<std::uint64_t> cells_;
  std::vector<std::uint32_t> cellCorners_;  // 8 per cell
};

}  // namespace zs::mesh
