#include "codegen/emit_glsl.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "codegen/glsl_literal.hpp"
#include "codegen/op_glsl.hpp"
#include "expr/derivative.hpp"

namespace zs {
namespace {

bool isLeaf(Op op) { return opInfo(op).arity == 0; }

// The GLSL text of every reachable node: a literal or input for leaves, a temporary name
// otherwise. Computed once so that a node has the same name in zs_F and in zs_FGrad, which
// makes the two bodies easy to compare by eye.
std::vector<std::string> nameNodes(const Graph& g, const std::vector<NodeId>& order) {
  std::vector<std::string> names(g.size());
  std::size_t next = 0;
  for (NodeId id : order) {
    const Node& n = g[id];
    std::string& name = names[static_cast<std::size_t>(id)];
    if (n.op == Op::Const) {
      name = glslFloatLiteral(n.value).text;
      // "a - -2.0" would lex as a decrement; parenthesize every negative literal.
      if (name.front() == '-') name = "(" + name + ")";
    } else if (n.op == Op::VarX) {
      name = "p.x";
    } else if (n.op == Op::VarY) {
      name = "p.y";
    } else if (n.op == Op::VarZ) {
      name = "p.z";
    } else if (n.op == Op::Param) {
      name = "zs_params[" + std::to_string(n.ival) + "]";
    } else {
      name = "t" + std::to_string(next++);
    }
  }
  return names;
}

// Writes the statements of one function body, node by node in topological order.
class BodyWriter {
 public:
  BodyWriter(const Graph& g, const std::vector<std::string>& names) : g_(g), names_(names) {}

  void node(NodeId id, const std::string& flag) {
    const Node& n = g_[id];
    if (n.op == Op::Const && std::isnan(n.value)) {
      // A NaN constant (e.g. folded sqrt(-1)) makes F undefined wherever it is used.
      out += "  " + flag + " = true;  // constant NaN\n";
    }
    if (isLeaf(n.op)) return;
    if (n.op == Op::PowI) {
      powi(id, name(n.a), n.ival, flag);
      return;
    }
    declare(name(id), glslOpExpression(n.op, name(n.a), n.b == kNoNode ? "" : name(n.b), flag));
  }

  std::string out;
  std::size_t temporaries = 0;

 private:
  const std::string& name(NodeId id) const { return names_[static_cast<std::size_t>(id)]; }

  void declare(const std::string& lhs, const std::string& rhs) {
    out += "  float " + lhs + " = " + rhs + ";\n";
    ++temporaries;
  }

  // base^(2^i), declaring the missing squares as "<owner>_<power>" temporaries. Squares are
  // cached per base, so x^4 after x^8 (or after x^2) costs at most one multiplication.
  std::string square(const std::string& base, int i, const std::string& owner) {
    std::string prev = base;
    for (int j = 1; j <= i; ++j) {
      const std::int64_t power = std::int64_t{1} << j;
      const std::string key = base + "^" + std::to_string(power);
      auto it = squares_.find(key);
      if (it == squares_.end()) {
        const std::string tmp = owner + "_" + std::to_string(power);
        declare(tmp, prev + " * " + prev);
        it = squares_.emplace(key, tmp).first;
      }
      prev = it->second;
    }
    return prev;
  }

