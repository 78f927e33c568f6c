#include "codegen/emit_hessian.hpp"

#include <vector>

#include "codegen/body_writer.hpp"
#include "expr/derivative.hpp"

namespace zs {

std::string emitHessianGlsl(Graph& g, const std::array<NodeId, 3>& grad) {
  std::array<std::array<NodeId, 3>, 3> h{};
  for (int i = 0; i < 3; ++i) h[i] = gradient(g, grad[i]);
  std::vector<NodeId> roots;
  for (const auto& row : h) roots.insert(roots.end(), row.begin(), row.end());
  const std::vector<NodeId> order = reachable(g, roots);
  const std::vector<std::string> names = nameNodes(g, order);
  BodyWriter body(g, names);
  for (NodeId id : order) body.node(id, "zs_uh");
  auto name = [&](NodeId id) { return names[static_cast<std::size_t>(id)]; };
  std::string s =
      "\n// Second derivatives of F (src/codegen/emit_hessian.cpp), for curvature coloring.\n";
  s += "mat3 zs_FHess(vec3 p) {\n";
  s += "  bool zs_uh = false;  // set where a second derivative is undefined (not used)\n";
  s += body.out;
  // mat3(a, b, c, ...) fills columns; H is symmetric, column j = d(grad F)/dx_j.
  s += "  return mat3(";
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) s += name(h[i][j]) + (i == 2 && j == 2 ? "" : ", ");
  }
  s += ");\n}\n";
  return s;
}

}  // namespace zs
