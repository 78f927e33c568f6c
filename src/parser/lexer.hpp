#pragma once
// Splits formula text into tokens with byte spans. Malformed numbers, stray bytes, NUL and
// non-ASCII characters become Error tokens so the parser can report them where they stand.
#include <string>
#include <string_view>
#include <vector>

#include "parser/parser.hpp"

namespace zs {

enum class Tok {
  Number,
  Ident,
  Plus,
  Minus,
  Star,
  Slash,
  Caret,
  LParen,
  RParen,
  LBracket,
  RBracket,
  Comma,
  Equals,
  End,
  Error
};

struct Token {
  Tok kind;
  Span span;
  double number = 0.0;    // Number
  std::string message{};  // Error: what is wrong
  std::string hint{};     // Error: how to fix it
};

std::vector<Token> tokenize(std::string_view text);

// How a token kind is written, for messages ("expected ')'").
const char* describe(Tok kind);  // English, marked for translation (i18n::tr)

}  // namespace zs
