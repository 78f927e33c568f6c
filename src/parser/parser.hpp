#pragma once
// The formula parser: takes the text a person typed, puts out either a Formula (expression
// graph + root) or a ParseError carrying a byte span, a message and a hint. It never throws
// and never recurses deeper than kMaxNesting, whatever the input.
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

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

// The formula, a caret line under the error's span, the message and the hint:
//   x^^2
//     ^
//   error: expected an operand after '^'
std::string formatError(std::string_view text, const ParseError& error);

}  // namespace zs
