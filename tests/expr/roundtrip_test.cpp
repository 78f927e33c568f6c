// print -> parse is the identity on the graph: for hand-picked formulas and for thousands of
// random ones, the printed normal form parses back to an isomorphic graph.
#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <string>
#include <vector>

#include "expr/printer.hpp"
#include "parser/parser.hpp"
#include "support/random_formula.hpp"

namespace zs {
namespace {

// The DAG below `root` in a canonical numbering (first visit of a post-order walk from the
// root), with parameters by name: equal keys mean isomorphic graphs, whatever ids the two
// parses happened to allocate. Explicit stack: random formulas can be deep.
std::string structuralKey(const Graph& g, NodeId root) {
  std::vector<int> number(g.size(), -1);
  std::string key;
  int next = 0;
  std::vector<std::pair<NodeId, bool>> stack{{root, false}};
  while (!stack.empty()) {
    auto [id, expanded] = stack.back();
    stack.pop_back();
    if (number[id] >= 0) continue;
    const Node& n = g[id];
    const int arity = opInfo(n.op).arity;
    if (!expanded) {
      stack.push_back({id, true});
      if (arity >= 2) stack.push_back({n.b, false});
      if (arity >= 1) stack.push_back({n.a, false});
      continue;
    }
    number[id] = next++;
    key += std::string(opInfo(n.op).enumName) + "(";
    if (arity >= 1) key += std::to_string(number[n.a]);
    if (arity >= 2) key += "," + std::to_string(number[n.b]);
    if (n.op == Op::Const) key += std::to_string(std::bit_cast<std::uint64_t>(n.value));
    if (n.op == Op::PowI) key += "^" + std::to_string(n.ival);
    if (n.op == Op::Param) key += g.params()[n.ival];
    key += ")";
  }
  return key;
}

// Parses `text`, prints, parses the print; true when both graphs agree.
::testing::AssertionResult roundTrips(const std::string& text) {
  ParseResult first = parseFormula(text);
  if (!std::holds_alternative<Formula>(first)) return ::testing::AssertionSuccess();  // rejected
  const Formula& f = std::get<Formula>(first);
  const auto printed = print(f.graph, f.root);
  if (!printed) return ::testing::AssertionFailure() << "too large to print: " << text;
  ParseResult second = parseFormula(*printed);
  if (auto* e = std::get_if<ParseError>(&second)) {
    return ::testing::AssertionFailure() << "printed form does not parse: " << text << "\n"
                                         << formatError(*printed, *e);
  }
  const Formula& g = std::get<Formula>(second);
  if (structuralKey(f.graph, f.root) != structuralKey(g.graph, g.root)) {
    return ::testing::AssertionFailure()
           << "graphs differ\n  input:   " << text << "\n  printed: " << *printed
           << "\n  reprint: " << print(g.graph, g.root).value_or("?");
  }
  return ::testing::AssertionSuccess();
}

TEST(RoundTrip, HandPickedFormulas) {
  for (const char* text : {
           "x^2 + z^2 - y",
           "x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)",
           "x^4 + y^4 + z^4 - 1",
           "x^2 + y^3 + z^5 - 1",
           "x^3*y + y^3*z + z^3*x",
           "x^4 - z^4 - y",
           "x^2*y^2 + y^2*z^2 + z^2*x^2 - 1",
           "-x^2",
           "(-x)^3",
           "x^-2",
           "x^y^z",
           "(x^y)^z",
           "(-2)^x",
           "2^-x",
           "x - (y - z)",
           "x/(y/z)",
           "x/y/z",
           "-(x*y)",
           "-x*y",
           "x*-y",
           "x - -y",
           "-0*x + y",
           "1e300*1e300*x",
           "1e-300*x",
           "a*x + b*y",
           "sin(x)^2 + cos(y)^-1",
           "atan2(-y, x)^0.5",
           "pow(x, y) - pow(-x, 2)",
           "min(-x, max(y, -z))",
           "-(-(x))",
           "sqrt(x)*0",
           "log(x) - log(x)",
           "x^1024",
           "2.5e-320*x",  // a subnormal constant prints and reads back exactly
       }) {
    EXPECT_TRUE(roundTrips(text));
  }
}

TEST(RoundTrip, RandomFormulas) {
  std::mt19937_64 rng(20261121);
  int accepted = 0;
  for (int i = 0; i < 3000; ++i) {
    test::RandomFormulaOptions options;
    options.maxDepth = 2 + i % 8;
    const std::string text = test::randomFormula(rng, options);
    ASSERT_TRUE(roundTrips(text));
    accepted += std::holds_alternative<Formula>(parseFormula(text));
  }
  EXPECT_GE(accepted, 1000);  // the generator writes valid formulas; most must parse
}

// Found by zs_parser_fuzz: the simplifier can turn a flat chain of products into a graph
// whose faithful text needs more nested parentheses than the parser accepts. The printer
// then returns nothing rather than text that does not parse.
TEST(RoundTrip, TooDeepToPrintIsNothingNotUnparsableText) {
  Graph g;
  NodeId acc = g.var(0);
  for (int i = 0; i < 2 * kMaxNesting; ++i)
    acc = g.binary(Op::Mul, i % 2 ? g.var(1) : g.param("k"), acc);  // k*(y*(k*(...)))
  const std::optional<std::string> deep = print(g, acc);
  if (deep) {
    EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula(*deep))) << deep->substr(0, 200);
  }
  NodeId shallow = g.var(0);
  for (int i = 0; i < kMaxNesting / 2; ++i)
    shallow = g.binary(Op::Mul, i % 2 ? g.var(1) : g.param("k"), shallow);
  const std::optional<std::string> text = print(g, shallow);
  ASSERT_TRUE(text);
  EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula(*text)));
}

}  // namespace
}  // namespace zs
