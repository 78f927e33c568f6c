#pragma once
// The expression graph: takes operations from the parser (or the derivative), puts out a
// hash-consed DAG in which every node's operands have smaller ids. Iterating ids upward is
// therefore a topological order, so no pass over the graph ever needs recursion.
//
// The builder methods simplify as they build (constant folding, x+0, x*1, x^1, x*x -> x^2,
// nested integer powers), never in a way that changes where F is defined: x*0 folds to 0
// only when x is defined everywhere.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "expr/opcode.hpp"

namespace zs {

using NodeId = std::int32_t;
inline constexpr NodeId kNoNode = -1;

struct Node {
  Op op = Op::Const;
  NodeId a = kNoNode;     // first operand
  NodeId b = kNoNode;     // second operand
  double value = 0.0;     // Const: its value
  std::int32_t ival = 0;  // PowI: the exponent; Param: index into Graph::params()

  // Bitwise on `value`, so -0.0 and 0.0 stay distinct and NaN equals itself: hash-consing
  // must never merge two constants that print differently.
  bool operator==(const Node& o) const;
};

// Largest |n| accepted in x^n; larger exponents are written with pow().
inline constexpr int kMaxIntegerExponent = 1024;

// Deepest nesting the parser accepts: parentheses, calls, unary signs and powers, each a
// level. The printer gives up on a graph whose text would nest deeper.
inline constexpr int kMaxNesting = 256;

class Graph {
 public:
  NodeId constant(double v);
  NodeId var(int axis);  // 0 = x, 1 = y, 2 = z
  NodeId param(std::string_view name);
  NodeId unary(Op op, NodeId a);
  NodeId binary(Op op, NodeId a, NodeId b);
  NodeId powi(NodeId a, int exponent);

  // The id of a node equal to n (operands, value, exponent) if the graph has one, else kNoNode.
  NodeId find(const Node& n) const;

  const Node& operator[](NodeId id) const { return nodes_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return nodes_.size(); }
  const std::vector<std::string>& params() const { return params_; }
  int paramIndex(std::string_view name) const;  // -1 when absent

  // True when the node is defined (finite-valued op, no domain restriction) for all inputs.
  bool isTotal(NodeId id) const { return total_[static_cast<std::size_t>(id)]; }
  bool isConst(NodeId id) const { return (*this)[id].op == Op::Const; }
  // True when the node depends on none of x, y, z (parameters allowed).
  bool isSpatiallyConstant(NodeId id) const { return !spatial_[static_cast<std::size_t>(id)]; }

 private:
  struct NodeHash {
    std::size_t operator()(const Node& n) const;
  };
  NodeId intern(const Node& n);
  NodeId fold(Op op, NodeId a, NodeId b);

  std::vector<Node> nodes_;
  std::vector<bool> total_;
  std::vector<bool> spatial_;
  std::unordered_map<Node, NodeId, NodeHash> index_;
  std::vector<std::string> params_;
};

// The node `root` of `from` rebuilt in `to` (through to's builder methods, so shared
// subexpressions merge and parameters match by name); returns its id in `to`.
NodeId copyInto(Graph& to, const Graph& from, NodeId root);

// f where f is defined, else 1: IfDefined(f, f - 1) + 1, or f itself where it is total. The
// product of several surfaces takes each factor so (scene/surfaces.cpp).
NodeId definedOrOne(Graph& g, NodeId f);

// Nodes reachable from `roots`, in increasing id order (a topological order).
std::vector<NodeId> reachable(const Graph& g, const std::vector<NodeId>& roots);

// A parsed formula F(x, y, z): the graph and the root of F.
struct Formula {
  Graph graph;
  NodeId root = kNoNode;
};

}  // namespace zs
