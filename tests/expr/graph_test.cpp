// Hash-consing, the simplifier's domain discipline, the tape evaluator and the degree.
#include <gtest/gtest.h>

#include <cmath>

#include "expr/degree.hpp"
#include "expr/tape.hpp"
#include "parsed.hpp"
#include "parser/parser.hpp"

namespace zs {
namespace {

using test::parsed;

TEST(Graph, SharedSubexpressionIsStoredOnce) {
  Formula f = parsed("sin(x*y) + cos(x*y) + (x*y)^2");
  int products = 0;
  for (NodeId id : reachable(f.graph, {f.root})) products += f.graph[id].op == Op::Mul;
  EXPECT_EQ(products, 1);
}

TEST(Graph, OperandsComeBeforeTheirUsers) {
  Formula f = parsed("exp(sin(x) + y^3) / (z - 2)");
  for (std::size_t id = 0; id < f.graph.size(); ++id) {
    const Node& n = f.graph[NodeId(id)];
    if (opInfo(n.op).arity >= 1) EXPECT_LT(n.a, NodeId(id));
    if (opInfo(n.op).arity >= 2) EXPECT_LT(n.b, NodeId(id));
  }
}

TEST(Graph, NegativeAndPositiveZeroStayDistinct) {
  Graph g;
  EXPECT_NE(g.constant(0.0), g.constant(-0.0));
  EXPECT_EQ(g.constant(0.5), g.constant(0.5));
}

TEST(Simplifier, NeverWidensTheDomain) {
  // Each of these is undefined somewhere; folding it to a constant would draw a surface
  // (or hide one) where F is not defined.
  for (const char* text : {"sqrt(x)*0", "log(x) - log(x)", "(1/x)^0", "0/x"}) {
    Formula f = parsed(text);
    EXPECT_FALSE(f.graph.isConst(f.root)) << text;
  }
}

TEST(Simplifier, DoesNotFoldToNonFiniteConstants) {
  Formula f = parsed("1/0 + x");
  PointEvaluator ev(compileTape(f.graph, {f.root}));
  EXPECT_TRUE(std::isinf(ev.eval1(0.3, 0, 0)));
}

TEST(Tape, EvaluatesWithParameters) {
  Formula f = parsed("a*x^2 + b*y - z");
  const std::vector<double> params = {2.0, 3.0};  // a, b in order of appearance
  PointEvaluator ev(compileTape(f.graph, {f.root}));
  EXPECT_DOUBLE_EQ(ev.eval1(1.5, 2.0, 0.25, params), 2.0 * 2.25 + 6.0 - 0.25);
}

TEST(Tape, DomainErrorsAreNaN) {
  for (const char* text : {"sqrt(x)", "log(x)", "asin(x)", "x^0.5"}) {
    Formula f = parsed(text);
    PointEvaluator ev(compileTape(f.graph, {f.root}));
    EXPECT_TRUE(std::isnan(ev.eval1(-2, 0, 0))) << text;
  }
}

TEST(Tape, IntegerPowersOfNegativeBases) {
  Formula f = parsed("x^3 + x^-2");
  PointEvaluator ev(compileTape(f.graph, {f.root}));
  EXPECT_DOUBLE_EQ(ev.eval1(-2, 0, 0), -8.0 + 0.25);
}

TEST(Degree, OfPolynomials) {
  const std::pair<const char*, int> cases[] = {
      {"x^2 + z^2 - y", 2},
      {"x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)", 3},
      {"x^4 + y^4 + z^4 - 1", 4},
      {"x^2 + y^3 + z^5 - 1", 5},
      {"x^3*y + y^3*z + z^3*x", 4},
      {"(x+1)^2 - x^2 - 2x", 0},  // cancellation is seen through
      {"a*x^3 + y", 3},
      {"(x^2 + y^2 + z^2)/2", 2},
      {"(x + y + z)^40", 40},  // too many terms to expand: the structural bound
      {"sin(2)*x^2", 2},
  };
  for (const auto& [text, degree] : cases) {
    Formula f = parsed(text);
    EXPECT_EQ(polynomialDegree(f.graph, f.root), std::optional<int>(degree)) << text;
  }
}

TEST(Degree, OfNonPolynomials) {
  for (const char* text : {"sin(x)", "1/x", "sqrt(x^2)", "x^-2", "x^0.5", "abs(x)", "x/y"}) {
    Formula f = parsed(text);
    EXPECT_EQ(polynomialDegree(f.graph, f.root), std::nullopt) << text;
  }
}

}  // namespace
}  // namespace zs
