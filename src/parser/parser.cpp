#include "parser/parser.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "parser/lexer.hpp"
#include "parser/suggest.hpp"

namespace zs {

namespace {

// Recursive descent with an explicit depth budget: every level of nesting (group, call,
// unary sign, exponent) costs one unit, so hostile input ends in an error, never in a stack
// overflow. Grammar (docs/formula.md):
//   formula := sum ['=' sum]
//   sum     := product (('+'|'-') product)*
//   product := unary (('*'|'/') unary | <implicit> power)*
//   unary   := ('-'|'+') unary | power
//   power   := atom ['^' unary]          right-associative through unary
//   atom    := number | name | name '(' args ')' | '(' sum ')' | '[' sum ']'
class Parser {
 public:
  Parser(std::string_view text, std::vector<Token> tokens) : text_(text), toks_(std::move(tokens)) {}

  ParseResult run() {
    Formula f;
    g_ = &f.graph;
    NodeId lhs = sum();
    if (ok() && peek().kind == Tok::Equals) {
      const Span eq = next().span;
      if (peek().kind == Tok::End) {
        fail(eq, "expected an expression after '='", "write F = G, e.g. x^2 + y^2 = 1");
      }
      NodeId rhs = ok() ? sum() : kNoNode;
      if (ok()) lhs = g_->binary(Op::Sub, lhs, rhs);
      if (ok() && peek().kind == Tok::Equals) {
        fail(peek().span, "a formula has at most one '='", "write F = G, meaning F - G = 0");
      }
    }
    if (ok() && peek().kind != Tok::End) unexpected("an operator or the end of the formula");
    if (!ok()) return *error_;
    f.root = lhs;
    return f;
  }

 private:
  bool ok() const { return !error_; }
  std::string text(std::size_t begin, std::size_t end) const {
    return std::string(text_.substr(begin, end - begin));
  }
  const Token& peek() const { return toks_[pos_]; }
  const Token& next() { return toks_[pos_ < toks_.size() - 1 ? pos_++ : pos_]; }

  void fail(Span span, std::string message, std::string hint) {
    if (!error_) error_ = ParseError{span, std::move(message), std::move(hint)};
  }
  void unexpected(std::string_view expected) {
    const Token& t = peek();
    if (t.kind == Tok::Error) return fail(t.span, t.message, t.hint);
    fail(t.span, "expected " + std::string(expected) + ", found " + std::string(describe(t.kind)),
         t.kind == Tok::Caret ? "'^' needs a base and an exponent, e.g. x^2" : "");
  }

  struct DepthGuard {
    Parser& p;
    explicit DepthGuard(Parser& parser, Span span) : p(parser) {
      if (++p.depth_ > kMaxNesting) {
        p.fail(span, "the formula is nested too deeply (more than " +
                         std::to_string(kMaxNesting) + " levels)",
               "simplify the expression or split it");
      }
    }
    ~DepthGuard() { --p.depth_; }
  };

  NodeId sum() {
    NodeId acc = product();
    while (ok() && (peek().kind == Tok::Plus || peek().kind == Tok::Minus)) {
      const Op op = next().kind == Tok::Plus ? Op::Add : Op::Sub;
      const NodeId rhs = product();
      if (!ok()) return kNoNode;
      acc = g_->binary(op, acc, rhs);
    }
    return acc;
  }

  static bool startsAtom(Tok k) {
    return k == Tok::Number || k == Tok::Ident || k == Tok::LParen || k == Tok::LBracket;
  }

  NodeId product() {
    NodeId acc = unary();
    while (ok()) {
      const Tok k = peek().kind;
      if (k == Tok::Star || k == Tok::Slash) {
        next();
        const NodeId rhs = unary();
        if (!ok()) return kNoNode;
        acc = g_->binary(k == Tok::Star ? Op::Mul : Op::Div, acc, rhs);
      } else if (startsAtom(k)) {
        // Implicit multiplication: 2x, 3(x+1), (x+1)(x-1), 2 pi, x y.
        if (k == Tok::Number && toks_[pos_ - 1].kind == Tok::Number) {
          fail(peek().span, "two numbers in a row",
               "write an operator between them, e.g. 2*3, or remove the space");
          return kNoNode;
        }
        const NodeId rhs = power();
        if (!ok()) return kNoNode;
        acc = g_->binary(Op::Mul, acc, rhs);
      } else {
        break;
      }
    }
    return ok() ? acc : kNoNode;
  }

  NodeId unary() {
    const Tok k = peek().kind;
    if (k == Tok::Minus || k == Tok::Plus) {
      DepthGuard guard(*this, peek().span);
      next();
      if (!ok()) return kNoNode;
      const NodeId a = unary();
      if (!ok()) return kNoNode;
      return k == Tok::Minus ? g_->unary(Op::Neg, a) : a;
    }
    return power();
  }

  NodeId power() {
    const NodeId base = atom();
    if (!ok() || peek().kind != Tok::Caret) return base;
    DepthGuard guard(*this, peek().span);
    next();
    if (!ok()) return kNoNode;
    const std::size_t expBegin = peek().span.begin;
    const NodeId exponent = unary();
    if (!ok()) return kNoNode;
    const Node& e = (*g_)[exponent];
    if (e.op == Op::Const && std::nearbyint(e.value) == e.value &&
        std::fabs(e.value) > kMaxIntegerExponent) {
      fail({expBegin, toks_[pos_ - 1].span.end},
           "integer exponent " + text(expBegin, toks_[pos_ - 1].span.end) + " is too large",
           "exponents are limited to " + std::to_string(kMaxIntegerExponent) +
               " in magnitude; use exp(n*log(x)) for x > 0");
      return kNoNode;
    }
    return g_->binary(Op::Pow, base, exponent);
  }

