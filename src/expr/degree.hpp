#pragma once
// The total degree of F in x, y, z when F is a polynomial (parameters count as constants).
#include <optional>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

// nothing when F is not a polynomial in x, y, z.
std::optional<int> polynomialDegree(const Graph& g, NodeId root);

// Per node (indexed by id), an upper bound of its degree in x, y, z read from the structure
// alone (max over sums, sum over products, k times for ^k), or -1 where the node is not a
// polynomial; nodes not reachable from root are -1. Unlike polynomialDegree no cancellation
// is ever assumed, so truncating a node's expansion at this degree is always exact.
std::vector<int> structuralDegrees(const Graph& g, NodeId root);

}  // namespace zs
