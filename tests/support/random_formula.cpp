#include "support/random_formula.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "expr/opcode.hpp"

namespace zs::test {
namespace {

// Precedence levels of the grammar (parser.cpp): a piece printed at level L may stand
// wherever the grammar asks for level <= L.
enum Level { kSum = 1, kProduct = 2, kUnary = 3, kPower = 4, kAtom = 5 };
// Token classes at the two ends of a piece: they decide spacing and implicit products.
enum class Edge { Number, Name, Param, Open, Close, Sign };

struct Piece {
  std::string text;
  Level level = kAtom;
  Edge first = Edge::Number;
  Edge last = Edge::Number;
  bool constant = true;  // no x, y, z or parameter inside
};

constexpr std::array<std::string_view, 10> kParamNames = {"a", "b",     "c",    "k",      "r",
                                                          "s", "alpha", "beta", "radius", "t"};

class Generator {
 public:
  Generator(std::mt19937_64& rng, const RandomFormulaOptions& o) : rng_(rng), o_(o) {
    for (const OpInfo& info : kOpTable) {
      if (info.kind == OpKind::Call) functions_.push_back(info);
    }
  }

  std::string formula() {
    const int depth = std::clamp(o_.maxDepth, 0, kMaxRandomDepth);
    Piece lhs = expr(depth);
    if (!chance(o_.equalsProbability)) return lhs.text;
    Piece rhs = expr(depth / 2);
    return lhs.text + pickOf({" = ", "=", " =", "= "}) + rhs.text;
  }

 private:
  std::uint64_t pick(std::uint64_t n) { return rng_() % n; }
  bool chance(double p) { return double(rng_() >> 11) * 0x1.0p-53 < p; }
  std::string pickOf(std::initializer_list<const char*> options) {
    return *(options.begin() + pick(options.size()));
  }

  Piece expr(int depth) {
    if (depth <= 0 || chance(o_.leafProbability)) return leaf();
    switch (pick(10)) {
      case 0:
      case 1:
        return sum(depth);
      case 2:
      case 3:
        return product(depth);
      case 4:
        return negate(depth);
      case 5:
      case 6:
        return power(depth);
      case 7:
      case 8:
        return call(depth);
      default:
        return group(expr(depth - 1));
    }
  }

  Piece leaf() {
    const std::uint64_t k = pick(o_.paramCount > 0 ? 10 : 8);
    if (k < 3) return number();
    if (k < 6) return name(std::string(1, char('x' + k - 3)), false);
    if (k == 6) return constantName();
    if (k == 7) return number();
    const auto count = static_cast<std::uint64_t>(std::min<int>(o_.paramCount, 10));
    return name(std::string(kParamNames[pick(count)]), true);
  }

  Piece number() {
    const auto whole = std::to_string(pick(100));
    const auto frac = std::to_string(pick(1000));
    std::string t;
    switch (pick(6)) {
      case 0:
      case 1:
        t = whole;
        break;
      case 2:
        t = whole + "." + frac;
        break;
      case 3:
        t = "." + frac;
        break;
      case 4:
        t = std::to_string(1 + pick(9)) + pickOf({"e", "E"}) + pickOf({"", "-", "+"}) +
            std::to_string(pick(4));
        break;
      default:
        t = std::to_string(1 + pick(9)) + "." + frac + "e-" + std::to_string(pick(3));
    }
    return {t, kAtom, Edge::Number, Edge::Number, true};
  }
  Piece name(std::string n, bool param) {
    const Edge e = param ? Edge::Param : Edge::Name;
    return {std::move(n), kAtom, e, e, false};
  }
  Piece constantName() { return {pick(2) ? "pi" : "e", kAtom, Edge::Name, Edge::Name, true}; }

  // Parenthesizes with ( ) or, one time in four, [ ].
  Piece group(Piece p) {
    const bool square = pick(4) == 0;
    p.text = (square ? "[" : "(") + p.text + (square ? "]" : ")");
    p.level = kAtom;
    p.first = Edge::Open;
    p.last = Edge::Close;
    return p;
  }
  Piece atLeast(Piece p, Level level) { return p.level >= level ? p : group(std::move(p)); }

  std::string op(const char* symbol) {
    return chance(0.5) ? symbol : std::string(" ") + symbol + " ";
  }

  Piece sum(int depth) {
    Piece a = atLeast(expr(depth - 1), kSum);
    Piece b = atLeast(expr(depth - 1), kProduct);  // left-associative
    const std::string symbol = op(pick(2) ? "+" : "-");
    return {a.text + symbol + b.text, kSum, a.first, b.last, a.constant && b.constant};
  }

