#include "expr/degree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace zs {

namespace {

// A polynomial as monomial -> coefficient; the monomial packs the x, y, z exponents.
using Monomial = std::array<int, 3>;
using Poly = std::map<Monomial, double>;

constexpr std::size_t kMaxTerms = 4096;
constexpr int kMaxDegree = 512;

int degreeOf(const Monomial& m) {
  return m[0] + m[1] + m[2];
}

// Parameters stand for generic nonzero coefficients: distinct irrational-looking values make
// an accidental cancellation vanishingly unlikely (the Schwartz-Zippel argument).
double genericParamValue(int index) {
  return std::sqrt(2.0 + 3.0 * index) + 0.1234567;
}

void prune(Poly& p) {
  double scale = 0;
  for (const auto& [m, c] : p) scale = std::max(scale, std::fabs(c));
  std::erase_if(p, [&](const auto& kv) { return std::fabs(kv.second) <= 1e-12 * scale; });
}

std::optional<Poly> product(const Poly& a, const Poly& b) {
  Poly r;
  for (const auto& [ma, ca] : a) {
    for (const auto& [mb, cb] : b) {
      Monomial m{ma[0] + mb[0], ma[1] + mb[1], ma[2] + mb[2]};
      if (degreeOf(m) > kMaxDegree) return std::nullopt;
      r[m] += ca * cb;
      if (r.size() > kMaxTerms) return std::nullopt;
    }
  }
  prune(r);
  return r;
}

Poly sum(const Poly& a, const Poly& b, double sign) {
  Poly r = a;
  for (const auto& [m, c] : b) r[m] += sign * c;
  prune(r);
  return r;
}

std::optional<double> constantOf(const Poly& p) {
  if (p.empty()) return 0.0;
  if (p.size() == 1 && p.begin()->first == Monomial{0, 0, 0}) return p.begin()->second;
  return std::nullopt;
}

}  // namespace

std::vector<int> structuralDegrees(const Graph& g, NodeId root) {
  // Nested powers ((x^1000)^1000)^1000 would overflow: any degree past this is "huge".
  const auto saturate = [](std::int64_t d) { return int(std::min<std::int64_t>(d, 1 << 24)); };
  std::vector<int> deg(g.size(), -1);  // -1: not a polynomial
  for (NodeId id : reachable(g, {root})) {
    const Node& n = g[id];
    const auto at = [&](NodeId k) { return deg[static_cast<std::size_t>(k)]; };
    int r = -1;
    if (g.isSpatiallyConstant(id)) {
      r = 0;
    } else if (n.op == Op::VarX || n.op == Op::VarY || n.op == Op::VarZ) {
      r = 1;
    } else if (n.op == Op::Neg) {
      r = at(n.a);
    } else if ((n.op == Op::Add || n.op == Op::Sub) && at(n.a) >= 0 && at(n.b) >= 0) {
      r = std::max(at(n.a), at(n.b));
    } else if (n.op == Op::Mul && at(n.a) >= 0 && at(n.b) >= 0) {
      r = saturate(std::int64_t{at(n.a)} + at(n.b));
    } else if (n.op == Op::Div && at(n.a) >= 0 && g.isSpatiallyConstant(n.b)) {
      r = at(n.a);
    } else if (n.op == Op::PowI && n.ival >= 0 && at(n.a) >= 0) {
      r = saturate(std::int64_t{at(n.a)} * n.ival);
    }
    deg[static_cast<std::size_t>(id)] = r;
  }
  return deg;
}

namespace {

// Upper bound from the structure alone (max over sums, sum over products): the answer when
// the exact expansion would be too large to hold.
std::optional<int> structuralDegree(const Graph& g, NodeId root) {
  const int d = structuralDegrees(g, root)[static_cast<std::size_t>(root)];
  return d >= 0 ? std::optional<int>(d) : std::nullopt;
}

}  // namespace

std::optional<int> polynomialDegree(const Graph& g, NodeId root) {
  std::vector<std::optional<Poly>> poly(g.size());
  for (NodeId id : reachable(g, {root})) {
    const Node& n = g[id];
    const auto at = [&](NodeId k) -> const std::optional<Poly>& {
      return poly[static_cast<std::size_t>(k)];
    };
    std::optional<Poly> r;
    switch (n.op) {
      case Op::Const:
        r = Poly{{Monomial{0, 0, 0}, n.value}};
        break;
      case Op::Param:
        r = Poly{{Monomial{0, 0, 0}, genericParamValue(n.ival)}};
        break;
      case Op::VarX:
        r = Poly{{Monomial{1, 0, 0}, 1.0}};
        break;
      case Op::VarY:
        r = Poly{{Monomial{0, 1, 0}, 1.0}};
        break;
      case Op::VarZ:
        r = Poly{{Monomial{0, 0, 1}, 1.0}};
        break;
      case Op::Neg:
        if (at(n.a)) r = sum(Poly{}, *at(n.a), -1);
        break;
      case Op::Add:
      case Op::Sub:
        if (at(n.a) && at(n.b)) r = sum(*at(n.a), *at(n.b), n.op == Op::Add ? 1 : -1);
        break;
      case Op::Mul:
        if (at(n.a) && at(n.b)) r = product(*at(n.a), *at(n.b));
        break;
      case Op::Div:  // a polynomial divided by a nonzero constant
        if (at(n.a) && at(n.b)) {
          if (auto c = constantOf(*at(n.b)); c && *c != 0) r = sum(Poly{}, *at(n.a), 1 / *c);
        }
        break;
      case Op::PowI:
        if (at(n.a) && n.ival >= 0) {
          Poly acc{{Monomial{0, 0, 0}, 1.0}};
          for (int k = 0; k < n.ival && acc.size() <= kMaxTerms; ++k) {
            auto next = product(acc, *at(n.a));
            if (!next) break;
            acc = std::move(*next);
            if (k + 1 == n.ival) r = acc;
          }
          if (n.ival == 0) r = acc;
        }
        break;
      case Op::Pow:
      case Op::Sin:
      case Op::Cos:
      case Op::Tan:
      case Op::Asin:
      case Op::Acos:
      case Op::Atan:
      case Op::Atan2:
      case Op::Sinh:
      case Op::Cosh:
      case Op::Tanh:
      case Op::Exp:
      case Op::Log:
      case Op::Sqrt:
      case Op::Cbrt:
      case Op::Abs:
      case Op::Sign:
      case Op::Floor:
      case Op::Ceil:
      case Op::Min:
      case Op::Max:
      case Op::IfDefined:
        // Not polynomial operations; a subexpression free of x, y, z is still a coefficient.
        if (g.isSpatiallyConstant(id)) r = Poly{{Monomial{0, 0, 0}, 1.0 + 0.5 * id}};
        break;
    }
    poly[static_cast<std::size_t>(id)] = std::move(r);
  }
  const auto& p = poly[static_cast<std::size_t>(root)];
  if (!p) return structuralDegree(g, root);
  int degree = 0;
  for (const auto& [m, c] : *p) degree = std::max(degree, degreeOf(m));
  return degree;
}

}  // namespace zs
