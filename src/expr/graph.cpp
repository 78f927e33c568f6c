#include "expr/graph.hpp"

#include <cassert>
#include <cmath>
#include <functional>

#include "expr/bit_cast.hpp"
#include "expr/tape.hpp"

namespace zs {

bool Node::operator==(const Node& o) const {
  return op == o.op && a == o.a && b == o.b && ival == o.ival &&
         bitCast<std::uint64_t>(value) == bitCast<std::uint64_t>(o.value);
}

std::size_t Graph::NodeHash::operator()(const Node& n) const {
  std::uint64_t h = static_cast<std::uint64_t>(n.op);
  auto mix = [&h](std::uint64_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
  mix(static_cast<std::uint32_t>(n.a));
  mix(static_cast<std::uint32_t>(n.b));
  mix(static_cast<std::uint32_t>(n.ival));
  mix(bitCast<std::uint64_t>(n.value));
  return static_cast<std::size_t>(h);
}

namespace {

// Operations that are defined (never NaN from a domain restriction) for every finite input.
bool opIsTotal(Op op) {
  switch (op) {
    case Op::Div:
    case Op::Pow:
    case Op::Tan:
    case Op::Asin:
    case Op::Acos:
    case Op::Log:
    case Op::Sqrt:
      return false;
    case Op::Const:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::PowI:
    case Op::Sin:
    case Op::Cos:
    case Op::Atan:
    case Op::Atan2:
    case Op::Sinh:
    case Op::Cosh:
    case Op::Tanh:
    case Op::Exp:
    case Op::Cbrt:
    case Op::Abs:
    case Op::Sign:
    case Op::Floor:
    case Op::Ceil:
    case Op::Min:
    case Op::Max:
    case Op::IfDefined:  // defined where b is (0 where a is not): total when its operands are
      return true;
  }
  return false;
}

}  // namespace

NodeId Graph::find(const Node& n) const {
  const auto it = index_.find(n);
  return it != index_.end() ? it->second : kNoNode;
}

NodeId Graph::intern(const Node& n) {
  if (auto it = index_.find(n); it != index_.end()) return it->second;
  const auto id = static_cast<NodeId>(nodes_.size());
  const int arity = opInfo(n.op).arity;
  bool total = opIsTotal(n.op) && !(n.op == Op::PowI && n.ival < 0);
  bool spatial = n.op == Op::VarX || n.op == Op::VarY || n.op == Op::VarZ;
  if (arity >= 1) {
    total = total && isTotal(n.a);
    spatial = spatial || spatial_[static_cast<std::size_t>(n.a)];
  }
  if (arity >= 2) {
    total = total && isTotal(n.b);
    spatial = spatial || spatial_[static_cast<std::size_t>(n.b)];
  }
  nodes_.push_back(n);
  total_.push_back(total);
  spatial_.push_back(spatial);
  index_.emplace(n, id);
  return id;
}

NodeId Graph::constant(double v) {
  Node n;
  n.op = Op::Const;
  n.value = v;
  return intern(n);
}

NodeId Graph::var(int axis) {
  assert(axis >= 0 && axis < 3);
  Node n;
  n.op = axis == 0 ? Op::VarX : axis == 1 ? Op::VarY : Op::VarZ;
  return intern(n);
}

int Graph::paramIndex(std::string_view name) const {
  for (std::size_t i = 0; i < params_.size(); ++i) {
    if (params_[i] == name) return static_cast<int>(i);
  }
  return -1;
}

NodeId Graph::param(std::string_view name) {
  int index = paramIndex(name);
  if (index < 0) {
    index = static_cast<int>(params_.size());
    params_.emplace_back(name);
  }
  Node n;
  n.op = Op::Param;
  n.ival = index;
  return intern(n);
}

// Constant folding: only when the result is finite, so a formula never gains an inf or NaN
// literal that the language cannot spell, and 1/0 keeps meaning "undefined here".
NodeId Graph::fold(Op op, NodeId a, NodeId b) {
  const double va = (*this)[a].value;
  const double vb = b == kNoNode ? 0.0 : (*this)[b].value;
  const double r = applyScalar(op, va, vb, 0, 0.0);
  if (!std::isfinite(r)) return kNoNode;
  return constant(r);
}

NodeId Graph::unary(Op op, NodeId a) {
  assert(opInfo(op).arity == 1 && op != Op::PowI);
  const Node& na = (*this)[a];
  if (na.op == Op::Const) {
    if (NodeId f = fold(op, a, kNoNode); f != kNoNode) return f;
  }
  if (op == Op::Neg && na.op == Op::Neg) return na.a;
  Node n;
  n.op = op;
  n.a = a;
  return intern(n);
}

NodeId Graph::powi(NodeId a, int exponent) {
  const Node na = (*this)[a];
  if (exponent == 1) return a;
  if (exponent == 0 && isTotal(a)) return constant(1.0);
  if (na.op == Op::Const) {
    const double r = applyScalar(Op::PowI, na.value, 0, exponent, 0);
    if (std::isfinite(r)) return constant(r);
  }
  // (a^m)^n = a^(m n) for positive m, n; negative ones could change where it is defined.
  if (na.op == Op::PowI && na.ival > 0 && exponent > 0 &&
      static_cast<long long>(na.ival) * exponent <= kMaxIntegerExponent) {
    return powi(na.a, na.ival * exponent);
  }
  if (na.op == Op::Neg && exponent % 2 == 0) return powi(na.a, exponent);
  Node n;
  n.op = Op::PowI;
  n.a = a;
  n.ival = exponent;
  return intern(n);
}

NodeId Graph::binary(Op op, NodeId a, NodeId b) {
  assert(opInfo(op).arity == 2);
  const Node na = (*this)[a];
  const Node nb = (*this)[b];
  const bool ca = na.op == Op::Const, cb = nb.op == Op::Const;
  if (ca && cb) {
    if (NodeId f = fold(op, a, b); f != kNoNode) return f;
  }
  auto is = [](const Node& n, double v) { return n.op == Op::Const && n.value == v; };
  switch (op) {
    case Op::Add:
      if (is(na, 0)) return b;
      if (is(nb, 0)) return a;
      if (nb.op == Op::Neg) return binary(Op::Sub, a, nb.a);
      break;
    case Op::Sub:
      if (is(nb, 0)) return a;
      if (is(na, 0)) return unary(Op::Neg, b);
      if (a == b && isTotal(a)) return constant(0.0);
      if (nb.op == Op::Neg) return binary(Op::Add, a, nb.a);
      break;
    case Op::Mul:
      if (cb && !ca) return binary(Op::Mul, b, a);  // constants go left: 2*x, never x*2
      if (is(na, 1)) return b;
      if (is(na, 0) && isTotal(b)) return a;
      if (is(na, -1)) return unary(Op::Neg, b);
      if (a == b) return powi(a, 2);
      if (ca && nb.op == Op::Mul && (*this)[nb.a].op == Op::Const) {
        const NodeId c = fold(Op::Mul, a, nb.a);
        if (c != kNoNode) return binary(Op::Mul, c, nb.b);
      }
      break;
    case Op::Div:
      if (is(nb, 1)) return a;
      break;
    case Op::Pow:
      if (cb && std::nearbyint(nb.value) == nb.value &&
          std::fabs(nb.value) <= kMaxIntegerExponent) {
        return powi(a, static_cast<int>(nb.value));
      }
      break;
    default:
      break;
  }
  Node n;
  n.op = op;
  n.a = a;
  n.b = b;
  return intern(n);
}

NodeId copyInto(Graph& to, const Graph& from, NodeId root) {
  std::vector<NodeId> mapped(from.size(), kNoNode);
  for (const NodeId id : reachable(from, {root})) {
    const Node& n = from[id];
    NodeId m = kNoNode;
    switch (n.op) {
      case Op::Const:
        m = to.constant(n.value);
        break;
      case Op::VarX:
        m = to.var(0);
        break;
      case Op::VarY:
        m = to.var(1);
        break;
      case Op::VarZ:
        m = to.var(2);
        break;
      case Op::Param:
        m = to.param(from.params()[static_cast<std::size_t>(n.ival)]);
        break;
      case Op::PowI:
        m = to.powi(mapped[static_cast<std::size_t>(n.a)], n.ival);
        break;
      default:
        m = opInfo(n.op).arity == 1 ? to.unary(n.op, mapped[static_cast<std::size_t>(n.a)])
                                    : to.binary(n.op, mapped[static_cast<std::size_t>(n.a)],
                                                mapped[static_cast<std::size_t>(n.b)]);
    }
    mapped[static_cast<std::size_t>(id)] = m;
  }
  return mapped[static_cast<std::size_t>(root)];
}

std::vector<NodeId> reachable(const Graph& g, const std::vector<NodeId>& roots) {
  std::vector<char> mark(g.size(), 0);
  for (NodeId r : roots) mark[static_cast<std::size_t>(r)] = 1;
  // Operands have smaller ids: one downward sweep marks everything reachable.
  for (std::size_t i = g.size(); i-- > 0;) {
    if (!mark[i]) continue;
    const Node& n = g[static_cast<NodeId>(i)];
    const int arity = opInfo(n.op).arity;
    if (arity >= 1) mark[static_cast<std::size_t>(n.a)] = 1;
    if (arity >= 2) mark[static_cast<std::size_t>(n.b)] = 1;
  }
  std::vector<NodeId> out;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (mark[i]) out.push_back(static_cast<NodeId>(i));
  }
  return out;
}

NodeId definedOrOne(Graph& g, NodeId f) {
  if (g.isTotal(f)) return f;
  const NodeId one = g.constant(1.0);
  return g.binary(Op::Add, g.binary(Op::IfDefined, f, g.binary(Op::Sub, f, one)), one);
}

}  // namespace zs
