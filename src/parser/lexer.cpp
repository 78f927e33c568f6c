#include "parser/lexer.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "i18n/translate.hpp"

namespace zs {

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isIdentStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentChar(char c) {
  return isIdentStart(c) || isDigit(c);
}

// Length of the UTF-8 sequence starting with lead byte c (1 for invalid bytes).
std::size_t utf8Length(unsigned char c) {
  if (c >= 0xF0 && c < 0xF8) return 4;
  if (c >= 0xE0) return c < 0xF0 ? 3 : 1;
  if (c >= 0xC0) return 2;
  return 1;
}

Token error(std::size_t begin, std::size_t end, std::string message, std::string hint = {}) {
  Token t{Tok::Error, {begin, end}};
  t.message = std::move(message);
  t.hint = std::move(hint);
  return t;
}

// number := digits [. digits] | . digits, then optional e[+-]digits.
Token lexNumber(std::string_view s, std::size_t& i) {
  const std::size_t begin = i;
  while (i < s.size() && isDigit(s[i])) ++i;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i;
  }
  // 'e' is an exponent only when digits follow; otherwise "2e" is 2 times Euler's e.
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (j < s.size() && isDigit(s[j])) {
      i = j;
      while (i < s.size() && isDigit(s[i])) ++i;
    }
  }
  if (i < s.size() && s[i] == '.') {
    std::size_t end = i + 1;
    while (end < s.size() && (isDigit(s[end]) || s[end] == '.')) ++end;
    return error(begin, end,
                 i18n::format(i18n::tr("malformed number '%s'"),
                              std::string(s.substr(begin, end - begin)).c_str()),
                 i18n::tr("a number has at most one decimal point, e.g. 2.5"));
  }
  const std::string text(s.substr(begin, i - begin));
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(v)) {
    return error(begin, i, i18n::format(i18n::tr("number '%s' is too large"), text.c_str()),
                 i18n::tr("numbers must be below 1.8e308"));
  }
  Token t{Tok::Number, {begin, i}};
  t.number = v;
  return t;
}

}  // namespace

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
      continue;
    }
    if (isDigit(c) || (c == '.' && i + 1 < s.size() && isDigit(s[i + 1]))) {
      out.push_back(lexNumber(s, i));
      continue;
    }
    if (isIdentStart(c)) {
      const std::size_t begin = i;
      while (i < s.size() && isIdentChar(s[i])) ++i;
      out.push_back(Token{Tok::Ident, {begin, i}});
      continue;
    }
    const std::size_t begin = i;
    Tok kind;
    switch (c) {
      case '+':
        kind = Tok::Plus;
        break;
      case '-':
        kind = Tok::Minus;
        break;
      case '*':
        if (i + 1 < s.size() && s[i + 1] == '*') {
          ++i;
          kind = Tok::Caret;
        } else
          kind = Tok::Star;
        break;
      case '/':
        kind = Tok::Slash;
        break;
      case '^':
        kind = Tok::Caret;
        break;
      case '(':
        kind = Tok::LParen;
        break;
      case ')':
        kind = Tok::RParen;
        break;
      case '[':
        kind = Tok::LBracket;
        break;
      case ']':
        kind = Tok::RBracket;
        break;
      case ',':
        kind = Tok::Comma;
        break;
      case '=':
        kind = Tok::Equals;
        break;
      case '.':
        out.push_back(error(i, i + 1, i18n::tr("a '.' must be part of a number"),
                            i18n::tr("write 0.5 or .5")));
        ++i;
        continue;
      case '\0':
        out.push_back(
            error(i, i + 1, i18n::tr("the formula contains a NUL byte"), i18n::tr("remove it")));
        ++i;
        continue;
      default: {
        const auto u = static_cast<unsigned char>(c);
        const std::size_t len = std::min(utf8Length(u), s.size() - i);
        std::string hint =
            i18n::tr("formulas use ASCII: x y z, numbers, + - * / ^ ( ) and functions");
        if (u >= 0x80 && s.substr(i, len) == "\xC2\xB2") hint = i18n::tr("write x^2 instead of x²");
        if (u >= 0x80 && s.substr(i, len) == "\xCF\x80") hint = i18n::tr("write pi");
        std::string message;
        if (u >= 0x80) {
          message = i18n::format(i18n::tr("unexpected character '%s' (not ASCII)"),
                                 std::string(s.substr(i, len)).c_str());
        } else if (u < 0x20 || u == 0x7f) {
          char code[8];
          std::snprintf(code, sizeof code, "0x%02X", u);
          message = i18n::format(i18n::tr("unexpected control character (byte %s)"), code);
        } else {
          message = i18n::format(i18n::tr("unexpected character '%s'"), std::string(1, c).c_str());
        }
        out.push_back(error(i, i + len, message, hint));
        i += len;
        continue;
      }
    }
    ++i;
    out.push_back(Token{kind, {begin, i}});
  }
  out.push_back(Token{Tok::End, {s.size(), s.size()}});
  return out;
}

const char* describe(Tok kind) {
  switch (kind) {
    case Tok::Number:
      return N_("a number");
    case Tok::Ident:
      return N_("a name");
    case Tok::Plus:
      return "'+'";
    case Tok::Minus:
      return "'-'";
    case Tok::Star:
      return "'*'";
    case Tok::Slash:
      return "'/'";
    case Tok::Caret:
      return "'^'";
    case Tok::LParen:
      return "'('";
    case Tok::RParen:
      return "')'";
    case Tok::LBracket:
      return "'['";
    case Tok::RBracket:
      return "']'";
    case Tok::Comma:
      return "','";
    case Tok::Equals:
      return "'='";
    case Tok::End:
      return N_("the end of the formula");
    case Tok::Error:
      return N_("an invalid character");
  }
  return "?";
}

}  // namespace zs
