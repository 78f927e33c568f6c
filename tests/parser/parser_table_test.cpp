// Table tests of the formula language: formula -> normalized text, formula -> error span.
// The normalized text is what the printer writes for the simplified graph; see
// docs/formula.md for the rules these rows pin down.
#include <gtest/gtest.h>

#include <string>

#include "expr/printer.hpp"
#include "parser/parser.hpp"

namespace zs {
namespace {

struct NormalCase {
  std::string input;
  std::string normalized;
};

struct ErrorCase {
  std::string input;
  std::size_t begin, end;
  std::string messageStart;
};

const NormalCase kNormal[] = {
    {"x^2 + z^2 - y", "x^2 + z^2 - y"},
    {"x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)",
     "x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - 0.4*(x*y + x*z + y*z)"},
    {"x^4 + y^4 + z^4 - 1", "x^4 + y^4 + z^4 - 1"},
    {"x^2 + y^3 + z^5 - 1", "x^2 + y^3 + z^5 - 1"},
    {"x^3*y + y^3*z + z^3*x", "x^3*y + y^3*z + z^3*x"},
    {"x^4 - z^4 - y", "x^4 - z^4 - y"},
    {"x^2*y^2 + y^2*z^2 + z^2*x^2 - 1", "x^2*y^2 + y^2*z^2 + z^2*x^2 - 1"},
    {"2", "2"},
    {"2.5", "2.5"},
    {".5", "0.5"},
    {"1e-3", "0.001"},
    {"2.5e+3", "2500"},
    {"x", "x"},
    {"pi", "3.141592653589793"},
    {"e", "2.718281828459045"},
    {"2pi", "6.283185307179586"},
    {"2 pi", "6.283185307179586"},
    {"2x", "2*x"},
    {"3(x+1)", "3*(x + 1)"},
    {"(x+1)(x-1)", "(x + 1)*(x - 1)"},
    {"x y", "x*y"},
    {"x y z", "x*y*z"},
    {"2x^2", "2*x^2"},
    {"-x^2", "-x^2"},
    {"(-x)^2", "x^2"},
    {"x^-2", "x^-2"},
    {"x^2^3", "x^8"},
    {"2^3^2", "512"},
    {"x**2", "x^2"},
    {"[x+1]*2", "2*(x + 1)"},
    {"x = y", "x - y"},
    {"x^2 + y^2 = z^2", "x^2 + y^2 - z^2"},
    {"x + 0", "x"},
    {"0 + x", "x"},
    {"x*1", "x"},
    {"1*x", "x"},
    {"x^1", "x"},
    {"x^0", "1"},
    {"x*x", "x^2"},
    {"x*2", "2*x"},
    {"x*0", "0"},
    {"sqrt(x)*0", "0*sqrt(x)"},
    {"x - x", "0"},
    {"sqrt(x) - sqrt(x)", "sqrt(x) - sqrt(x)"},
    {"-(-x)", "x"},
    {"--x", "x"},
    {"+x", "x"},
    {"x - -y", "x + y"},
    {"x + -y", "x - y"},
    {"sin(x) + cos(y)", "sin(x) + cos(y)"},
    {"atan2(y, x)", "atan2(y, x)"},
    {"min(x, y) + max(y, z)", "min(x, y) + max(y, z)"},
    {"pow(x, 3)", "x^3"},
    {"pow(x, 0.5)", "x^0.5"},
    {"x^0.5", "x^0.5"},
    {"x^y", "x^y"},
    {"a*x^2 + b", "a*x^2 + b"},
    {"a x", "a*x"},
    {"ln(x)", "log(x)"},
    {"sign(x) + floor(y) + ceil(z) + abs(x)", "sign(x) + floor(y) + ceil(z) + abs(x)"},
    {"cbrt(x) + exp(y) + log(z)", "cbrt(x) + exp(y) + log(z)"},
    {"sinh(x) + cosh(y) + tanh(z)", "sinh(x) + cosh(y) + tanh(z)"},
    {"asin(x) + acos(y) + atan(z)", "asin(x) + acos(y) + atan(z)"},
    {"tan(x)", "tan(x)"},
    {"1/x", "1/x"},
    {"x/2", "x/2"},
    {"x/y/z", "x/y/z"},
    {"x/(y/z)", "x/(y/z)"},
    {"x - (y - z)", "x - (y - z)"},
    {"x - y - z", "x - y - z"},
    {"(x^2)^3", "x^6"},
    {"(x^3)^-1", "(x^3)^-1"},
    {"2*3*x", "6*x"},
    {"1e300*1e300*x", "1e+300^2*x"},
    {"sin(pi)", "1.2246467991473532e-16"},
    {"(x + y)^2", "(x + y)^2"},
    {"-2x", "-2*x"},
    {"x*-2", "-2*x"},
    {"a^2", "a^2"},
    {"-x*y", "-x*y"},
    {"-(x*y)", "-(x*y)"},
};

const ErrorCase kErrors[] = {
    {"", 0, 0, "the formula is empty"},
    {"x+", 1, 2, "expected an operand after '+'"},
    {"(x", 0, 1, "this '(' is never closed"},
    {"sin(", 3, 4, "expected an operand after '('"},
    {"x^^2", 2, 3, "expected an operand after '^',"},
    {"2..3", 0, 4, "malformed number '2..3'"},
    {"1.2.3", 0, 5, "malformed number '1.2.3'"},
    {"xy", 0, 2, "'xy' is not a name"},
    {"xyz", 0, 3, "'xyz' is not a name"},
    {"x2", 0, 2, "'x2' is not a name"},
    {"sinx", 0, 4, "'sinx' is not a name"},
    {"sinn(x)", 0, 4, "unknown function 'sinn' — did "},
    {"sin x", 0, 3, "function 'sin' needs its argum"},
    {"sin(x, y)", 5, 6, "sin() takes 1 argument"},
    {"atan2(x)", 7, 8, "atan2() takes 2 arguments"},
    {"x = y = z", 6, 7, "a formula has at most one '='"},
    {")", 0, 1, "expected an operand (a number,"},
    {"x +* y", 3, 4, "expected an operand, found '*'"},
    {"2 3", 2, 3, "two numbers in a row"},
    {"x^2000", 2, 6, "integer exponent 2000 is too l"},
    {"1e999", 0, 5, "number '1e999' is too large"},
    {"x ∈ y", 2, 5, "unexpected character '∈' (not "},
    {"x²", 1, 3, "unexpected character '²' (not "},
    {"x # y", 2, 3, "unexpected character '#'"},
    {".", 0, 1, "a '.' must be part of a number"},
    {"(x))", 3, 4, "expected an operator or the en"},
    {"[x)", 2, 3, "expected ']', found ')'"},
    {"f(", 1, 2, "expected an operand after '('"},
    {std::string("x + \0y", 6), 4, 5, "the formula contains a NUL byte"},
    {"x + \x01", 4, 5, "unexpected control character"},
    {"x^-", 2, 3, "expected an operand after '-'"},
    {"pow(x)", 5, 6, "pow() takes 2 arguments"},
    {"x =", 2, 3, "expected an expression after '='"},
};

TEST(ParserTable, NormalizesFormulas) {
  for (const NormalCase& c : kNormal) {
    ParseResult r = parseFormula(c.input);
    ASSERT_TRUE(std::holds_alternative<Formula>(r))
        << c.input << "\n"
        << formatError(c.input, std::get<ParseError>(r));
    const Formula& f = std::get<Formula>(r);
    EXPECT_EQ(print(f.graph, f.root).value_or("?"), c.normalized) << "input: " << c.input;
  }
}

TEST(ParserTable, ReportsErrorSpans) {
  for (const ErrorCase& c : kErrors) {
    ParseResult r = parseFormula(c.input);
    ASSERT_TRUE(std::holds_alternative<ParseError>(r)) << "accepted: " << c.input;
    const ParseError& e = std::get<ParseError>(r);
    EXPECT_EQ(e.span.begin, c.begin) << c.input;
    EXPECT_EQ(e.span.end, c.end) << c.input;
    EXPECT_EQ(e.message.substr(0, c.messageStart.size()), c.messageStart) << c.input;
  }
}

TEST(ParserTable, HasEnoughRows) {
  EXPECT_GE(std::size(kNormal) + std::size(kErrors), 60u);
}

}  // namespace
}  // namespace zs

