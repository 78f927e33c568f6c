#pragma once
// The uniform grid of 2^level cells per axis, visited brick by brick. A brick is the block
// of 4 x 4 x 4 cells under one box of the interval octree two levels above the grid (the
// octree stops there: at its last two levels the interval tests cost more than evaluating F
// at every corner), and F is evaluated at all 5^3 corners of a brick together, by the batch
// evaluator. marchBricks (march.hpp) takes the octree's boxes and closes them under "the
// zero set crosses the brick's face to a brick not yet taken", so every cell the zero set
// crosses lies in a marched brick whatever rounding did to the octree: the mesh never ends
// on a face it should cross.
#include <cstdint>
#include <span>
#include <vector>

#include "interval/hierarchy.hpp"
#include "mesh/field.hpp"

namespace zs::mesh {

// A corner (or a cell, or a brick, by its lowest corner) packed as x | y << 20 | z << 40.
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

// The octree level whose boxes are the grid's bricks.
inline int brickLevel(int gridLevel) {
  return gridLevel > 2 ? gridLevel - 2 : 0;
}

class Grid {
 public:
  Grid(const Box& box, int level);

  std::uint32_t cellsPerAxis() const { return n_; }
  std::uint32_t brickCells() const { return b_; }  // cells along a brick's edge
  std::uint32_t bricksPerAxis() const { return n_ / b_; }
  std::size_t brickCornerCount() const { return std::size_t(b_ + 1) * (b_ + 1) * (b_ + 1); }
  P3 position(std::uint64_t cornerKey) const;
  // The key of a brick's lowest corner on the grid.
  std::uint64_t brickOrigin(std::uint64_t brick) const;

  // The field at the brick's corners, x fastest then y then z (brickCornerCount() values),
  // at the coordinates position() gives, so every user of a corner sees one value.
  void evaluateBrick(std::uint64_t brick, FieldEvaluator& evaluator,
                     std::span<double> values) const;
  // The bricks beside this one across the faces the zero set crosses (its corners there
  // are not all of one sign), inside the domain.
  void crossedNeighbours(std::uint64_t brick, const double* values,
                         std::vector<std::uint64_t>& out) const;

 private:
  Box box_;
  int level_;
  std::uint32_t n_, b_;
};

}  // namespace zs::mesh
