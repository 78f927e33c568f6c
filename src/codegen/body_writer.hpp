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

// a || b for GLSL bool expressions, where "false" and "true" are known values.
std::string glslOr(const std::string& a, const std::string& b);

// Writes the statements of one function body, node by node in topological order.
//
// A graph without IfDefined needs one flag per body: every node that can be undefined
// reports to the `flag` its caller names. A graph with IfDefined (several surfaces, one of
// which may be undefined somewhere) needs to know whether each operand of an IfDefined is
// defined, so every node gets its own flag, `u_<name>` (false and true where that is
// known), the OR of its operands' and its own; the caller reads the roots' with flagOf().
class BodyWriter {
 public:
  BodyWriter(const Graph& g, const std::vector<std::string>& names);

  // The statement(s) defining node `id`; `flag` is the bool set where it is undefined (not
  // used with per-node flags).
  void node(NodeId id, const std::string& flag);

  // Per-node flags (the graph has IfDefined) and, with them, the GLSL bool expression that
  // is true where a written node is undefined.
  bool perNodeFlags() const { return perNode_; }
  const std::string& flagOf(NodeId id) const { return flags_[static_cast<std::size_t>(id)]; }
  // The statement that sets zs_standIns (raytrace_prelude.frag.glsl): bit i for the i-th
  // IfDefined of `nodes` whose first operand is undefined.
  std::string standIns(const std::vector<NodeId>& nodes) const;

  std::string out;
  std::size_t temporaries = 0;

 private:
  void nodeWithOwnFlag(NodeId id);
  const std::string& name(NodeId id) const { return names_[static_cast<std::size_t>(id)]; }
  void declare(const std::string& lhs, const std::string& rhs);
  std::string square(const std::string& base, int i, const std::string& owner);
  void powi(NodeId id, const std::string& base, std::int32_t k, const std::string& flag);

  const Graph& g_;
  const std::vector<std::string>& names_;
  std::unordered_map<std::string, std::string> squares_;  // "base^power" -> temporary
  bool perNode_ = false;
  std::vector<std::string> flags_;  // per node: "false", "true" or its flag's name
};

}  // namespace zs
