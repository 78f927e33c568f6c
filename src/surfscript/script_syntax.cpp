#include "surfscript/script_syntax.hpp"

#include <cctype>
#include <cstdlib>
#include <string>

namespace zs::surfscript {

namespace {

enum class Tok { Number, Name, String, Op, End };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // Op: the character; Name: the word; String: the contents
  double number = 0;
  bool integer = false;
  Place place;
};

struct Failure {
  ScriptError error;
};

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    for (;;) {
      skipSpaceAndComments();
      Token t;
      t.place = {line_, column(), 1};
      if (at_ >= text_.size()) {
        out.push_back(t);
        return out;
      }
      const char c = text_[at_];
      if (std::isdigit(static_cast<unsigned char>(c)) ||
          (c == '.' && at_ + 1 < text_.size() &&
           std::isdigit(static_cast<unsigned char>(text_[at_ + 1])))) {
        number(t);
      } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        const std::size_t start = at_;
        while (at_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_'))
          ++at_;
        t.kind = Tok::Name;
        t.text = std::string(text_.substr(start, at_ - start));
        t.place.width = static_cast<int>(at_ - start);
      } else if (c == '"') {
        string(t);
      } else if (std::string_view("+-*/^(),;=").find(c) != std::string_view::npos) {
        t.kind = Tok::Op;
        t.text = std::string(1, c);
        ++at_;
      } else {
        throw Failure{{t.place,
                       std::string("unexpected character '") +
                           (std::isprint(static_cast<unsigned char>(c)) ? std::string(1, c) : "?") +
                           "'",
                       "surf's scripts use numbers, names, \"strings\", + - * / ^ ( ) , ; and ="}};
      }
      out.push_back(std::move(t));
    }
  }

 private:
  int column() const { return static_cast<int>(at_ - lineStart_) + 1; }

  void newline() {
    ++line_;
    lineStart_ = at_ + 1;
  }

  void skipSpaceAndComments() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        newline();
        ++at_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++at_;
      } else if (text_.substr(at_, 2) == "//") {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (text_.substr(at_, 2) == "/*") {
        const Place open{line_, column(), 2};
        at_ += 2;
        while (at_ < text_.size() && text_.substr(at_, 2) != "*/") {
          if (text_[at_] == '\n') newline();
          ++at_;
        }
        if (at_ >= text_.size())
          throw Failure{{open, "this comment is never closed", "end it with */"}};
        at_ += 2;
      } else {
        return;
      }
    }
  }

  void number(Token& t) {
    const std::size_t start = at_;
    bool integer = true;
    while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_]))) ++at_;
    if (at_ < text_.size() && text_[at_] == '.') {
      integer = false;
      ++at_;
      while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_]))) ++at_;
    }
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      std::size_t e = at_ + 1;
      if (e < text_.size() && (text_[e] == '+' || text_[e] == '-')) ++e;
      if (e < text_.size() && std::isdigit(static_cast<unsigned char>(text_[e]))) {
        integer = false;
        at_ = e;
        while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_]))) ++at_;
      }
    }
    const std::string digits(text_.substr(start, at_ - start));
    t.kind = Tok::Number;
    t.text = digits;
    t.number = std::strtod(digits.c_str(), nullptr);
    t.integer = integer;
    t.place.width = static_cast<int>(at_ - start);
  }

  void string(Token& t) {
    const std::size_t start = at_++;
    while (at_ < text_.size() && text_[at_] != '"' && text_[at_] != '\n') ++at_;
    if (at_ >= text_.size() || text_[at_] != '"')
      throw Failure{{t.place, "this string is never closed", "end it with \" on the same line"}};
    t.kind = Tok::String;
    t.text = std::string(text_.substr(start + 1, at_ - start - 1));
    ++at_;
    t.place.width = static_cast<int>(at_ - start);
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t lineStart_ = 0;
  int line_ = 1;
};

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  std::vector<Statement> run() {
    std::vector<Statement> out;
    while (peek().kind != Tok::End) {
      if (isOp(";")) {  // an empty statement
        ++at_;
        continue;
      }
      out.push_back(statement());
    }
    return out;
  }

 private:
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(at_ + ahead, tokens_.size() - 1)];
  }
  bool isOp(std::string_view op, std::size_t ahead = 0) const {
    return peek(ahead).kind == Tok::Op && peek(ahead).text == op;
  }

  [[noreturn]] void fail(const Place& place, std::string message, std::string hint = {}) const {
    throw Failure{{place, std::move(message), std::move(hint)}};
  }

  // Where a ';' was due: right after the token before, so the caret is where it is missing.
  Place afterPrevious() const {
    const Token& prev = tokens_[at_ > 0 ? at_ - 1 : 0];
    return {prev.place.line, prev.place.column + prev.place.width, 1};
  }

  void endOfStatement() {
    if (isOp(";")) {
      ++at_;
      return;
    }
    fail(afterPrevious(), "expected ';' at the end of the statement",
         "each statement ends with ';'");
  }

  Statement statement() {
    const Token& first = peek();
    if (first.kind != Tok::Name)
      fail(first.place, "a statement starts with a name",
           "write NAME = VALUE; or a command such as draw_surface;");
    Statement s;
    s.place = first.place;
    if (isTypeName(first.text) && peek(1).kind == Tok::Name) {
      s.kind = Statement::Kind::Declare;
      s.type = first.text;
      ++at_;
      s.name = peek().text;
      s.namePlace = peek().place;
      ++at_;
      if (isOp("=")) {
        ++at_;
        s.value = expression();
        s.hasValue = true;
      }
      endOfStatement();
      return s;
    }
    s.name = first.text;
    s.namePlace = first.place;
    ++at_;
    if (isOp("=")) {
      ++at_;
      s.kind = Statement::Kind::Assign;
      s.value = expression();
      s.hasValue = true;
    } else {
      s.kind = Statement::Kind::Command;
    }
    endOfStatement();
    return s;
  }

  // Nesting bound for ( ... ) and signs, which the parser follows recursively.
  static constexpr int kMaxNesting = 500;

  struct Nesting {
    Parser& p;
    explicit Nesting(Parser& parser) : p(parser) {
      if (++p.nesting_ > kMaxNesting)
        p.fail(p.peek().place, "this expression is nested too deeply", "use fewer parentheses");
    }
    ~Nesting() { --p.nesting_; }
  };

  Expr expression() {
    Nesting guard(*this);
    Expr left = term();
    while (isOp("+") || isOp("-")) left = binary(std::move(left), &Parser::term);
    return left;
  }

  Expr term() {
    Expr left = power();
    while (isOp("*") || isOp("/")) left = binary(std::move(left), &Parser::power);
    return left;
  }

  Expr power() {
    Expr left = unary();
    while (isOp("^")) left = binary(std::move(left), &Parser::unary);
    return left;
  }

  Expr binary(Expr left, Expr (Parser::*right)()) {
    Expr e;
    e.kind = Expr::Kind::Binary;
    e.place = peek().place;
    e.op = peek().text[0];
    ++at_;
    e.args.push_back(std::move(left));
    e.args.push_back((this->*right)());
    return e;
  }

  Expr unary() {
    Nesting guard(*this);
    if (isOp("-") || isOp("+")) {
      const bool minus = isOp("-");
      const Place place = peek().place;
      ++at_;
      Expr operand = unary();
      if (!minus) return operand;
      Expr e;
      e.kind = Expr::Kind::Negate;
      e.place = place;
      e.args.push_back(std::move(operand));
      return e;
    }
    return primary();
  }

  Expr primary() {
    const Token& t = peek();
    Expr e;
    e.place = t.place;
    switch (t.kind) {
      case Tok::Number:
        e.kind = Expr::Kind::Number;
        e.number = t.number;
        e.integer = t.integer;
        e.text = t.text;
        ++at_;
        return e;
      case Tok::String:
        e.kind = Expr::Kind::String;
        e.text = t.text;
        ++at_;
        return e;
      case Tok::Name:
        e.text = t.text;
        ++at_;
        if (!isOp("(")) {
          e.kind = Expr::Kind::Name;
          return e;
        }
        e.kind = Expr::Kind::Call;
        ++at_;
        if (!isOp(")")) {
          for (;;) {
            e.args.push_back(expression());
            if (isOp(",")) {
              ++at_;
              continue;
            }
            break;
          }
        }
        if (!isOp(")"))
          fail(peek().place, "expected ')' or ',' in the arguments of " + e.text + "(...)");
        ++at_;
        return e;
      case Tok::Op:
        if (t.text == "(") {
          ++at_;
          Expr inner = expression();
          if (!isOp(")")) fail(peek().place, "expected ')'", "every '(' needs its ')'");
          ++at_;
          return inner;
        }
        if (t.text == ";") fail(t.place, "a value is missing before ';'", "write NAME = VALUE;");
        fail(t.place, "expected a value, not '" + t.text + "'",
             "a value is a number, a name, a call such as rotate(surface, 0.5, xAxis), or (...)");
      case Tok::End:
        fail(afterPrevious(), "the script ends in the middle of a statement",
             "finish it and end it with ';'");
    }
    fail(t.place, "unexpected token");
  }

  std::vector<Token> tokens_;
  std::size_t at_ = 0;
  int nesting_ = 0;
};

}  // namespace

bool isTypeName(std::string_view word) {
  return word == "double" || word == "int" || word == "poly" || word == "string";
}

std::variant<std::vector<Statement>, ScriptError> parseScript(std::string_view text) {
  try {
    return Parser(Lexer(text).run()).run();
  } catch (const Failure& f) {
    return f.error;
  }
}

}  // namespace zs::surfscript