  // base^k by repeated squaring: with h the highest set bit of |k|,
  //   base^|k| = s(h-1) * s(h-1) * prod over set bits i < h of s(i),  s(i) = base^(2^i).
  // Never GLSL pow(): it is undefined for negative bases. Negative k divides 1 by the chain.
  void powi(NodeId id, const std::string& base, std::int32_t k, const std::string& flag) {
    const std::string& result = name(id);
    if (k == 0) {
      declare(result, "1.0");  // like std::pow(x, 0), also for x = 0
      return;
    }
    const std::int64_t m = k < 0 ? -std::int64_t{k} : std::int64_t{k};
    int h = 0;
    while ((m >> (h + 1)) != 0) ++h;
    std::string chain = base;
    if (h > 0) {
      // base^(2^h) itself may already exist (x^2 before x^3): then it is one factor.
      auto cached = squares_.find(base + "^" + std::to_string(std::int64_t{1} << h));
      if (cached != squares_.end()) {
        chain = cached->second;
      } else {
        const std::string top = square(base, h - 1, result);
        chain = top + " * " + top;
      }
      for (int i = 0; i < h; ++i) {
        if ((m >> i) & 1) chain += " * " + square(base, i, result);
      }
    }
    const bool powerOfTwo = (m & (m - 1)) == 0 && m >= 2;
    if (k > 0) {
      declare(result, chain);
      if (powerOfTwo) squares_.emplace(base + "^" + std::to_string(m), result);
      return;
    }
    std::string magnitude = chain;
    if (h > 0) {  // keep operands simple names: the chain gets its own temporary
      magnitude = result + "_m";
      declare(magnitude, chain);
      if (powerOfTwo) squares_.emplace(base + "^" + std::to_string(m), magnitude);
    }
    declare(result, glslOpExpression(Op::Div, "1.0", magnitude, flag));
  }

  const Graph& g_;
  const std::vector<std::string>& names_;
  std::unordered_map<std::string, std::string> squares_;  // "base^power" -> temporary
};

// Parameter names go into a comment only when they are plain identifiers: nothing a
// formula contains may reach the shader unchecked, not even inside a comment.
bool plainIdentifier(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                    (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

std::string paramDeclaration(const Graph& g) {
  const auto& params = g.params();
  if (params.empty()) return "";
  std::string s = "uniform float zs_params[" + std::to_string(params.size()) + "];  //";
  for (std::size_t i = 0; i < params.size(); ++i) {
    s += " [" + std::to_string(i) + "] " + (plainIdentifier(params[i]) ? params[i] : "?");
  }
  return s + "\n";
}

}  // namespace

GlslFormula emitFormulaGlsl(const Graph& g, NodeId f, const std::array<NodeId, 3>& grad) {
  const std::vector<NodeId> all = reachable(g, {f, grad[0], grad[1], grad[2]});
  const std::vector<NodeId> fNodes = reachable(g, {f});
  std::vector<bool> inF(g.size(), false);
  for (NodeId id : fNodes) inF[static_cast<std::size_t>(id)] = true;
  const std::vector<std::string> names = nameNodes(g, all);
  auto nameOf = [&](NodeId id) { return names[static_cast<std::size_t>(id)]; };

  GlslFormula result;
  result.paramCount = g.params().size();
  std::string& s = result.source;
  s += "// zeroset formula block (generated by src/codegen): F and its gradient.\n";
  s += paramDeclaration(g);

  BodyWriter fBody(g, names);
  for (NodeId id : fNodes) fBody.node(id, "zs_u");
  s += "\nfloat zs_F(vec3 p) {\n";
  s += "  bool zs_u = false;  // set where p is outside F's domain\n";
  s += fBody.out;
  s += "  return zs_finishF(" + nameOf(f) + ", zs_u);\n}\n";

  // In zs_FGrad a node that F itself needs reports to zs_u, a node only the gradient needs
  // to zs_ug: an undefined derivative must not hide a defined F.
  BodyWriter gradBody(g, names);
  for (NodeId id : all) gradBody.node(id, inF[static_cast<std::size_t>(id)] ? "zs_u" : "zs_ug");
  s += "\nvec4 zs_FGrad(vec3 p) {\n";
  s += "  bool zs_u = false;   // set where p is outside F's domain\n";
  s += "  bool zs_ug = false;  // set where p is outside the gradient's domain\n";
  s += gradBody.out;
  s += "  return zs_finishFGrad(vec3(" + nameOf(grad[0]) + ", " + nameOf(grad[1]) + ", " +
       nameOf(grad[2]) + "), " + nameOf(f) + ", zs_u, zs_ug);\n}\n";
  result.temporaries = gradBody.temporaries;
  return result;
}

GlslFormula emitFormulaGlsl(Formula& formula) {
  const std::array<NodeId, 3> grad = gradient(formula.graph, formula.root);
  return emitFormulaGlsl(formula.graph, formula.root, grad);
}

}  // namespace zs
