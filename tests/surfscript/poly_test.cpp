// surf's polynomials: exact transforms on the script's own tree, printed for zeroset.
#include <gtest/gtest.h>

#include <cmath>

#include "expr/tape.hpp"
#include "parser/parser.hpp"
#include "surfscript/poly_expr.hpp"

namespace zs::surfscript {
namespace {

const Poly X = Poly::variable(0), Y = Poly::variable(1), Z = Poly::variable(2);

double evalFormula(const std::string& text, double x, double y, double z) {
  auto parsed = parseFormula(text);
  EXPECT_TRUE(std::holds_alternative<Formula>(parsed)) << text;
  if (!std::holds_alternative<Formula>(parsed)) return NAN;
  const Formula& f = std::get<Formula>(parsed);
  return PointEvaluator(compileTape(f.graph, {f.root})).eval1(x, y, z);
}

TEST(SurfPoly, PrintsWithTheFewestParentheses) {
  EXPECT_EQ((X.pow(2) + Y.pow(2) - Poly::constant(1)).formula(), "x^2 + y^2 - 1");
  EXPECT_EQ(((X + Poly::constant(1)) * (X - Poly::constant(1))).formula(), "(x + 1)*(x - 1)");
  EXPECT_EQ((-(X * Y)).formula(), "-(x*y)");
  EXPECT_EQ((X - (Y - Z)).formula(), "x - (y - z)");
  EXPECT_EQ((X * Y).pow(3).formula(), "(x*y)^3");
}

TEST(SurfPoly, SubstitutionMapsLeaves) {
  // x -> 2y + 1, y -> -x, z -> z
  const AffineMap map{{{0, 2, 0, 1}, {-1, 0, 0, 0}, {0, 0, 1, 0}}};
  const Poly p = X.pow(2) * Y + Z;
  const Poly q = p.substitute(map);
  EXPECT_EQ(q.formula(), "(2*y + 1)^2*(-x) + z");
  for (double x : {-1.3, 0.2}) {
    for (double y : {0.7, -2.0}) {
      const double z = 0.4;
      EXPECT_NEAR(evalFormula(q.formula(), x, y, z), (2 * y + 1) * (2 * y + 1) * -x + z, 1e-12);
    }
  }
  EXPECT_EQ(q.degree(), 3);
  EXPECT_FALSE(q.constantValue());
  EXPECT_EQ((Poly::constant(2) * Poly::constant(3)).pow(2).constantValue(), 36.0);
}

TEST(SurfPoly, StackedSubstitutionsKeepTheTreeSize) {
  Poly p = X.pow(4) + Y.pow(4) + Z.pow(4) - Poly::constant(1);
  const double c = std::cos(0.3), s = std::sin(0.3);
  const AffineMap rotZ{{{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}}};
  const std::size_t before = p.substitute(rotZ).formula().size();
  for (int i = 0; i < 20; ++i) p = p.substitute(rotZ);
  EXPECT_LT(p.formula().size(), before + 40);
  // Twenty turns of 0.3 about z: the point (1, 0, 0) turned back by 6 rad is on the surface.
  const double t = -6.0;
  EXPECT_NEAR(evalFormula(p.formula(), std::cos(t), std::sin(t), 0), 0, 1e-12);
}

}  // namespace
}  // namespace zs::surfscript
