#pragma once
// The surface's bounding box: takes a formula, its parameter values and a domain (box, or
// ball inside its bounding box), puts out the smallest box, on the grid of 2^level cells per
// axis of the domain, that holds every cell where interval arithmetic cannot rule out a
// point of F = 0. Every surface point of the domain lies in it; it is empty (isEmpty,
// hierarchy.hpp) when no cell can hold one.
//
// Why: the octree's leaves at the levels users trace with (1-3) are coarse, and the exact
// tracing methods clip each ray to them; a surface that fills a small part of a generous
// domain (a sphere in [-1.5, 1.5]^3, metaballs) leaves rays walking through proven-empty
// space. A uniform subdivision to level 6 would cost up to 2^18 evaluations; the bound of
// each of the six faces is instead found by a best-first search that refines the cell
// reaching furthest out first, so only the cells near the extreme are ever evaluated.
#include <cstddef>
#include <optional>
#include <span>

#include "expr/graph.hpp"
#include "interval/hierarchy.hpp"
#include "interval/octree.hpp"

namespace zs {

struct SurfaceBoundsSettings {
  int level = 6;  // the grid: 2^level cells per axis of the domain
  // Interval evaluations per face, then the bound so far; fewer for a formula whose tape
  // is longer than 256 instructions (2^20 instructions per face at most).
  std::size_t faceBudget = 4096;
};

// Conservative whatever the budget: a face whose search runs out of evaluations keeps the
// furthest extent of the cells still unexamined. Formula, params and domain must be valid
// for buildOctree (it checks them first in every pipeline).
Box surfaceBounds(const Formula& formula, std::span<const double> params, const Box& domain,
                  const std::optional<Ball>& ball, const SurfaceBoundsSettings& settings = {});

}  // namespace zs
