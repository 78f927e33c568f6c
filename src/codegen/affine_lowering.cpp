#include "codegen/affine_lowering.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "codegen/op_interval_glsl.hpp"
#include "expr/derivative.hpp"

namespace zs {
namespace {

// The smallest float interval that holds `value` (not NaN). GPUs flush denormals, so a
// non-zero value below the smallest normal float is not its own float.
std::pair<float, float> floatEnclosure(double value) {
  constexpr float kMax = std::numeric_limits<float>::max();
  constexpr float kMin = std::numeric_limits<float>::min();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (std::fabs(value) > double(kMax))  // beyond the floats (or infinite)
    return value > 0 ? std::pair{kMax, kInf} : std::pair{-kInf, -kMax};
  if (value != 0.0 && std::fabs(value) < double(kMin))
    return value > 0 ? std::pair{0.0f, kMin} : std::pair{-kMin, 0.0f};
  const float f = static_cast<float>(value);
  return {double(f) <= value ? f : std::nextafter(f, -kInf),
          double(f) >= value ? f : std::nextafter(f, kInf)};
}

// A constant node whose value is a float, so that it is its own exact interval.
bool exactFloat(const Graph& g, NodeId id) {
  const Node& n = g[id];
  if (n.op != Op::Const || std::isnan(n.value)) return false;
  const auto [lo, hi] = floatEnclosure(n.value);
  return lo == hi;
}

class Lowering {
 public:
  Lowering(const Graph& g, int firstDirection) : g_(g), firstDirection_(firstDirection) {
    value_.assign(g.size(), -1);
    settledValue_.assign(g.size(), -1);
    depth_.assign(g.size(), 0);
  }

  void lowerAll(NodeId f, NodeId df) {
    const std::vector<NodeId> fNodes = reachable(g_, {f});
    const std::vector<NodeId> all = reachable(g_, {f, df});
    std::vector<bool> inF(g_.size(), false);
    wanted_.assign(g_.size(), false);
    for (NodeId id : fNodes) inF[at(id)] = true;
    for (NodeId id : all) wanted_[at(id)] = true;
    for (NodeId id : fNodes) node(id);
    out_.f = settled(f);
    out_.fEnd = static_cast<std::int32_t>(out_.steps.size());
    derivativeOnly_ = true;
    for (NodeId id : all) {
      if (!inF[at(id)]) node(id);
    }
    out_.df = settled(df);
  }

  AffineProgram take() { return std::move(out_); }

 private:
  static std::size_t at(NodeId id) { return static_cast<std::size_t>(id); }
  bool direction(NodeId id) const {
    return g_[id].op == Op::Param && g_[id].ival >= firstDirection_;
  }

  std::int32_t push(AffineStep s) {
    s.derivativeOnly = derivativeOnly_;
    out_.steps.push_back(s);
    return static_cast<std::int32_t>(out_.steps.size() - 1);
  }

  // The node's form, settled first where a chain of polynomial rules ends in it.
  std::int32_t settled(NodeId id) {
    if (depth_[at(id)] == 0) return value_[at(id)];
    std::int32_t& own = settledValue_[at(id)];
    if (own < 0) {
      AffineStep s;
      s.kind = AffineStep::Kind::Settle;
      s.a = value_[at(id)];
      s.ival = depth_[at(id)];
      own = push(s);
    }
    return own;
  }

