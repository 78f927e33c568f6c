#pragma once
// surf's script language (the .pic files of surf 1.0.6, SURFER-2008's galleries and
// Singular's surf.lib), read into statements: `TYPE NAME = EXPR;`, `NAME = EXPR;` and bare
// commands `NAME;`, with `//` and `/* */` comments. Expressions are numbers, names, strings,
// calls `f(a, b)`, signs and + - * / ^ with surf's precedence, which is not the usual one: a
// sign binds tightest (-x^2 is (-x)^2) and ^ groups to the left (2^3^2 is 64), as surf's
// yacc grammar has it. Every node keeps the place it came from.
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace zs::surfscript {

struct Place {
  int line = 1;    // 1-based
  int column = 1;  // 1-based, in bytes (surf's scripts are ASCII)
  int width = 1;   // characters the caret underlines
};

struct ScriptError {
  Place place;
  std::string message;
  std::string hint;  // may be empty
};

struct Expr {
  enum class Kind { Number, Name, String, Call, Negate, Binary };
  Kind kind = Kind::Number;
  Place place;
  double number = 0;
  bool integer = false;    // a Number written without '.' or exponent
  std::string text;        // Name and Call: the name; String: its contents
  char op = 0;             // Binary: + - * / ^
  std::vector<Expr> args;  // Call: the arguments; Negate: one; Binary: two
};

struct Statement {
  enum class Kind { Declare, Assign, Command };
  Kind kind = Kind::Command;
  Place place;       // of the statement's first word
  std::string type;  // Declare: double, int, poly, string
  std::string name;
  Place namePlace;
  Expr value;  // Declare (may be absent: hasValue), Assign
  bool hasValue = false;
};

std::variant<std::vector<Statement>, ScriptError> parseScript(std::string_view text);

// The words that declare a variable.
bool isTypeName(std::string_view word);

}  // namespace zs::surfscript
