#pragma once
// The formula parser: takes the text a person typed, puts out either a Formula (expression
// graph + root) or a ParseError carrying a byte span, a message and a hint. It never throws
// and never recurses deeper than kMaxNesting, whatever the input.
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

inline constexpr std::size_t kMaxFormulaBytes = 1 << 20;  // 1 MiB

// Value given to a named parameter that the scene or --set does not mention.
inline constexpr double kDefaultParamValue = 0.5;

struct Span {
  std::size_t begin = 0;  // byte offsets into the formula, [begin, end)
  std::size_t end = 0;
};

struct ParseError {
  Span span;
  std::string message;
  std::string hint;  // may be empty
};

using ParseResult = std::variant<Formula, ParseError>;

ParseResult parseFormula(std::string_view text);

// The formula as written, for typesetting (src/print): no folding, no sharing, names and
// numbers as typed, implicit products marked, an equation kept as its two sides. Unary
// plus and parentheses leave no node (the typesetter places parentheses by precedence).
struct SyntaxNode {
  enum class Kind { Number, Variable, Constant, Param, Operation, Equation };
  Kind kind;
  Op op;                  // Operation: Neg, Add, Sub, Mul, Div, Pow or a function
  std::string text;       // Number: as typed; Variable, Constant (pi, e), Param: the name
  int a = -1, b = -1;     // operands: indices into SyntaxTree::nodes
  bool implicit = false;  // Mul written without '*': 2x, x y, (x+1)(x-1)
};
struct SyntaxTree {
  std::vector<SyntaxNode> nodes;  // operands before the nodes that use them
  int root = -1;
};
// The same errors as parseFormula.
std::variant<SyntaxTree, ParseError> parseSyntax(std::string_view text);

// The formula, a caret line under the error's span, the message and the hint:
//   x^^2
//     ^
//   error: expected an operand after '^'
std::string formatError(std::string_view text, const ParseError& error);

}  // namespace zs
