#pragma once
// Symbolic differentiation: takes a node of a graph, adds dF/dx, dF/dy, dF/dz to the same
// graph and returns their ids. Forward mode over the topological order: no recursion.
#include <array>

#include "expr/graph.hpp"

namespace zs {

NodeId derivative(Graph& g, NodeId root, int axis);
std::array<NodeId, 3> gradient(Graph& g, NodeId root);
// The derivative of root along a direction whose components are the nodes `direction` (any
// nodes of g, e.g. the ray direction's components as leaves of their own): grad F . direction
// in one forward pass, without the three partial derivatives.
NodeId directionalDerivative(Graph& g, NodeId root, const std::array<NodeId, 3>& direction);

}  // namespace zs
