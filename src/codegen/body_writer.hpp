#pragma once
// Scalar GLSL statements for graph nodes, shared by the formula block (emit_glsl.cpp) and
// the ray polynomial (emit_ray_polynomial.cpp): every non-leaf node becomes one
// `float tN = <op>(operands);`, integer powers become squaring chains. Internal to codegen.
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

// The GLSL text of every node in `order` (indexed by id): a literal or input for leaves, a
// temporary name otherwise. Computed once so that a node has the same name in every body.
std::vector<std::string> nameNodes(const Graph& g, const std::vector<NodeId>& order);

// Writes the statements of one function body, node by node in topological order.
class BodyWriter {
 public:
  BodyWriter(const Graph& g, const std::vector<std::string>& names) : g_(g), names_(names) {}

  // The statement(s) defining node `id`; `flag` is the bool set where it is undefined.
  void node(NodeId id, const std::string& flag);

  std::string out;
  std::size_t temporaries = 0;

 private:
  const std::string& name(NodeId id) const { return names_[static_cast<std::size_t>(id)]; }
  void declare(const std::string& lhs, const std::string& rhs);
  std::string square(const std::string& base, int i, const std::string& owner);
  void powi(NodeId id, const std::string& base, std::int32_t k, const std::string& flag);

  const Graph& g_;
  const std::vector<std::string>& names_;
  std::unordered_map<std::string, std::string> squares_;  // "base^power" -> temporary
};

}  // namespace zs
