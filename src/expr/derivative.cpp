#include "expr/derivative.hpp"

#include <vector>

namespace zs {

namespace {

// Builds derivative terms, skipping products with a zero factor: the derivative is only
// ever evaluated where F is defined, so 0 * (anything) may be dropped here even when the
// general simplifier must keep it.
struct Builder {
  Graph& g;
  bool zero(NodeId id) const { return g[id].op == Op::Const && g[id].value == 0.0; }
  NodeId c(double v) { return g.constant(v); }
  NodeId add(NodeId a, NodeId b) { return zero(a) ? b : zero(b) ? a : g.binary(Op::Add, a, b); }
  NodeId sub(NodeId a, NodeId b) {
    return zero(b) ? a : zero(a) ? g.unary(Op::Neg, b) : g.binary(Op::Sub, a, b);
  }
  NodeId mul(NodeId a, NodeId b) { return zero(a) || zero(b) ? c(0) : g.binary(Op::Mul, a, b); }
  NodeId div(NodeId a, NodeId b) { return zero(a) ? c(0) : g.binary(Op::Div, a, b); }
  NodeId neg(NodeId a) { return zero(a) ? a : g.unary(Op::Neg, a); }
  NodeId fn(Op op, NodeId a) { return g.unary(op, a); }
  NodeId sq(NodeId a) { return g.powi(a, 2); }
};

NodeId derive(Builder& B, NodeId self, const Node& n, NodeId da, NodeId db) {
  Graph& g = B.g;
  const NodeId a = n.a, b = n.b;
  switch (n.op) {
    case Op::Const:
    case Op::Param:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
      return B.c(0);  // handled by the caller; kept for -Werror=switch
    case Op::Neg:
      return B.neg(da);
    case Op::Add:
      return B.add(da, db);
    case Op::Sub:
      return B.sub(da, db);
    case Op::Mul:
      return B.add(B.mul(da, b), B.mul(a, db));
    case Op::Div:  // (da*b - a*db) / b^2
      if (B.zero(db)) return B.div(da, b);
      return B.div(B.sub(B.mul(da, b), B.mul(a, db)), B.sq(b));
    case Op::PowI:
      return B.mul(B.mul(B.c(n.ival), g.powi(a, n.ival - 1)), da);
    case Op::Pow:
      if (B.zero(db))  // b * a^(b-1) * da
        return B.mul(B.mul(b, g.binary(Op::Pow, a, B.sub(b, B.c(1)))), da);
      // a^b * (db*log(a) + b*da/a)
      return B.mul(self, B.add(B.mul(db, B.fn(Op::Log, a)), B.div(B.mul(b, da), a)));
    case Op::Sin:
      return B.mul(B.fn(Op::Cos, a), da);
    case Op::Cos:
      return B.neg(B.mul(B.fn(Op::Sin, a), da));
    case Op::Tan:
      return B.div(da, B.sq(B.fn(Op::Cos, a)));
    case Op::Asin:
      return B.div(da, B.fn(Op::Sqrt, B.sub(B.c(1), B.sq(a))));
    case Op::Acos:
      return B.neg(B.div(da, B.fn(Op::Sqrt, B.sub(B.c(1), B.sq(a)))));
    case Op::Atan:
      return B.div(da, B.add(B.c(1), B.sq(a)));
    case Op::Atan2:  // atan2(a, b) = angle of (b, a): (b*da - a*db) / (a^2 + b^2)
      return B.div(B.sub(B.mul(b, da), B.mul(a, db)), B.add(B.sq(a), B.sq(b)));
    case Op::Sinh:
      return B.mul(B.fn(Op::Cosh, a), da);
    case Op::Cosh:
      return B.mul(B.fn(Op::Sinh, a), da);
    case Op::Tanh:
      return B.mul(B.sub(B.c(1), B.sq(self)), da);
    case Op::Exp:
      return B.mul(self, da);
    case Op::Log:
      return B.div(da, a);
    case Op::Sqrt:
      return B.div(da, B.mul(B.c(2), self));
    case Op::Cbrt:
      return B.div(da, B.mul(B.c(3), B.sq(self)));
    case Op::Abs:
      return B.mul(B.fn(Op::Sign, a), da);
    case Op::Sign:
    case Op::Floor:
    case Op::Ceil:
      return B.c(0);  // piecewise constant: zero wherever differentiable
    case Op::Min:
    case Op::Max: {
      // min/max = (a+b)/2 -/+ |a-b|/2, so d = (da+db)/2 -/+ sign(a-b) (da-db)/2
      const NodeId mean = B.mul(B.c(0.5), B.add(da, db));
      const NodeId half =
          B.mul(B.c(0.5), B.mul(B.fn(Op::Sign, g.binary(Op::Sub, a, b)), B.sub(da, db)));
      return n.op == Op::Min ? B.sub(mean, half) : B.add(mean, half);
    }
    // 0 where a is undefined, a constant there: b's derivative where a is defined.
    case Op::IfDefined:
      return g.binary(Op::IfDefined, a, db);
  }
  return B.c(0);
}

// Forward mode over the topological order; leaf(op) is the derivative of the variable `op`.
template <class Leaf>
NodeId forwardDerivative(Graph& g, NodeId root, Leaf leaf) {
  Builder B{g};
  const std::vector<NodeId> order = reachable(g, {root});
  std::vector<NodeId> d(g.size(), kNoNode);
  for (NodeId id : order) {
    const Node n = g[id];  // copy: the graph grows while we derive
    NodeId r;
    if (g.isSpatiallyConstant(id)) {
      r = B.c(0);
    } else if (opInfo(n.op).arity == 0) {
      r = leaf(n.op);
    } else {
      const NodeId da = d[static_cast<std::size_t>(n.a)];
      const NodeId db = opInfo(n.op).arity >= 2 ? d[static_cast<std::size_t>(n.b)] : kNoNode;
      r = derive(B, id, n, da, db);
    }
    d[static_cast<std::size_t>(id)] = r;
  }
  return d[static_cast<std::size_t>(root)];
}

}  // namespace

NodeId derivative(Graph& g, NodeId root, int axis) {
  const Op var = axis == 0 ? Op::VarX : axis == 1 ? Op::VarY : Op::VarZ;
  return forwardDerivative(g, root, [&](Op op) { return g.constant(op == var ? 1.0 : 0.0); });
}

NodeId directionalDerivative(Graph& g, NodeId root, const std::array<NodeId, 3>& direction) {
  return forwardDerivative(g, root, [&](Op op) {
    return direction[op == Op::VarX ? 0 : op == Op::VarY ? 1 : 2];
  });
}

std::array<NodeId, 3> gradient(Graph& g, NodeId root) {
  return {derivative(g, root, 0), derivative(g, root, 1), derivative(g, root, 2)};
}

}  // namespace zs