  Piece product(int depth) {
    Piece a = atLeast(expr(depth - 1), kProduct);
    if (chance(o_.implicitProbability)) return implicit(std::move(a), expr(depth - 1));
    Piece b = atLeast(expr(depth - 1), kUnary);  // "x * -y" is fine
    const std::string symbol = op(pick(3) == 0 ? "/" : "*");
    return {a.text + symbol + b.text, kProduct, a.first, b.last, a.constant && b.constant};
  }

  // Juxtaposition: the right factor is a power (no leading sign: "2 -x" is a difference).
  Piece implicit(Piece a, Piece b) {
    b = atLeast(std::move(b), kPower);
    // "2 3" is an error ("two numbers in a row"), even across "x^2 3".
    if (a.last == Edge::Number && b.first == Edge::Number) b = group(std::move(b));
    std::string joint;
    if (a.last == Edge::Param && b.first == Edge::Open) {
      joint = "*";  // "k(x)" or "k [x]" would read k as an unknown function
    } else if (a.last == Edge::Number && (b.text == "x" || b.text == "y" || b.text == "z")) {
      joint = chance(0.7) ? "" : " ";  // 2x
    } else if ((a.last == Edge::Number || a.last == Edge::Name || a.last == Edge::Param) &&
               (b.first == Edge::Name || b.first == Edge::Param || b.first == Edge::Number)) {
      joint = " ";  // x y, 2 pi, x 2.5
    } else {
      joint = chance(0.5) ? "" : " ";  // (x+1)(y-1), 3(x), x sin(y)
    }
    return {a.text + joint + b.text, kProduct, a.first, b.last, a.constant && b.constant};
  }

  Piece negate(int depth) {
    Piece a = atLeast(expr(depth - 1), kUnary);
    const std::string sign = pick(5) == 0 ? "+" : "-";
    return {sign + a.text, kUnary, Edge::Sign, a.last, a.constant};
  }

  Piece power(int depth) {
    Piece base = atLeast(expr(depth - 1), kAtom);
    Piece exponent = powerExponent(depth);
    const std::string symbol = pick(6) == 0 ? "**" : "^";
    return {base.text + symbol + exponent.text, kPower, base.first, exponent.last,
            base.constant && exponent.constant};
  }

  Piece powerExponent(int depth) {
    const int maxExp = std::max(1, o_.maxIntegerExponent);
    switch (pick(6)) {
      case 0:
      case 1:
      case 2:
        return {std::to_string(1 + pick(std::uint64_t(maxExp))), kAtom, Edge::Number, Edge::Number,
                true};
      case 3:  // negative integer: the exponent is a unary, "x^-2" is x^(-2)
        return {"-" + std::to_string(1 + pick(std::uint64_t(maxExp))), kUnary, Edge::Sign,
                Edge::Number, true};
      case 4: {  // real: 2.5 or .5 (never 9e3, which is an integer beyond the limit)
        const std::string whole = pick(2) ? std::to_string(pick(4)) : "";
        return {whole + "." + std::to_string(1 + pick(99)), kAtom, Edge::Number, Edge::Number,
                true};
      }
      default: {
        // A general exponent. A constant one could fold to an integer beyond
        // kMaxIntegerExponent, which the parser rejects, so it must contain a variable.
        Piece e = atLeast(expr(std::min(depth - 1, 2)), kUnary);
        if (e.constant) return {"(x+" + e.text + ")", kAtom, Edge::Open, Edge::Close, false};
        return e;
      }
    }
  }

  Piece call(int depth) {
    const OpInfo& fn = functions_[pick(functions_.size())];
    std::string text(fn.spelling);
    text += "(";
    bool constant = true;
    for (int i = 0; i < fn.arity; ++i) {
      Piece arg = expr(depth - 1);
      if (i > 0) text += pickOf({", ", ","});
      text += arg.text;
      constant = constant && arg.constant;
    }
    text += ")";
    return {text, kAtom, Edge::Name, Edge::Close, constant};
  }

  std::mt19937_64& rng_;
  const RandomFormulaOptions& o_;
  std::vector<OpInfo> functions_;
};

}  // namespace

std::string randomFormula(std::mt19937_64& rng, const RandomFormulaOptions& options) {
  return Generator(rng, options).formula();
}

}  // namespace zs::test
