#include "surfscript/poly_expr.hpp"

#include <algorithm>
#include <cmath>

#include "expr/number_text.hpp"

namespace zs::surfscript {

struct Poly::Node {
  enum class Op { Leaf, Add, Sub, Mul, Neg, Pow };
  Op op = Op::Leaf;
  Affine leaf{0, 0, 0, 0};  // Leaf: a constant has zero x, y, z coefficients
  int exponent = 0;         // Pow
  int depth = 1;
  std::shared_ptr<const Node> a, b;
};

namespace {

using Node = Poly::Node;
using NodePtr = std::shared_ptr<const Node>;

NodePtr makeLeaf(const Affine& form) {
  auto n = std::make_shared<Node>();
  n->leaf = form;
  return n;
}

NodePtr make(Node::Op op, NodePtr a, NodePtr b = nullptr, int exponent = 0) {
  auto n = std::make_shared<Node>();
  n->op = op;
  n->a = std::move(a);
  n->b = std::move(b);
  n->exponent = exponent;
  n->depth = 1 + std::max(n->a ? n->a->depth : 0, n->b ? n->b->depth : 0);
  return n;
}

bool isConstantLeaf(const Node& n) {
  return n.op == Node::Op::Leaf && n.leaf[0] == 0 && n.leaf[1] == 0 && n.leaf[2] == 0;
}

NodePtr substituted(const NodePtr& n, const AffineMap& map) {
  if (n->op == Node::Op::Leaf) {
    Affine out{0, 0, 0, n->leaf[3]};
    for (int axis = 0; axis < 3; ++axis) {
      const double c = n->leaf[axis];
      if (c == 0) continue;
      for (int k = 0; k < 4; ++k) out[k] += c * map[axis][k];
    }
    return makeLeaf(out);
  }
  return make(n->op, substituted(n->a, map), n->b ? substituted(n->b, map) : nullptr, n->exponent);
}

std::optional<double> valueOf(const Node& n) {
  switch (n.op) {
    case Node::Op::Leaf:
      if (!isConstantLeaf(n)) return std::nullopt;
      return n.leaf[3];
    case Node::Op::Neg: {
      auto a = valueOf(*n.a);
      if (!a) return std::nullopt;
      return -*a;
    }
    case Node::Op::Pow: {
      auto a = valueOf(*n.a);
      if (!a) return std::nullopt;
      return std::pow(*a, n.exponent);
    }
    default: {
      auto a = valueOf(*n.a), b = valueOf(*n.b);
      if (!a || !b) return std::nullopt;
      if (n.op == Node::Op::Add) return *a + *b;
      if (n.op == Node::Op::Sub) return *a - *b;
      return *a * *b;
    }
  }
}

int degreeOf(const Node& n) {
  switch (n.op) {
    case Node::Op::Leaf:
      return isConstantLeaf(n) ? 0 : 1;
    case Node::Op::Neg:
      return degreeOf(*n.a);
    case Node::Op::Pow:
      return degreeOf(*n.a) * n.exponent;
    case Node::Op::Mul:
      return degreeOf(*n.a) + degreeOf(*n.b);
    default:
      return std::max(degreeOf(*n.a), degreeOf(*n.b));
  }
}

// Precedence of what a node prints as: 1 sum, 2 product, 3 unary minus, 4 power, 5 atom.
int precedence(const Node& n) {
  switch (n.op) {
    case Node::Op::Add:
    case Node::Op::Sub:
      return 1;
    case Node::Op::Mul:
      return 2;
    case Node::Op::Neg:
      return 3;
    case Node::Op::Pow:
      return 4;
    case Node::Op::Leaf:
      break;
  }
  int terms = 0;
  for (int k = 0; k < 4; ++k) terms += n.leaf[k] != 0;
  if (terms > 1) return 1;
  if (terms == 0) return 5;
  if (n.leaf[3] != 0) return n.leaf[3] < 0 ? 3 : 5;
  for (int k = 0; k < 3; ++k) {
    if (n.leaf[k] == 1) return 5;
    if (n.leaf[k] == -1) return 3;
    if (n.leaf[k] != 0) return n.leaf[k] < 0 ? 3 : 2;
  }
  return 5;
}

std::string leafText(const Affine& f) {
  static const char* const names[3] = {"x", "y", "z"};
  std::string out;
  auto term = [&](double c, const char* name) {
    if (c == 0) return;
    const bool negative = c < 0;
    const double m = std::abs(c);
    if (out.empty())
      out += negative ? "-" : "";
    else
      out += negative ? " - " : " + ";
    if (!name)
      out += shortestText(m);
    else if (m == 1)
      out += name;
    else
      out += shortestText(m) + "*" + name;
  };
  for (int k = 0; k < 3; ++k) term(f[k], names[k]);
  term(f[3], nullptr);
  return out.empty() ? "0" : out;
}

std::string text(const Node& n);

// `n` as an operand that needs at least precedence `need`.
std::string operand(const Node& n, int need) {
  std::string t = text(n);
  return precedence(n) < need ? "(" + t + ")" : t;
}

std::string text(const Node& n) {
  switch (n.op) {
    case Node::Op::Leaf:
      return leafText(n.leaf);
    case Node::Op::Add:
      return text(*n.a) + " + " + operand(*n.b, 2);
    case Node::Op::Sub:
      return text(*n.a) + " - " + operand(*n.b, 2);
    case Node::Op::Mul:
      return operand(*n.a, 2) + "*" + operand(*n.b, 4);
    case Node::Op::Neg:
      return "-" + operand(*n.a, 4);
    case Node::Op::Pow:
      return operand(*n.a, 5) + "^" + std::to_string(n.exponent);
  }
  return {};
}

}  // namespace

AffineMap identityMap() {
  return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
}

AffineMap compose(const AffineMap& outer, const AffineMap& inner) {
  AffineMap out{};
  for (int i = 0; i < 3; ++i) {
    out[i] = {0, 0, 0, outer[i][3]};
    for (int axis = 0; axis < 3; ++axis) {
      const double c = outer[i][axis];
      if (c == 0) continue;
      for (int k = 0; k < 4; ++k) out[i][k] += c * inner[axis][k];
    }
  }
  return out;
}

Poly Poly::constant(double c) {
  return Poly(makeLeaf({0, 0, 0, c}));
}

Poly Poly::variable(int axis) {
  Affine f{0, 0, 0, 0};
  f[axis] = 1;
  return Poly(makeLeaf(f));
}

std::pair<Poly, Poly> Poly::aligned(const Poly& a, const Poly& b) {
  if (a.map_ == b.map_) return {a, b};
  if (degreeOf(*b.node_) == 0) return {a, Poly(b.node_, a.map_)};
  if (degreeOf(*a.node_) == 0) return {Poly(a.node_, b.map_), b};
  return {a.applied(), b.applied()};
}

namespace {

std::optional<double> constantOf(const NodePtr& n) {
  if (n->op == Node::Op::Leaf && isConstantLeaf(*n)) return n->leaf[3];
  return std::nullopt;
}

}  // namespace

// Numbers fold (as surf computes them, in doubles), and p + 0, p - 0 are p: the formula keeps
// what the script means, not its bookkeeping (SURFER-2008 writes -1*(a-1*0.5) with a = 0.5).
Poly Poly::operator+(const Poly& o) const {
  const auto ca = constantOf(node_), cb = constantOf(o.node_);
  if (ca && cb) return constant(*ca + *cb);
  if (cb && *cb == 0) return *this;
  if (ca && *ca == 0) return o;
  auto [a, b] = aligned(*this, o);
  return Poly(make(Node::Op::Add, a.node_, b.node_), a.map_);
}
Poly Poly::operator-(const Poly& o) const {
  const auto ca = constantOf(node_), cb = constantOf(o.node_);
  if (ca && cb) return constant(*ca - *cb);
  if (cb && *cb == 0) return *this;
  auto [a, b] = aligned(*this, o);
  return Poly(make(Node::Op::Sub, a.node_, b.node_), a.map_);
}
Poly Poly::operator*(const Poly& o) const {
  // 1*p is p exactly (SURFER-2008 writes -1*z^2): the formula reads as the mathematics.
  if (node_->op == Node::Op::Leaf && isConstantLeaf(*node_) && node_->leaf[3] == 1) return o;
  if (o.node_->op == Node::Op::Leaf && isConstantLeaf(*o.node_) && o.node_->leaf[3] == 1)
    return *this;
  if (const auto ca = constantOf(node_), cb = constantOf(o.node_); ca && cb)
    return constant(*ca * *cb);
  auto [a, b] = aligned(*this, o);
  return Poly(make(Node::Op::Mul, a.node_, b.node_), a.map_);
}
Poly Poly::operator-() const {
  return Poly(make(Node::Op::Neg, node_), map_);
}
Poly Poly::pow(int exponent) const {
  if (exponent == 1) return *this;
  return Poly(make(Node::Op::Pow, node_, nullptr, exponent), map_);
}

Poly Poly::substitute(const AffineMap& map) const {
  return Poly(node_, compose(map_, map));
}

Poly Poly::applied() const {
  if (map_ == identityMap()) return *this;
  return Poly(substituted(node_, map_));
}

std::optional<double> Poly::constantValue() const {
  return valueOf(*node_);
}

int Poly::degree() const {
  return degreeOf(*node_);
}

int Poly::depth() const {
  return node_->depth;
}

std::optional<std::pair<Affine, double>> Poly::slab() const {
  const Node& n = *node_;
  // b*L^2 as (coefficient, L)
  auto square = [](const Node& t) -> std::optional<std::pair<double, Affine>> {
    auto bare = [](const Node& q) -> std::optional<Affine> {
      if (q.op == Node::Op::Pow && q.exponent == 2 && q.a->op == Node::Op::Leaf &&
          !isConstantLeaf(*q.a))
        return q.a->leaf;
      return std::nullopt;
    };
    if (auto l = bare(t)) return std::pair{1.0, *l};
    if (t.op == Node::Op::Mul) {
      if (auto c = valueOf(*t.a); c && bare(*t.b)) return std::pair{*c, *bare(*t.b)};
      if (auto c = valueOf(*t.b); c && bare(*t.a)) return std::pair{*c, *bare(*t.a)};
    }
    return std::nullopt;
  };
  std::optional<double> a;
  std::optional<std::pair<double, Affine>> sq;
  if (n.op == Node::Op::Sub) {
    a = valueOf(*n.a);
    sq = square(*n.b);
  } else if (n.op == Node::Op::Add && n.b->op == Node::Op::Neg) {
    a = valueOf(*n.a);
    sq = square(*n.b->a);
  } else if (n.op == Node::Op::Add && n.a->op == Node::Op::Neg) {
    a = valueOf(*n.b);
    sq = square(*n.a->a);
  }
  if (!a || !sq || !(*a > 0) || !(sq->first > 0)) return std::nullopt;
  return std::pair{sq->second, std::sqrt(*a / sq->first)};
}

std::string Poly::formula() const {
  return text(*applied().node_);
}

}  // namespace zs::surfscript