  NodeId group(Tok close, std::string_view closeText) {
    const Token open = next();
    DepthGuard guard(*this, open.span);
    if (!ok()) return kNoNode;
    const NodeId inner = sum();
    if (!ok()) return kNoNode;
    if (peek().kind != close) {
      if (peek().kind == Tok::End) {
        fail(open.span, "this '" + std::string(text_.substr(open.span.begin, 1)) +
                            "' is never closed", "add " + std::string(closeText));
      } else {
        unexpected(closeText);
      }
      return kNoNode;
    }
    next();
    return inner;
  }

  NodeId atom() {
    const Token& t = peek();
    switch (t.kind) {
      case Tok::Number: next(); return g_->constant(t.number);
      case Tok::LParen: return group(Tok::RParen, "')'");
      case Tok::LBracket: return group(Tok::RBracket, "']'");
      case Tok::Ident: return name();
      case Tok::End:
        if (pos_ == 0) {
          fail(t.span, "the formula is empty", "type an expression such as x^2 + y^2 + z^2 - 1");
        } else {
          const Token& prev = toks_[pos_ - 1];
          fail(prev.span, "expected an operand after " + std::string(describe(prev.kind)),
               "complete the expression");
        }
        return kNoNode;
      case Tok::Caret: case Tok::Star: case Tok::Slash: case Tok::Equals:
        if (pos_ > 0 && (toks_[pos_ - 1].kind == Tok::Caret || toks_[pos_ - 1].kind == Tok::Star ||
                         toks_[pos_ - 1].kind == Tok::Slash)) {
          fail(t.span, "expected an operand after " + std::string(describe(toks_[pos_ - 1].kind)) +
                           ", found " + std::string(describe(t.kind)),
               "remove the extra operator");
          return kNoNode;
        }
        unexpected("an operand");
        return kNoNode;
      default:
        unexpected("an operand (a number, x, y, z, a name or '(')");
        return kNoNode;
    }
  }

  NodeId name() {
    const Token t = next();
    const std::string_view id = text_.substr(t.span.begin, t.span.end - t.span.begin);
    const bool call = peek().kind == Tok::LParen;
    if (id == "x" || id == "y" || id == "z") return g_->var(id[0] - 'x');
    if (id == "pi") return g_->constant(std::numbers::pi);
    if (id == "e") return g_->constant(std::numbers::e);
    if (auto op = functionByName(id)) {
      if (!call) {
        fail(t.span, "function '" + std::string(id) + "' needs its argument in parentheses",
             "write " + std::string(id) + "(x)");
        return kNoNode;
      }
      return callArgs(*op, t);
    }
    if (auto problem = diagnoseName(id, call)) {
      fail(t.span, problem->message, problem->hint);
      return kNoNode;
    }
    return g_->param(id);  // any other name is a parameter (docs/formula.md)
  }

  NodeId callArgs(Op op, const Token& nameTok) {
    const Token open = next();
    DepthGuard guard(*this, open.span);
    if (!ok()) return kNoNode;
    const int arity = opInfo(op).arity;
    NodeId args[2] = {kNoNode, kNoNode};
    for (int k = 0; k < arity; ++k) {
      if (k > 0) {
        if (peek().kind != Tok::Comma) {
          const std::string fn(text_.substr(nameTok.span.begin, nameTok.span.end - nameTok.span.begin));
          fail(peek().kind == Tok::End ? open.span : peek().span,
               fn + "() takes " + std::to_string(arity) + " arguments",
               "write " + fn + "(a, b)");
          return kNoNode;
        }
        next();
      }
      args[k] = sum();
      if (!ok()) return kNoNode;
    }
    if (peek().kind != Tok::RParen) {
      const std::string fn(text_.substr(nameTok.span.begin, nameTok.span.end - nameTok.span.begin));
      if (peek().kind == Tok::Comma) {
        fail(peek().span, fn + "() takes " + std::to_string(arity) + " argument" +
                              (arity == 1 ? "" : "s"), "remove the extra arguments");
      } else if (peek().kind == Tok::End) {
        fail(open.span, "this '(' is never closed", "add ')'");
      } else {
        unexpected("')'");
      }
      return kNoNode;
    }
    next();
    return arity == 1 ? g_->unary(op, args[0]) : g_->binary(op, args[0], args[1]);
  }

  std::string_view text_;
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  Graph* g_ = nullptr;
  std::optional<ParseError> error_;
};

}  // namespace

ParseResult parseFormula(std::string_view text) {
  if (text.size() > kMaxFormulaBytes) {
    return ParseError{{kMaxFormulaBytes, text.size()},
                      "the formula is longer than " + std::to_string(kMaxFormulaBytes) + " bytes",
                      "shorten it, or use parameters for repeated parts"};
  }
  std::vector<Token> tokens = tokenize(text);
  // Lexical errors come first so they are reported even inside otherwise broken syntax.
  for (const Token& t : tokens) {
    if (t.kind == Tok::Error) return ParseError{t.span, t.message, t.hint};
  }
  return Parser(text, std::move(tokens)).run();
}

}  // namespace zs
