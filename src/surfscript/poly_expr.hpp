#pragma once
// surf's polynomials, kept as the expression the script wrote rather than expanded: a tree
// of sums, products and integer powers whose leaves are numbers and affine forms
// a*x + b*y + c*z + d, and an affine map still to be substituted for x, y, z. surf's
// transforms (rotate, scale, translate) substitute affine forms for the coordinates, so a
// stack of them is one map, kept aside: the importer can turn the camera instead of the
// formula (the scene keeps the formula the script wrote), and where it must apply the map
// every leaf becomes another affine form, so the tree keeps its size and stays exact.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace zs::surfscript {

// a[0]*x + a[1]*y + a[2]*z + a[3]
using Affine = std::array<double, 4>;
// Row i is the affine form substituted for coordinate i.
using AffineMap = std::array<Affine, 3>;

AffineMap identityMap();
// The map s -> outer(inner(s)): substituting `outer` first and then `inner`.
AffineMap compose(const AffineMap& outer, const AffineMap& inner);

class Poly {
 public:
  static Poly constant(double c);
  static Poly variable(int axis);  // 0 x, 1 y, 2 z

  Poly operator+(const Poly& o) const;
  Poly operator-(const Poly& o) const;
  Poly operator*(const Poly& o) const;
  Poly operator-() const;
  Poly pow(int exponent) const;  // exponent >= 0

  // The polynomial with each coordinate replaced by its row of `map` (kept aside: pending).
  Poly substitute(const AffineMap& map) const;

  // The polynomial as written, before the pending substitution, and that substitution: this
  // polynomial is written(pending(s)).
  Poly written() const { return Poly(node_); }
  const AffineMap& pending() const { return map_; }
  // The pending substitution applied to the leaves.
  Poly applied() const;

  // A constant polynomial's value (no x, y or z left in any leaf), or nothing.
  std::optional<double> constantValue() const;
  // Total degree (an upper bound where terms cancel).
  int degree() const;
  // Levels of the written tree (a leaf is 1): the runner keeps it bounded, since printing
  // and substituting walk it recursively.
  int depth() const;

  // Where the written tree is a - b*L^2 with numbers a, b > 0 and L affine, such as
  // 1 - x^2 (the slab |L| <= sqrt(a/b)): L and sqrt(a/b).
  std::optional<std::pair<Affine, double>> slab() const;

  // In zeroset's formula language (docs/formula.md), with the fewest parentheses.
  std::string formula() const;

  struct Node;

 private:
  explicit Poly(std::shared_ptr<const Node> node) : node_(std::move(node)), map_(identityMap()) {}
  Poly(std::shared_ptr<const Node> node, const AffineMap& map)
      : node_(std::move(node)), map_(map) {}
  // Both operands with one pending map: theirs where they agree (or one has no x, y, z),
  // else each applied.
  static std::pair<Poly, Poly> aligned(const Poly& a, const Poly& b);

  std::shared_ptr<const Node> node_;
  AffineMap map_;
};

}  // namespace zs::surfscript