namespace zs {
namespace {

// The syntax tree for typesetting: the formula as written.
TEST(SyntaxTree, KeepsNumbersNamesAndSidesAsWritten) {
  auto parsed = parseSyntax("2x + sqrt(2)/4 - pi*a = 1.5e-3");
  ASSERT_TRUE(std::holds_alternative<SyntaxTree>(parsed));
  const SyntaxTree& t = std::get<SyntaxTree>(parsed);
  const SyntaxNode& root = t.nodes[std::size_t(t.root)];
  EXPECT_EQ(root.kind, SyntaxNode::Kind::Equation);
  EXPECT_EQ(t.nodes[std::size_t(root.b)].text, "1.5e-3");  // as typed, not 0.0015
  int implicit = 0, sqrt = 0, pi = 0, params = 0;
  for (const SyntaxNode& n : t.nodes) {
    implicit += n.kind == SyntaxNode::Kind::Operation && n.op == Op::Mul && n.implicit;
    sqrt += n.kind == SyntaxNode::Kind::Operation && n.op == Op::Sqrt;  // not folded
    pi += n.kind == SyntaxNode::Kind::Constant && n.text == "pi";
    params += n.kind == SyntaxNode::Kind::Param && n.text == "a";
  }
  EXPECT_EQ(implicit, 1);
  EXPECT_EQ(sqrt, 1);
  EXPECT_EQ(pi, 1);
  EXPECT_EQ(params, 1);
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    EXPECT_LT(t.nodes[i].a, int(i)) << "operands come first";
    EXPECT_LT(t.nodes[i].b, int(i));
  }
}

TEST(SyntaxTree, RefusesWhatTheParserRefusesWithTheSameError) {
  for (const char* bad : {"x^^2", "sin x", "x^100000", "(x + 1", ""}) {
    auto syntax = parseSyntax(bad);
    auto formula = parseFormula(bad);
    ASSERT_TRUE(std::holds_alternative<ParseError>(syntax)) << bad;
    EXPECT_EQ(std::get<ParseError>(syntax).message, std::get<ParseError>(formula).message);
  }
}

}  // namespace
}  // namespace zs
