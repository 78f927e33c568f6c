#pragma once
// The total degree of F in x, y, z when F is a polynomial (parameters count as constants).
#include <optional>

#include "expr/graph.hpp"

namespace zs {

// nothing when F is not a polynomial in x, y, z.
std::optional<int> polynomialDegree(const Graph& g, NodeId root);

}  // namespace zs
