#include "codegen/body_writer.hpp"

#include <cmath>

#include "codegen/glsl_literal.hpp"
#include "codegen/op_glsl.hpp"

namespace zs {
namespace {

bool isLeaf(Op op) {
  return opInfo(op).arity == 0;
}

}  // namespace

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

BodyWriter::BodyWriter(const Graph& g, const std::vector<std::string>& names)
    : g_(g), names_(names) {
  for (std::size_t i = 0; i < g.size() && !perNode_; ++i)
    perNode_ = g[static_cast<NodeId>(i)].op == Op::IfDefined;
  if (perNode_) flags_.assign(g.size(), "false");
}

std::string glslOr(const std::string& a, const std::string& b) {
  if (a == "true" || b == "true") return "true";
  if (a == "false") return b;
  if (b == "false") return a;
  return a + " || " + b;
}

std::string BodyWriter::standIns(const std::vector<NodeId>& nodes) const {
  std::string bits;
  unsigned bit = 0;
  for (NodeId id : nodes) {
    if (g_[id].op != Op::IfDefined || bit >= 32) continue;
    const std::string& a = flagOf(g_[id].a);
    const std::string mask = std::to_string(1u << bit++) + "u";
    if (a == "false") continue;
    bits +=
        (bits.empty() ? "" : " | ") + (a == "true" ? mask : "((" + a + ") ? " + mask + " : 0u)");
  }
  return "  zs_standIns = " + (bits.empty() ? std::string("0u") : bits) + ";\n";
}

void BodyWriter::nodeWithOwnFlag(NodeId id) {
  const Node& n = g_[id];
  std::string& own = flags_[static_cast<std::size_t>(id)];
  if (n.op == Op::Const && std::isnan(n.value)) own = "true";
  if (isLeaf(n.op)) return;
  const std::string& fa = flagOf(n.a);
  const std::string fb = n.b == kNoNode ? std::string("false") : flagOf(n.b);
  const std::string mine = "u_" + name(id);
  if (n.op == Op::IfDefined) {  // b where a is defined, else 0
    if (fa == "false") {
      own = fb;
      declare(name(id), name(n.b));
    } else if (fa == "true") {
      own = "false";
      declare(name(id), "0.0");
    } else {
      own = fb == "false" ? "false" : mine;
      if (own == mine) out += "  bool " + mine + " = !(" + fa + ") && (" + fb + ");\n";
      declare(name(id), "(" + fa + ") ? 0.0 : " + name(n.b));
    }
    return;
  }
  const bool canFail = opCanBeUndefined(n.op) || (n.op == Op::PowI && n.ival < 0);
  const std::string in = glslOr(fa, fb);
  if (canFail || in.find(' ') != std::string::npos) {
    out += "  bool " + mine + " = " + in + ";\n";
    own = mine;
  } else {
    own = in;  // "false", "true" or one operand's flag: nothing to write
  }
  if (n.op == Op::PowI) {
    powi(id, name(n.a), n.ival, own);
    return;
  }
  declare(name(id), glslOpExpression(n.op, name(n.a), n.b == kNoNode ? "" : name(n.b), own));
}

void BodyWriter::node(NodeId id, const std::string& flag) {
  if (perNode_) {
    nodeWithOwnFlag(id);
    return;
  }
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

void BodyWriter::declare(const std::string& lhs, const std::string& rhs) {
  out += "  float " + lhs + " = " + rhs + ";\n";
  ++temporaries;
}

// base^(2^i), declaring the missing squares as "<owner>_<power>" temporaries. Squares are
// cached per base, so x^4 after x^8 (or after x^2) costs at most one multiplication.
std::string BodyWriter::square(const std::string& base, int i, const std::string& owner) {
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
void BodyWriter::powi(NodeId id, const std::string& base, std::int32_t k, const std::string& flag) {
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

}  // namespace zs
