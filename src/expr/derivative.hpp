#pragma once
// Symbolic differentiation: takes a node of a graph, adds dF/dx, dF/dy, dF/dz to the same
// graph and returns their ids. Forward mode over the topological order: no recursion.
#include <array>

#include "expr/graph.hpp"

namespace zs {

NodeId derivative(Graph& g, NodeId root, int axis);
std::array<NodeId, 3> gradient(Graph& g, NodeId root);

}  // namespace zs
