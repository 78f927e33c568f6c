#include "codegen/emit_interval_glsl.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "codegen/glsl_literal.hpp"
#include "codegen/op_interval_glsl.hpp"
#include "expr/derivative.hpp"

namespace zs {
namespace {

std::string floatText(float v) {
  if (std::isinf(v)) return v > 0 ? "ZSI_INF" : "(-ZSI_INF)";
  std::string t = glslFloatLiteral(v).text;
  return !t.empty() && t[0] == '-' ? "(" + t + ")" : t;
}

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

// The vec2 literal of the smallest float interval that holds `value` ("vec2(lo, hi)", or
// "vec2(v)" when value is a float); empty for NaN.
std::string glslIntervalLiteral(double value) {
  if (std::isnan(value)) return "";
  const auto [lo, hi] = floatEnclosure(value);
  if (lo == hi) return "vec2(" + floatText(lo) + ")";
  return "vec2(" + floatText(lo) + ", " + floatText(hi) + ")";
}

// A constant as an affine form: itself where it is a float, else its float enclosure's.
std::string affineConstant(double value) {
  if (std::isnan(value)) return "";
  const auto [lo, hi] = floatEnclosure(value);
  if (lo == hi) return "zsa_const(" + floatText(lo) + ")";
  return "zsa_fromInterval(" + glslIntervalLiteral(value) + ")";
}

struct Bodies {
  std::string f, df;  // F's statements, then those of the nodes only dF/dt reaches
  std::string fResult, dfResult;  // the settled forms of F and dF/dt
};

// One `vec4 aN = zsa_<rule>(...);` per non-leaf node of F (undefined flag zs_u), then per
// node only the derivative df reaches (zs_ug). Parameters from index `firstDirection` on are
// the ray direction's components d.x, d.y, d.z.
//
// Rounding (affine_prelude.frag.glsl): the polynomial operations leave their rounding
// unsettled; `depth` counts the longest chain of them since the operand was last settled,
// and a form is settled (`vec4 sN = zsa_settle(aN, depth)`, once per node) before any other
// rule reads it and at the end.
Bodies emitNodes(const Graph& g, NodeId f, NodeId df, int firstDirection) {
  const std::vector<NodeId> fNodes = reachable(g, {f});
  const std::vector<NodeId> all = reachable(g, {f, df});
  auto direction = [&](NodeId id) {
    return g[id].op == Op::Param && g[id].ival >= firstDirection;
  };
  static constexpr const char* kDirection[] = {"d.x", "d.y", "d.z"};
  Bodies out;
  std::vector<std::string> names(g.size()), settledNames(g.size());
  std::vector<int> depth(g.size(), 0);
  std::vector<bool> inF(g.size(), false), wanted(g.size(), false);
  for (NodeId id : fNodes) inF[static_cast<std::size_t>(id)] = true;
  for (NodeId id : all) wanted[static_cast<std::size_t>(id)] = true;
  std::size_t next = 0;
  auto at = [](NodeId id) { return static_cast<std::size_t>(id); };
  // The node's form, settled first where a chain of polynomial operations ends in it.
  auto settled = [&](NodeId id, std::string& body) -> const std::string& {
    if (depth[at(id)] == 0) return names[at(id)];
    std::string& own = settledNames[at(id)];
    if (own.empty()) {
      own = "s" + std::to_string(next++);
      body += "  vec4 " + own + " = zsa_settle(" + names[at(id)] + ", " +
              std::to_string(depth[at(id)]) + ".0);\n";
    }
    return own;
  };
  auto emit = [&](NodeId id, std::string& body, const char* flag) {
    const Node& n = g[id];
    std::string& own = names[at(id)];
    switch (n.op) {
      case Op::VarX: own = "AX"; return;
      case Op::VarY: own = "AY"; return;
      case Op::VarZ: own = "AZ"; return;
      case Op::Param:  // exact: the direction zsa_var moves the coordinates by
        own = direction(id)
                  ? std::string("zsa_const(") + kDirection[n.ival - firstDirection] + ")"
                  : "zsa_point(zs_params[" + std::to_string(n.ival) + "])";
        return;
      case Op::Const:
        own = affineConstant(n.value);
        if (own.empty()) {  // a NaN constant: F is undefined wherever it is used
          own = "vec4(0.0)";
          body += std::string("  ") + flag + " = true;  // constant NaN\n";
        }
        return;
      default: break;
    }
    // sin and cos of one operand share the evaluation of sin and cos at its center (the
    // derivative of one is the other, so the pair is common): both are written at the first.
    if (n.op == Op::Sin || n.op == Op::Cos) {
      const Op other = n.op == Op::Sin ? Op::Cos : Op::Sin;
      const NodeId partner = g.find(Node{other, n.a});
      if (partner != kNoNode && wanted[at(partner)]) {
        std::string& mate = names[at(partner)];
        if (!mate.empty()) return;  // written with its partner
        const std::string& operand = settled(n.a, body);
        own = "a" + std::to_string(next++);
        mate = "a" + std::to_string(next++);
        const std::string& sn = n.op == Op::Sin ? own : mate;
        const std::string& cs = n.op == Op::Sin ? mate : own;
        body += "  vec4 " + sn + ", " + cs + ";\n";
        body += "  zsa_sincos(" + operand + ", " + sn + ", " + cs + ");\n";
        return;
      }
    }
    const bool polynomial = affineOpIsPolynomial(n.op, n.ival);
    // Operands: as they are for a polynomial operation, settled for any other rule.
    auto operand = [&](NodeId k) -> std::string {
      return polynomial ? names[at(k)] : settled(k, body);
    };
    const std::string a = operand(n.a);
    const std::string b = n.b == kNoNode ? std::string() : operand(n.b);
    if (polynomial) {
      depth[at(id)] = 1 + std::max(depth[at(n.a)], n.b == kNoNode ? 0 : depth[at(n.b)]);
    }
    own = "a" + std::to_string(next++);
    // A product with a constant that is a float, or with a component of the direction, is
    // a scaling: two products, not four.
    auto scalar = [&](NodeId k) { return exactFloat(g, k) || direction(k); };
    const NodeId k = n.op != Op::Mul ? kNoNode : scalar(n.a) ? n.a : scalar(n.b) ? n.b : kNoNode;
    if (k != kNoNode) {
      const std::string factor = direction(k) ? kDirection[g[k].ival - firstDirection]
                                              : floatText(float(g[k].value));
      body += "  vec4 " + own + " = zsa_scale(" + (k == n.a ? b : a) + ", " + factor + ");\n";
      return;
    }
    // A product with a factor constant along the ray (a constant that is not a float, a
    // parameter, the direction times a constant): no tau^2 term (zsa_mulk).
    if (n.op == Op::Mul && (g.isSpatiallyConstant(n.a) || g.isSpatiallyConstant(n.b))) {
      const bool first = g.isSpatiallyConstant(n.a) && !g.isSpatiallyConstant(n.b);
      body += "  vec4 " + own + " = zsa_mulk(" + (first ? b : a) + ", " + (first ? a : b) + ");\n";
      return;
    }
    body += "  vec4 " + own + " = " + glslAffineOpExpression(n.op, a, b, n.ival, flag) + ";\n";
  };
  for (NodeId id : fNodes) emit(id, out.f, "zs_u");
  out.fResult = settled(f, out.f);
  for (NodeId id : all) {
    if (!inF[at(id)]) emit(id, out.df, "zs_ug");
  }
  out.dfResult = settled(df, out.df);
  return out;
}


}  // namespace


IntervalGlsl emitIntervalGlsl(const Graph& graph, NodeId f) {
  // dF/dt = grad F . d in one forward pass (the three partial derivatives and their dot
  // product cost more: x / sqrt(r2) thrice instead of one division), in a copy of the graph
  // whose three extra parameters are d's components, leaves the emitter writes as d.x, d.y, d.z.
  Graph g = graph;
  const int firstDirection = static_cast<int>(g.params().size());
  const NodeId df = directionalDerivative(
      g, f, {g.param("ray direction x"), g.param("ray direction y"), g.param("ray direction z")});
  std::string s = "// zeroset interval formula block (generated by src/codegen): F and dF/dt along a ray segment.\n";
  // The nodes as affine forms along the segment t = tm + h tau (vec4 (c, s, r, m),
  // affine_prelude.frag.glsl); operations without a first-order rule use their interval
  // rule (zsi_*) on the operands' ranges.
  const Bodies ray = emitNodes(g, f, df, firstDirection);
  s += "// F and dF/dt as affine forms in tau along the segment t = tm + h tau.\n";
  s += "void zs_FAffine(vec3 o, vec3 d, float tm, float h, out vec3 F, out vec2 D, out bool "
       "partial) {\n";
  s += "  bool zs_u = false;   // F is defined nowhere on the segment\n";
  s += "  bool zs_ug = false;  // dF/dt is defined nowhere on the segment\n";
  s += "  zsi_partial = false;\n";
  s += "  vec4 AX = zsa_var(o.x, d.x, tm, h), AY = zsa_var(o.y, d.y, tm, h), "
       "AZ = zsa_var(o.z, d.z, tm, h);\n";
  s += ray.f;
  s += "  partial = zsi_partial;\n";
  s += ray.df;
  s += "  zsa_finish(" + ray.fResult + ", " + ray.dfResult + ", zs_u, zs_ug || zsi_partial, F, D);\n}\n";
  return {s};
}

}  // namespace zs
