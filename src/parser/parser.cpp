#include "parser/parser.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "i18n/translate.hpp"
#include "parser/lexer.hpp"
#include "parser/suggest.hpp"

namespace zs {

namespace {

// What the grammar builds, two ways: the expression graph (folded and shared, for every
// stage that computes) or the syntax tree (as written, for typesetting).
struct GraphBuilder {
  using Id = NodeId;
  Graph* g;
  Id number(double v, std::string_view) { return g->constant(v); }
  Id variable(int axis) { return g->var(axis); }
  Id namedConstant(std::string_view, double v) { return g->constant(v); }
  Id param(std::string_view name) { return g->param(name); }
  Id unary(Op op, Id a) { return g->unary(op, a); }
  Id binary(Op op, Id a, Id b, bool /*implicit*/ = false) { return g->binary(op, a, b); }
  Id equation(Id lhs, Id rhs) { return g->binary(Op::Sub, lhs, rhs); }
  // The exponent's value where it is a constant (folded), for the exponent limit.
  std::optional<double> constantValue(Id id) const {
    const Node& n = (*g)[id];
    return n.op == Op::Const ? std::optional<double>(n.value) : std::nullopt;
  }
};

struct SyntaxBuilder {
  using Id = int;
  SyntaxTree* t;
  Id add(SyntaxNode n) {
    t->nodes.push_back(std::move(n));
    return int(t->nodes.size()) - 1;
  }
  Id number(double, std::string_view text) {
    return add({SyntaxNode::Kind::Number, Op::Const, std::string(text)});
  }
  Id variable(int axis) {
    return add(
        {SyntaxNode::Kind::Variable, Op(int(Op::VarX) + axis), std::string(1, char('x' + axis))});
  }
  Id namedConstant(std::string_view name, double) {
    return add({SyntaxNode::Kind::Constant, Op::Const, std::string(name)});
  }
  Id param(std::string_view name) {
    return add({SyntaxNode::Kind::Param, Op::Param, std::string(name)});
  }
  Id unary(Op op, Id a) { return add({SyntaxNode::Kind::Operation, op, "", a}); }
  Id binary(Op op, Id a, Id b, bool implicit = false) {
    return add({SyntaxNode::Kind::Operation, op, "", a, b, implicit});
  }
  Id equation(Id lhs, Id rhs) { return add({SyntaxNode::Kind::Equation, Op::Sub, "", lhs, rhs}); }
  // parseSyntax reads only text parseFormula accepted: the limit is checked there.
  std::optional<double> constantValue(Id) const { return std::nullopt; }
};

// Recursive descent with an explicit depth budget: every level of nesting (group, call,
// unary sign, exponent) costs one unit, so hostile input ends in an error, never in a stack
// overflow. Grammar (docs/formula.md):
//   formula := sum ['=' sum]
//   sum     := product (('+'|'-') product)*
//   product := unary (('*'|'/') unary | <implicit> power)*
//   unary   := ('-'|'+') unary | power
//   power   := atom ['^' unary]          right-associative through unary
//   atom    := number | name | name '(' args ')' | '(' sum ')' | '[' sum ']'
template <class Builder>
class Parser {
  using NodeId = typename Builder::Id;
  static constexpr NodeId kNoNode = -1;

 public:
  Parser(std::string_view text, std::vector<Token> tokens, Builder builder)
      : text_(text), toks_(std::move(tokens)), b_(builder) {}

