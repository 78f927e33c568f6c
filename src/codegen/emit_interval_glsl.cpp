#include "codegen/emit_interval_glsl.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "codegen/glsl_literal.hpp"
#include "codegen/op_interval_glsl.hpp"

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

// What differs between the interval block and the affine one: the GLSL type of a node, the
// names of x, y and z, how leaves are written, and the rule of each opcode.
struct Flavor {
  const char* type;   // "vec2" or "vec3"
  const char* temp;   // temporaries' prefix: iN or aN
  const char* vars[3];
  const char* rules;  // rule prefix: zsi_ or zsa_
  std::string (*constant)(double value);  // "" for NaN
  std::string (*op)(Op, std::string_view, std::string_view, std::int32_t, std::string_view);
};

struct Bodies {
  std::string f, grad;  // F's statements, then those of the nodes only the gradient reaches
  std::vector<std::string> names;
};

// One `TYPE tN = RULE(...);` per non-leaf node of F (undefined flag zs_u), then per node only
// the gradient reaches (zs_ug).
Bodies emitNodes(const Graph& g, NodeId f, const std::array<NodeId, 3>& grad, const Flavor& k) {
  const std::vector<NodeId> fNodes = reachable(g, {f});
  const std::vector<NodeId> all = reachable(g, {f, grad[0], grad[1], grad[2]});
  Bodies out;
  out.names.resize(g.size());
  std::vector<bool> inF(g.size(), false);
  for (NodeId id : fNodes) inF[static_cast<std::size_t>(id)] = true;
  std::size_t next = 0;
  auto name = [&](NodeId id) -> const std::string& {
    return out.names[static_cast<std::size_t>(id)];
  };
  const std::string type(k.type), rules(k.rules);
  auto emit = [&](NodeId id, std::string& body, const char* flag) {
    const Node& n = g[id];
    std::string& own = out.names[static_cast<std::size_t>(id)];
    switch (n.op) {
      case Op::VarX: own = k.vars[0]; return;
      case Op::VarY: own = k.vars[1]; return;
      case Op::VarZ: own = k.vars[2]; return;
      case Op::Param: own = rules + "point(zs_params[" + std::to_string(n.ival) + "])"; return;
      case Op::Const:
        own = k.constant(n.value);
        if (own.empty()) {  // a NaN constant: F is undefined wherever it is used
          own = type + "(0.0)";
          body += std::string("  ") + flag + " = true;  // constant NaN\n";
        }
        return;
      default: break;
    }
    own = k.temp + std::to_string(next++);
    // A product with a constant that is a float is a scaling: two products, not four.
    const NodeId scalar = n.op != Op::Mul ? kNoNode : exactFloat(g, n.a) ? n.a : exactFloat(g, n.b) ? n.b : kNoNode;
    if (scalar != kNoNode) {
      const NodeId other = scalar == n.a ? n.b : n.a;
      body += "  " + type + " " + own + " = " + rules + "scale(" + name(other) + ", " +
              floatText(float(g[scalar].value)) + ");\n";
      return;
    }
    body += "  " + type + " " + own + " = " +
            k.op(n.op, name(n.a), n.b == kNoNode ? "" : name(n.b), n.ival, flag) + ";\n";
  };
  for (NodeId id : fNodes) emit(id, out.f, "zs_u");
  for (NodeId id : all) {
    if (!inF[static_cast<std::size_t>(id)]) emit(id, out.grad, "zs_ug");
  }
  return out;
}

// A constant as an affine form: itself where it is a float, else its float enclosure's.
std::string affineConstant(double value) {
  if (std::isnan(value)) return "";
  const auto [lo, hi] = floatEnclosure(value);
  if (lo == hi) return "vec3(" + floatText(lo) + ", 0.0, 0.0)";
  return "zsa_fromInterval(" + glslIntervalLiteral(value) + ")";
}

}  // namespace

std::string glslIntervalLiteral(double value) {
  if (std::isnan(value)) return "";
  const auto [lo, hi] = floatEnclosure(value);
  if (lo == hi) return "vec2(" + floatText(lo) + ")";
  return "vec2(" + floatText(lo) + ", " + floatText(hi) + ")";
}

IntervalGlsl emitIntervalGlsl(const Graph& g, NodeId f, const std::array<NodeId, 3>& grad) {
  std::string s = "// zeroset interval formula block (generated by src/codegen): F and dF/dt along a ray segment.\n";
  // The nodes as affine forms along the segment t = tm + h tau (vec3 (c, s, r),
  // affine_prelude.frag.glsl); operations without a first-order rule use their interval
  // rule (zsi_*) on the operands' ranges.
  const Flavor affine{"vec3", "a", {"AX", "AY", "AZ"}, "zsa_", affineConstant,
                      glslAffineOpExpression};
  const Bodies ray = emitNodes(g, f, grad, affine);
  auto aname = [&](NodeId id) { return ray.names[static_cast<std::size_t>(id)]; };
  s += "// F and dF/dt as affine forms in tau along the segment t = tm + h tau.\n";
  s += "void zs_FAffine(vec3 o, vec3 d, float tm, float h, out vec3 F, out vec2 D, out bool "
       "partial) {\n";
  s += "  bool zs_u = false;   // F is defined nowhere on the segment\n";
  s += "  bool zs_ug = false;  // the gradient is defined nowhere on the segment\n";
  s += "  zsi_partial = false;\n";
  s += "  vec3 AX = zsa_var(o.x, d.x, tm, h), AY = zsa_var(o.y, d.y, tm, h), "
       "AZ = zsa_var(o.z, d.z, tm, h);\n";
  s += ray.f;
  s += "  partial = zsi_partial;\n";
  s += ray.grad;
  s += "  zsa_finish(" + aname(f) + ", zsa_dot(" + aname(grad[0]) + ", " + aname(grad[1]) + ", " +
       aname(grad[2]) + ", d), zs_u, zs_ug || zsi_partial, F, D);\n}\n";
  return {s};
}

}  // namespace zs
