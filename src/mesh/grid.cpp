#include "mesh/grid.hpp"

#include "interval/octree.hpp"

namespace zs::mesh {

Grid::Grid(const Box& box, int level)
    : box_(box), level_(level), n_(1u << level), b_(1u << (level - brickLevel(level))) {}

P3 Grid::position(std::uint64_t key) const {
  P3 p;
  for (int a = 0; a < 3; ++a) p[std::size_t(a)] = cellCoordinate(box_, a, keyAxis(key, a), level_);
  return p;
}

std::uint64_t Grid::brickOrigin(std::uint64_t brick) const {
  return packKey(std::uint64_t(keyAxis(brick, 0)) * b_, std::uint64_t(keyAxis(brick, 1)) * b_,
                 std::uint64_t(keyAxis(brick, 2)) * b_);
}

void Grid::evaluateBrick(std::uint64_t brick, FieldEvaluator& evaluator,
                         std::span<double> values) const {
  constexpr std::size_t kMaxCorners = 5;
  const std::uint32_t m = b_ + 1;
  const std::uint64_t origin = brickOrigin(brick);
  double axis[3][kMaxCorners];
  for (int a = 0; a < 3; ++a)
    for (std::uint32_t k = 0; k < m; ++k)
      axis[a][k] = cellCoordinate(box_, a, keyAxis(origin, a) + k, level_);
  double xs[kMaxCorners * kMaxCorners * kMaxCorners], ys[std::size(xs)], zs[std::size(xs)];
  std::size_t at = 0;
  for (std::uint32_t z = 0; z < m; ++z)
    for (std::uint32_t y = 0; y < m; ++y)
      for (std::uint32_t x = 0; x < m; ++x, ++at)
        xs[at] = axis[0][x], ys[at] = axis[1][y], zs[at] = axis[2][z];
  evaluator.values({xs, at}, {ys, at}, {zs, at}, values.first(at));
}

void Grid::crossedNeighbours(std::uint64_t brick, const double* values,
                             std::vector<std::uint64_t>& out) const {
  const std::uint32_t m = b_ + 1;
  const std::size_t stride[3] = {1, m, std::size_t(m) * m};
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t at = keyAxis(brick, axis);
      if (side == 0 ? at == 0 : at + 1 == bricksPerAxis()) continue;  // the domain's boundary
      const double* face = values + (side ? b_ * stride[axis] : 0);
      const bool first = face[0] < 0;
      bool mixed = false;
      for (std::uint32_t j = 0; j < m && !mixed; ++j)
        for (std::uint32_t i = 0; i < m && !mixed; ++i)
          mixed = (face[i * stride[u] + j * stride[v]] < 0) != first;
      if (!mixed) continue;
      const std::uint64_t step = std::uint64_t(1) << (kKeyBits * axis);
      out.push_back(side == 0 ? brick - step : brick + step);
    }
  }
}

}  // namespace zs::mesh
