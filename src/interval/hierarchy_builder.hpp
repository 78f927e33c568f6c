#pragma once
// The box hierarchy builder: takes an octree's leaves (pre-order, with their cells),
// puts out the BoxHierarchy of hierarchy.hpp. Inner nodes exist only on the way to a
// kept leaf (subtrees with nothing kept are pruned), an inner node's box is the tight
// union of its children's boxes, and an inner node with a single child is dropped (its
// child has the same box), which shortens the GPU walk. docs/hierarchy.md has the layout.
#include "interval/hierarchy.hpp"
#include "interval/octree.hpp"

namespace zs {

// With `clip` (the surface's bounds, surface_bounds.hpp), every leaf's box is cut to it and
// leaves outside it are left out: the boxes stay a cover of the surface, and the exact
// tracing methods, which clip rays to them, walk less empty space.
BoxHierarchy buildBoxHierarchy(const Octree& tree, const Box* clip = nullptr);

// A node for `box`, not yet linked (escape 0, not a leaf), with the sphere around the box:
// its center, radius = half the diagonal (the smallest sphere that holds the box; the
// thesis' eq. 4.2 writes the full diagonal, twice as large).
BoxNode boxNode(const Box& box);

}  // namespace zs