  // The root, or the error.
  std::variant<NodeId, ParseError> run() {
    NodeId lhs = sum();
    if (ok() && peek().kind == Tok::Equals) {
      const Span eq = next().span;
      if (peek().kind == Tok::End) {
        fail(eq, i18n::tr("expected an expression after '='"),
             i18n::tr("write F = G, e.g. x^2 + y^2 = 1"));
      }
      NodeId rhs = ok() ? sum() : kNoNode;
      if (ok()) lhs = b_.equation(lhs, rhs);
      if (ok() && peek().kind == Tok::Equals) {
        fail(peek().span, i18n::tr("a formula has at most one '='"),
             i18n::tr("write F = G, meaning F - G = 0"));
      }
    }
    if (ok() && peek().kind != Tok::End) unexpected(N_("an operator or the end of the formula"));
    if (!ok()) return *error_;
    return lhs;
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
  // `expected` is English, marked N_ where it is written; it is translated here.
  void unexpected(const char* expected) {
    const Token& t = peek();
    if (t.kind == Tok::Error) return fail(t.span, t.message, t.hint);
    fail(t.span,
         i18n::format(i18n::tr("expected %s, found %s"), i18n::tr(expected),
                      i18n::tr(describe(t.kind))),
         t.kind == Tok::Caret ? i18n::tr("'^' needs a base and an exponent, e.g. x^2") : "");
  }

  struct DepthGuard {
    Parser& p;
    explicit DepthGuard(Parser& parser, Span span) : p(parser) {
      if (++p.depth_ > kMaxNesting) {
        p.fail(span,
               i18n::format(i18n::tr("the formula is nested too deeply (more than %d levels)"),
                            int(kMaxNesting)),
               i18n::tr("simplify the expression or split it"));
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
      acc = b_.binary(op, acc, rhs);
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
        acc = b_.binary(k == Tok::Star ? Op::Mul : Op::Div, acc, rhs);
      } else if (startsAtom(k)) {
        // Implicit multiplication: 2x, 3(x+1), (x+1)(x-1), 2 pi, x y.
        if (k == Tok::Number && toks_[pos_ - 1].kind == Tok::Number) {
          fail(peek().span, i18n::tr("two numbers in a row"),
               i18n::tr("write an operator between them, e.g. 2*3, or remove the space"));
          return kNoNode;
        }
        const NodeId rhs = power();
        if (!ok()) return kNoNode;
        acc = b_.binary(Op::Mul, acc, rhs, /*implicit=*/true);
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
      return k == Tok::Minus ? b_.unary(Op::Neg, a) : a;
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
    const std::optional<double> e = b_.constantValue(exponent);
    if (e && std::nearbyint(*e) == *e && std::fabs(*e) > kMaxIntegerExponent) {
      fail({expBegin, toks_[pos_ - 1].span.end},
           i18n::format(i18n::tr("integer exponent %s is too large"),
                        text(expBegin, toks_[pos_ - 1].span.end).c_str()),
           i18n::format(i18n::tr("exponents are limited to %d in magnitude; use exp(n*log(x)) "
                                 "for x > 0"),
                        int(kMaxIntegerExponent)));
      return kNoNode;
    }
    return b_.binary(Op::Pow, base, exponent);
  }

  NodeId group(Tok close, const char* closeText) {
    const Token open = next();
    DepthGuard guard(*this, open.span);
    if (!ok()) return kNoNode;
    const NodeId inner = sum();
    if (!ok()) return kNoNode;
    if (peek().kind != close) {
      if (peek().kind == Tok::End) {
        fail(open.span,
             i18n::format(i18n::tr("this '%s' is never closed"),
                          std::string(text_.substr(open.span.begin, 1)).c_str()),
             i18n::format(i18n::tr("add %s"), closeText));
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
      case Tok::Number:
        next();
        return b_.number(t.number, text_.substr(t.span.begin, t.span.end - t.span.begin));
      case Tok::LParen:
        return group(Tok::RParen, "')'");
      case Tok::LBracket:
        return group(Tok::RBracket, "']'");
      case Tok::Ident:
        return name();
      case Tok::End:
        if (pos_ == 0) {
          fail(t.span, i18n::tr("the formula is empty"),
               i18n::tr("type an expression such as x^2 + y^2 + z^2 - 1"));
        } else {
          const Token& prev = toks_[pos_ - 1];
          fail(
              prev.span,
              i18n::format(i18n::tr("expected an operand after %s"), i18n::tr(describe(prev.kind))),
              i18n::tr("complete the expression"));
        }
        return kNoNode;
      case Tok::Caret:
      case Tok::Star:
      case Tok::Slash:
      case Tok::Equals:
        if (pos_ > 0 && (toks_[pos_ - 1].kind == Tok::Caret || toks_[pos_ - 1].kind == Tok::Star ||
                         toks_[pos_ - 1].kind == Tok::Slash)) {
          fail(t.span,
               i18n::format(i18n::tr("expected an operand after %s, found %s"),
                            i18n::tr(describe(toks_[pos_ - 1].kind)), i18n::tr(describe(t.kind))),
               i18n::tr("remove the extra operator"));
          return kNoNode;
        }
        unexpected(N_("an operand"));
        return kNoNode;
      default:
        unexpected(N_("an operand (a number, x, y, z, a name or '(')"));
        return kNoNode;
    }
  }

  NodeId name() {
    const Token t = next();
    const std::string_view id = text_.substr(t.span.begin, t.span.end - t.span.begin);
    const bool call = peek().kind == Tok::LParen;
    if (id == "x" || id == "y" || id == "z") return b_.variable(id[0] - 'x');
    if (id == "pi") return b_.namedConstant(id, std::numbers::pi);
    if (id == "e") return b_.namedConstant(id, std::numbers::e);
    if (auto op = functionByName(id)) {
      if (!call) {
        fail(t.span,
             i18n::format(i18n::tr("function '%s' needs its argument in parentheses"),
                          std::string(id).c_str()),
             i18n::format(i18n::tr("write %s(x)"), std::string(id).c_str()));
        return kNoNode;
      }
      return callArgs(*op, t);
    }
    if (auto problem = diagnoseName(id, call)) {
      fail(t.span, problem->message, problem->hint);
      return kNoNode;
    }
    return b_.param(id);  // any other name is a parameter (docs/formula.md)
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
          const std::string fn(
              text_.substr(nameTok.span.begin, nameTok.span.end - nameTok.span.begin));
          fail(peek().kind == Tok::End ? open.span : peek().span,
               i18n::format(i18n::tr("%s() takes %d arguments"), fn.c_str(), int(arity)),
               i18n::format(i18n::tr("write %s(a, b)"), fn.c_str()));
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
        fail(peek().span,
             arity == 1 ? i18n::format(i18n::tr("%s() takes 1 argument"), fn.c_str())
                        : i18n::format(i18n::tr("%s() takes %d arguments"), fn.c_str(), int(arity)),
             i18n::tr("remove the extra arguments"));
      } else if (peek().kind == Tok::End) {
        fail(open.span, i18n::format(i18n::tr("this '%s' is never closed"), "("),
             i18n::format(i18n::tr("add %s"), "')'"));
      } else {
        unexpected("')'");  // not words: the same in every language
      }
      return kNoNode;
    }
    next();
    return arity == 1 ? b_.unary(op, args[0]) : b_.binary(op, args[0], args[1]);
  }

  std::string_view text_;
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  Builder b_;
  std::optional<ParseError> error_;
};

}  // namespace

ParseResult parseFormula(std::string_view text) {
  if (text.size() > kMaxFormulaBytes) {
    return ParseError{{kMaxFormulaBytes, text.size()},
                      i18n::format(i18n::tr("the formula is longer than %zu bytes"),
                                   std::size_t(kMaxFormulaBytes)),
                      i18n::tr("shorten it, or use parameters for repeated parts")};
  }
  std::vector<Token> tokens = tokenize(text);
  // Lexical errors come first so they are reported even inside otherwise broken syntax.
  for (const Token& t : tokens) {
    if (t.kind == Tok::Error) return ParseError{t.span, t.message, t.hint};
  }
  Formula f;
  auto root = Parser<GraphBuilder>(text, std::move(tokens), GraphBuilder{&f.graph}).run();
  if (auto* error = std::get_if<ParseError>(&root)) return *error;
  f.root = std::get<NodeId>(root);
  return f;
}

std::variant<SyntaxTree, ParseError> parseSyntax(std::string_view text) {
  ParseResult checked = parseFormula(text);
  if (auto* error = std::get_if<ParseError>(&checked)) return *error;
  SyntaxTree tree;
  auto root = Parser<SyntaxBuilder>(text, tokenize(text), SyntaxBuilder{&tree}).run();
  if (auto* error = std::get_if<ParseError>(&root)) return *error;
  tree.root = std::get<int>(root);
  return tree;
}

}  // namespace zs
