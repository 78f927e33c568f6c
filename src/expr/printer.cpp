#include "expr/printer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "expr/number_text.hpp"

namespace zs {

namespace {

// Binding strength of what a node prints as; a child printed into a slot that needs more
// gets parentheses. Matches the parser: sum < product < unary minus < power < atom.
enum Prec { kSum = 1, kProduct = 2, kUnary = 3, kPower = 4, kAtom = 5 };

struct Printed {
  std::string text;
  int prec = kAtom;
  int depth = 0;  // nesting levels the parser counts (parentheses, calls, signs, powers)
};

std::string number(double v) {
  return shortestText(v);  // shortest exact round trip
}

// `a^n` with an integer |n| beyond kMaxIntegerExponent is rejected by the parser, so such a
// power (built by pow()) is printed in call syntax.
bool hugeIntegerExponent(const Graph& g, NodeId exponent) {
  const Node& e = g[exponent];
  return e.op == Op::Const && std::nearbyint(e.value) == e.value &&
         std::fabs(e.value) > kMaxIntegerExponent;
}

}  // namespace

std::optional<std::string> print(const Graph& g, NodeId root, std::size_t maxChars) {
  const std::vector<NodeId> order = reachable(g, {root});
  std::vector<Printed> out(g.size());
  auto slot = [&](NodeId child, int need) {
    const Printed& p = out[static_cast<std::size_t>(child)];
    return p.prec >= need ? p.text : "(" + p.text + ")";
  };
  // The nesting of `child` printed into a slot that needs `need`.
  auto depthIn = [&](NodeId child, int need) {
    const Printed& p = out[static_cast<std::size_t>(child)];
    return p.depth + (p.prec >= need ? 0 : 1);
  };
  for (NodeId id : order) {
    const Node& n = g[id];
    const OpInfo& info = opInfo(n.op);
    Printed p;
    switch (info.kind) {
      case OpKind::Leaf:
        if (n.op == Op::Const) {
          p.text = number(n.value);
          if (n.value < 0 || (n.value == 0 && std::signbit(n.value))) p.prec = kUnary, p.depth = 1;
        } else if (n.op == Op::Param) {
          p.text = g.params()[static_cast<std::size_t>(n.ival)];
        } else {
          p.text = std::string(info.spelling);
        }
        break;
      case OpKind::Prefix:
        p.text = "-" + slot(n.a, kUnary);
        p.prec = kUnary;
        p.depth = 1 + depthIn(n.a, kUnary);
        break;
      case OpKind::Infix:
        if (n.op == Op::PowI) {
          p.text = slot(n.a, kAtom) + "^" + std::to_string(n.ival);
          p.prec = kPower;
          p.depth = std::max(depthIn(n.a, kAtom), n.ival < 0 ? 1 : 0) + 1;
        } else {
          const int prec = (n.op == Op::Add || n.op == Op::Sub) ? kSum : kProduct;
          // Left-associative: the right operand needs strictly more binding strength.
          p.text = slot(n.a, prec) + (prec == kSum ? " " : "") + std::string(info.spelling) +
                   (prec == kSum ? " " : "") + slot(n.b, prec + 1);
          p.prec = prec;
          p.depth = std::max(depthIn(n.a, prec), depthIn(n.b, prec + 1));
        }
        break;
      case OpKind::Call:
      case OpKind::Internal:
        if (n.op == Op::Pow && !hugeIntegerExponent(g, n.b)) {
          p.text = slot(n.a, kAtom) + "^" + slot(n.b, kUnary);
          p.prec = kPower;
          p.depth = std::max(depthIn(n.a, kAtom), depthIn(n.b, kUnary)) + 1;
        } else if (info.arity == 1) {
          p.text = std::string(info.spelling) + "(" + out[static_cast<std::size_t>(n.a)].text + ")";
          p.depth = out[static_cast<std::size_t>(n.a)].depth + 1;
        } else {
          p.text = std::string(info.spelling) + "(" + out[static_cast<std::size_t>(n.a)].text +
                   ", " + out[static_cast<std::size_t>(n.b)].text + ")";
          p.depth = std::max(out[static_cast<std::size_t>(n.a)].depth,
                             out[static_cast<std::size_t>(n.b)].depth) +
                    1;
        }
        break;
    }
    if (p.text.size() > maxChars || p.depth > kMaxNesting) return std::nullopt;
    out[static_cast<std::size_t>(id)] = std::move(p);
  }
  return out[static_cast<std::size_t>(root)].text;
}

}  // namespace zs