  void node(NodeId id) {
    const Node& n = g_[id];
    std::int32_t& own = value_[at(id)];
    AffineStep s;
    s.op = n.op;
    switch (n.op) {
      case Op::VarX:
      case Op::VarY:
      case Op::VarZ:
        s.kind = AffineStep::Kind::Coordinate;
        s.ival = n.op == Op::VarX ? 0 : n.op == Op::VarY ? 1 : 2;
        own = push(s);
        return;
      case Op::Param:  // exact: the direction the coordinates move by
        s.kind = direction(id) ? AffineStep::Kind::Direction : AffineStep::Kind::Param;
        s.ival = direction(id) ? n.ival - firstDirection_ : n.ival;
        own = push(s);
        return;
      case Op::Const:
        s.kind = AffineStep::Kind::Constant;
        s.nan = std::isnan(n.value);
        if (!s.nan) std::tie(s.lo, s.hi) = floatEnclosure(n.value);
        own = push(s);
        return;
      default:
        break;
    }
    if (n.op == Op::Sin || n.op == Op::Cos) {
      const Op other = n.op == Op::Sin ? Op::Cos : Op::Sin;
      const NodeId partner = g_.find(Node{other, n.a});
      if (partner != kNoNode && wanted_[at(partner)]) {
        if (value_[at(partner)] >= 0) return;  // written with its partner
        s.kind = AffineStep::Kind::SinCos;
        s.a = settled(n.a);
        own = push(s);
        AffineStep mate;
        mate.kind = AffineStep::Kind::Partner;
        mate.op = other;
        mate.a = own;
        value_[at(partner)] = push(mate);
        return;
      }
    }
    const bool polynomial = affineOpIsPolynomial(n.op, n.ival);
    // Operands: as they are for a polynomial rule, settled for any other.
    auto operand = [&](NodeId k) { return polynomial ? value_[at(k)] : settled(k); };
    const std::int32_t a = operand(n.a);
    const std::int32_t b = n.b == kNoNode ? -1 : operand(n.b);
    if (polynomial) {
      depth_[at(id)] = 1 + std::max(depth_[at(n.a)], n.b == kNoNode ? 0 : depth_[at(n.b)]);
    }
    auto scalar = [&](NodeId k) { return exactFloat(g_, k) || direction(k); };
    const NodeId k = n.op != Op::Mul ? kNoNode : scalar(n.a) ? n.a : scalar(n.b) ? n.b : kNoNode;
    if (k != kNoNode) {  // a scaling: two products, not four
      s.a = k == n.a ? b : a;
      if (direction(k)) {
        s.kind = AffineStep::Kind::ScaleDirection;
        s.ival = g_[k].ival - firstDirection_;
      } else {
        s.kind = AffineStep::Kind::Scale;
        s.lo = s.hi = static_cast<float>(g_[k].value);
      }
      own = push(s);
      return;
    }
    if (n.op == Op::Mul && (g_.isSpatiallyConstant(n.a) || g_.isSpatiallyConstant(n.b))) {
      // A factor constant along the ray (a constant that is not a float, a parameter, the
      // direction times a constant): no tau^2 term.
      const bool first = g_.isSpatiallyConstant(n.a) && !g_.isSpatiallyConstant(n.b);
      s.kind = AffineStep::Kind::MulK;
      s.a = first ? b : a;
      s.b = first ? a : b;
      own = push(s);
      return;
    }
    s.kind = AffineStep::Kind::Rule;
    s.a = a;
    s.b = b;
    s.ival = n.ival;
    own = push(s);
  }

  const Graph& g_;
  int firstDirection_;
  AffineProgram out_;
  std::vector<std::int32_t> value_, settledValue_;
  std::vector<int> depth_;
  std::vector<bool> wanted_;
  bool derivativeOnly_ = false;
};

}  // namespace

AffineProgram lowerAffine(const Graph& graph, NodeId f) {
  // dF/dt = grad F . d in one forward pass (the three partial derivatives and their dot
  // product cost more: x / sqrt(r2) thrice instead of one division), in a copy of the graph
  // whose three extra parameters are d's components.
  Graph g = graph;
  const int firstDirection = static_cast<int>(g.params().size());
  const NodeId df = directionalDerivative(
      g, f, {g.param("ray direction x"), g.param("ray direction y"), g.param("ray direction z")});
  Lowering lowering(g, firstDirection);
  lowering.lowerAll(f, df);
  return lowering.take();
}

}  // namespace zs
