// A recursive-descent recognizer of SURFER's grammar. Recursion is bounded: the nesting
// depth is counted and refused past kMaxDepth, far beyond any real SURFER formula.
#include "jsurf/surfer_syntax.hpp"

#include <array>
#include <cctype>

namespace zs::jsurf {
namespace {

constexpr int kMaxDepth = 200;

constexpr std::array<std::string_view, 13> kFunctions{"sin",   "cos", "tan", "asin", "acos",
                                                      "atan",  "exp", "log", "sqrt", "ceil",
                                                      "floor", "abs", "sign"};

enum class Tok { Number, Integer, Name, Op, End, Bad };

struct Token {
  Tok kind = Tok::End;
  std::size_t begin = 0;
  std::string_view text;
};

bool isLetter(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isDigit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// What a subexpression is, for the walker's checks.
struct Value {
  bool variable = false;  // holds x, y or z
  bool integer = false;   // an integer literal, perhaps in parentheses
};

class Recognizer {
 public:
  explicit Recognizer(std::string_view s) : s_(s) { next(); }

  std::optional<SurferSyntaxError> run() {
    Value v;
    if (!add(v, 0)) return error_;
    if (tok_.kind != Tok::End) fail(tok_.begin, "SURFER expects an operator here" + implicitHint());
    return error_;
  }

 private:
  std::string implicitHint() const {
    return tok_.kind == Tok::Name || tok_.kind == Tok::Number || tok_.kind == Tok::Integer ||
                   tok_.text == "("
               ? " (SURFER has no implicit product: write '*')"
               : "";
  }

  bool fail(std::size_t at, std::string message) {
    if (!error_) error_ = SurferSyntaxError{at, std::move(message)};
    return false;
  }

  void next() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' ||
                                s_[pos_] == '\r' || s_[pos_] == '\f'))
      ++pos_;
    tok_ = {Tok::End, pos_, {}};
    if (pos_ >= s_.size()) return;
    const std::size_t b = pos_;
    const char c = s_[pos_];
    if (isLetter(c)) {
      while (pos_ < s_.size() && (isLetter(s_[pos_]) || isDigit(s_[pos_]))) ++pos_;
      tok_ = {Tok::Name, b, s_.substr(b, pos_ - b)};
    } else if (isDigit(c) || (c == '.' && pos_ + 1 < s_.size() && isDigit(s_[pos_ + 1]))) {
      lexNumber();
    } else {
      ++pos_;
      const bool known = std::string_view("+-*/^()").find(c) != std::string_view::npos;
      tok_ = {known ? Tok::Op : Tok::Bad, b, s_.substr(b, 1)};
    }
  }

  void lexNumber() {
    const std::size_t b = pos_;
    while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;
    bool real = false;
    if (pos_ < s_.size() && s_[pos_] == '.') {
      real = true;
      ++pos_;
      while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      std::size_t p = pos_ + 1;
      if (p < s_.size() && (s_[p] == '+' || s_[p] == '-')) ++p;
      if (p < s_.size() && isDigit(s_[p])) {
        real = true;
        pos_ = p;
        while (pos_ < s_.size() && isDigit(s_[pos_])) ++pos_;
      }
    }
    const std::string_view text = s_.substr(b, pos_ - b);
    // SURFER's integers have no leading zero: "07" is two tokens to it.
    const bool leadingZero = !real && text.size() > 1 && text[0] == '0';
    tok_ = {leadingZero ? Tok::Bad : real ? Tok::Number : Tok::Integer, b, text};
  }

  bool isOp(char c) const { return tok_.kind == Tok::Op && tok_.text[0] == c; }

  bool add(Value& v, int depth) {
    if (depth > kMaxDepth) return fail(tok_.begin, "the formula nests too deeply for SURFER");
    if (!mult(v, depth)) return false;
    while (isOp('+') || isOp('-')) {
      next();
      Value rhs;
      if (!mult(rhs, depth)) return false;
      v = {v.variable || rhs.variable, false};
    }
    return true;
  }

  bool mult(Value& v, int depth) {
    if (!neg(v, depth)) return false;
    while (isOp('*') || isOp('/')) {
      const bool divide = isOp('/');
      const std::size_t at = tok_.begin;
      next();
      Value rhs;
      if (!neg(rhs, depth)) return false;
      if (divide && rhs.variable)
        return fail(at, "SURFER divides only by constants and parameters, not by x, y or z");
      v = {v.variable || rhs.variable, false};
    }
    return true;
  }

  bool neg(Value& v, int depth) {
    if (isOp('-')) {
      next();
      if (isOp('-') || isOp('+'))
        return fail(tok_.begin, "SURFER does not read two signs in a row: use parentheses");
      if (!pow(v, depth)) return false;
      v.integer = false;
      return true;
    }
    if (isOp('+')) return fail(tok_.begin, "SURFER has no unary '+'");
    return pow(v, depth);
  }

  bool pow(Value& v, int depth) {
    if (depth > kMaxDepth) return fail(tok_.begin, "the formula nests too deeply for SURFER");
    if (!unary(v, depth)) return false;
    if (!isOp('^')) return true;
    next();
    if (isOp('*')) return fail(tok_.begin, "SURFER has no '**': write '^'");
    if (isOp('-') || isOp('+'))
      return fail(tok_.begin, "SURFER does not read a sign after '^': use parentheses");
    const std::size_t at = tok_.begin;
    Value exponent;
    if (!pow(exponent, depth + 1)) return false;
    if (v.variable && !exponent.integer)
      return fail(at, "SURFER raises x, y and z only to integer powers written as numbers");
    v = {v.variable, false};
    return true;
  }

  bool unary(Value& v, int depth) {
    if (tok_.kind == Tok::Name) {
      const Token name = tok_;
      next();
      if (isOp('(')) {
        bool known = false;
        for (std::string_view f : kFunctions) known = known || f == name.text;
        if (!known)
          return fail(name.begin, "SURFER has no function '" + std::string(name.text) + "'");
        next();
        Value arg;
        if (!add(arg, depth + 1)) return false;
        if (!isOp(')'))
          return fail(tok_.begin, "SURFER expects ')' (its functions take one argument)");
        next();
        if (arg.variable)
          return fail(name.begin, "SURFER applies '" + std::string(name.text) +
                                      "' only to constants and parameters, not to x, y or z");
        v = {false, false};
        return true;
      }
      v = {name.text == "x" || name.text == "y" || name.text == "z", false};
      return true;
    }
    if (tok_.kind == Tok::Number || tok_.kind == Tok::Integer) {
      v = {false, tok_.kind == Tok::Integer};
      next();
      return true;
    }
    if (isOp('(')) {
      next();
      if (!add(v, depth + 1)) return false;
      if (!isOp(')')) return fail(tok_.begin, "SURFER expects ')' here");
      next();
      return true;
    }
    if (tok_.kind == Tok::End)
      return fail(tok_.begin, "the formula ends where SURFER expects an operand");
    if (tok_.kind == Tok::Bad && isDigit(tok_.text[0]))
      return fail(tok_.begin, "SURFER does not read integers with a leading zero");
    return fail(tok_.begin,
                "SURFER does not read '" + std::string(tok_.text.substr(0, 1)) + "' here");
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  Token tok_;
  std::optional<SurferSyntaxError> error_;
};

}  // namespace

std::optional<SurferSyntaxError> checkSurferSyntax(std::string_view formula) {
  return Recognizer(formula).run();
}

}  // namespace zs::jsurf
