#pragma once
// GLSL for the second derivatives of a formula, emitted only for the colorings that need
// them (shading.color = "gauss" or "mean", docs/curvature.md). Takes the graph with F and
// its gradient (expr/derivative.hpp), differentiates each gradient component once more in
// the same graph and puts out one function, appended to the formula block:
//
//   mat3 zs_FHess(vec3 p) { ... }   // column j = d(grad F)/d(x_j); symmetric
//
// Written like zs_FGrad (one temporary per node, codegen/body_writer.hpp); points outside
// the domain of a second derivative give whatever the operations give there (the coloring
// shows them, nothing else depends on them).
#include <array>
#include <string>

#include "expr/graph.hpp"

namespace zs {

// Adds the second derivatives of F to `g` (grad: the nodes returned by gradient(g, f)).
std::string emitHessianGlsl(Graph& g, const std::array<NodeId, 3>& grad);

}  // namespace zs
