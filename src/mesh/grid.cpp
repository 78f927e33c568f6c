#include "mesh/grid.hpp"

#include <algorithm>
#include <thread>

#include "interval/octree.hpp"

namespace zs::mesh {

Grid::Grid(const Box& box, int level, std::span<FieldEvaluator> evaluators)
    : box_(box), level_(level), n_(1u << level), evaluators_(evaluators) {}

P3 Grid::position(std::uint64_t key) const {
  P3 p;
  for (int a = 0; a < 3; ++a) p[std::size_t(a)] = cellCoordinate(box_, a, keyAxis(key, a), level_);
  return p;
}

void Grid::evaluate(std::span<const std::uint64_t> keys) {
  const std::size_t from = vertexKeys_.size();
  for (std::uint64_t k : keys) {
    bool inserted;
    vertexIndex_.insert(k, std::uint32_t(vertexKeys_.size()), inserted);
    if (inserted) vertexKeys_.push_back(k);
  }
  evaluateNew(from);
}

void Grid::evaluateNew(std::size_t from) {
  const std::size_t to = vertexKeys_.size();
  values_.resize(to);
  const std::size_t threads = std::min<std::size_t>(evaluators_.size(), (to - from) / 4096 + 1);
  auto work = [&](std::size_t t) {
    FieldEvaluator& ev = evaluators_[t];
    for (std::size_t i = from + t; i < to; i += threads) values_[i] = ev.value(position(vertexKeys_[i]));
  };
  std::vector<std::jthread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
}

void Grid::reserve(std::size_t cells) {
  cellIndex_.reserve(cells);
  cells_.reserve(cells);
  cellCorners_.reserve(8 * cells);
  vertexIndex_.reserve(2 * cells);
  vertexKeys_.reserve(2 * cells);
  values_.reserve(2 * cells);
}

void Grid::addCells(std::vector<std::uint64_t> pending) {
  while (!pending.empty()) {
    std::vector<std::size_t> added;  // indices into cells_
    const std::size_t from = vertexKeys_.size();
    for (std::uint64_t c : pending) {
      bool inserted;
      cellIndex_.insert(c, std::uint32_t(cells_.size()), inserted);
      if (!inserted) continue;
      added.push_back(cells_.size());
      cells_.push_back(c);
      for (int corner = 0; corner < 8; ++corner) {
        const std::uint64_t k = c + cornerOffset(corner);
        cellCorners_.push_back(vertexIndex_.insert(k, std::uint32_t(vertexKeys_.size()), inserted));
        if (inserted) vertexKeys_.push_back(k);
      }
    }
    evaluateNew(from);
    pending.clear();
    for (std::size_t i : added) {
      const std::uint64_t c = cells_[i];
      int neg = 0;
      for (int corner = 0; corner < 8; ++corner) neg |= int(negative(cellCorners_[8 * i + std::size_t(corner)])) << corner;
      if (neg == 0 || neg == 0xff) continue;
      for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
          int faceNeg = 0, faceCount = 0;
          for (int corner = 0; corner < 8; ++corner)
            if (((corner >> axis) & 1) == side) faceNeg += (neg >> corner) & 1, ++faceCount;
          if (faceNeg == 0 || faceNeg == faceCount) continue;
          const std::uint32_t at = keyAxis(c, axis);
          if (side == 0 ? at == 0 : at + 1 == n_) continue;  // the domain's boundary
          const std::uint64_t step = std::uint64_t(1) << (kKeyBits * axis);
          const std::uint64_t neighbour = side == 0 ? c - step : c + step;
          if (cellIndex_.find(neighbour) == FlatIndex::kAbsent) pending.push_back(neighbour);
        }
      }
    }
  }
}

}  // namespace zs::mesh
