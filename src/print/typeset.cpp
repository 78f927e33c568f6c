#include "print/typeset.hpp"

#include <algorithm>
#include <cmath>

namespace zs::printing {

void MathBox::place(const MathBox& other, double dx, double dy) {
  for (TextRun r : other.runs) {
    r.x += dx;
    r.y += dy;
    runs.push_back(std::move(r));
  }
  for (Stroke s : other.strokes) {
    for (auto& [x, y] : s.points) x += dx, y += dy;
    strokes.push_back(std::move(s));
  }
  width = std::max(width, dx + other.width);
  ascent = std::max(ascent, other.ascent - dy);
  descent = std::max(descent, other.descent + dy);
}

void MathBox::scale(double k) {
  for (TextRun& r : runs) r.size *= k, r.x *= k, r.y *= k;
  for (Stroke& s : strokes) {
    for (auto& [x, y] : s.points) x *= k, y *= k;
    s.width *= k;
  }
  width *= k, ascent *= k, descent *= k;
}

namespace {

// Binding strength, as the parser's grammar: what a slot needs and what a box offers.
enum Prec { kSum = 1, kProduct = 2, kUnary = 3, kPower = 4, kAtom = 5 };

// Proportions of the font size (a serif font's x-height and axis).
constexpr double kAscent = 0.72, kDescent = 0.22, kAxis = 0.26;
constexpr double kScriptScale = 0.7, kFractionScale = 0.9, kMinSize = 5.0;

struct Typeset {
  MathBox box;
  int prec = kAtom;
  bool fraction = false;  // a fraction needs parentheses as the base of a power
  bool startsWithDigit = false, endsWithDigit = false;  // for 2·3 against 2x
};

class Setter {
 public:
  Setter(const SyntaxTree& tree, const MeasureText& measure) : tree_(tree), measure_(measure) {}

  MathBox equation(double size) {
    MathBox out;
    for (const MathBox& piece : pieces(size)) append(out, piece);
    return out;
  }

  std::vector<MathBox> lines(double size, double width) {
    std::vector<MathBox> out(1);
    for (const MathBox& piece : pieces(size)) {
      if (out.back().width > 0 && out.back().width + piece.width > width) out.emplace_back();
      append(out.back(), piece);
    }
    return out;
  }

 private:
  // The equation in the pieces a line may break between: the terms of each side's
  // outermost sum, each after the first with its sign, then "= G" or "= 0".
  std::vector<MathBox> pieces(double size) {
    const SyntaxNode& root = tree_.nodes[std::size_t(tree_.root)];
    const bool equation = root.kind == SyntaxNode::Kind::Equation;
    std::vector<MathBox> out;
    terms(equation ? root.a : tree_.root, size, out);
    if (equation) {
      std::vector<MathBox> right;
      terms(root.b, size, right);
      right.front() = joined(text(" = ", false, size), right.front());
      out.insert(out.end(), right.begin(), right.end());
    } else {
      out.push_back(text(" = 0", false, size));
    }
    return out;
  }

  void terms(int id, double size, std::vector<MathBox>& out) {
    const std::vector<Link> links = chain(id, /*sums=*/true);
    out.push_back(slot(links.front().operand, kSum, size).box);
    for (std::size_t i = 1; i < links.size(); ++i) {
      out.push_back(joined(text(links[i].op == Op::Add ? " + " : " \u2212 ", false, size),
                           slot(links[i].operand, rightNeed(links[i]), size).box));
    }
  }

  // A left-deep chain of sums (or of products) as written: its operands leftmost first,
  // each after the first with the operation before it. Without recursion: a formula may
  // have thousands of terms, which the parser's nesting budget does not count.
  struct Link {
    Op op;
    int operand;
  };
  std::vector<Link> chain(int id, bool sums) const {
    auto inChain = [&](int k) {
      const SyntaxNode& m = tree_.nodes[std::size_t(k)];
      return m.kind == SyntaxNode::Kind::Operation &&
             (sums ? m.op == Op::Add || m.op == Op::Sub : m.op == Op::Mul);
    };
    std::vector<Link> links;
    int at = id;
    while (inChain(at)) {
      const SyntaxNode& m = tree_.nodes[std::size_t(at)];
      links.push_back({m.op, m.b});
      at = m.a;
    }
    links.push_back({Op::Const, at});
    std::reverse(links.begin(), links.end());
    return links;
  }

  MathBox joined(MathBox a, const MathBox& b) {
    append(a, b);
    return a;
  }

  // a − (b + c), and a written x + -y shows as x + (−y).
  int rightNeed(const Link& link) const {
    return isNeg(link.operand) ? kPower : link.op == Op::Sub ? kProduct : kSum;
  }

  MathBox text(const std::string& s, bool italic, double size) const {
    MathBox b;
    b.runs.push_back({s, italic, size, 0, 0});
    b.width = measure_(s, italic, size);
    b.ascent = kAscent * size;
    b.descent = kDescent * size;
    return b;
  }

  static void append(MathBox& to, const MathBox& b) { to.place(b, to.width, 0); }

  // Parentheses drawn to the height of what they hold.
  MathBox parenthesized(const MathBox& inner, double size) const {
    const double top = std::max(inner.ascent, kAscent * size) + 0.06 * size;
    const double bottom = std::max(inner.descent, kDescent * size) + 0.06 * size;
    const double height = top + bottom;
    const double bulge = 0.1 * size * std::pow(height / size, 0.4);
    const double w = bulge + 0.2 * size;
    auto arc = [&](double x0, double sign) {
      Stroke s;
      s.width = 0.06 * size;
      for (int i = 0; i <= 12; ++i) {
        const double t = i / 12.0, y = -top + t * height;
        s.points.push_back({x0 + sign * bulge * (1 - std::pow(2 * t - 1, 2)), y});
      }
      return s;
    };
    MathBox out;
    out.width = w;
    out.ascent = top;
    out.descent = bottom;
    out.strokes.push_back(arc(w - 0.08 * size, -1));
    out.place(inner, w, 0);
    const double right = out.width;
    out.strokes.push_back(arc(right + 0.08 * size, 1));
    out.width = right + w;
    return out;
  }

  Typeset slot(int id, int need, double size) {
    Typeset t = node(id, size);
    if (t.prec < need) {
      t.box = parenthesized(t.box, size);
      t.prec = kAtom;
      t.fraction = false;
      t.startsWithDigit = t.endsWithDigit = false;
    }
    return t;
  }

  Typeset number(const std::string& written, double size) {
    Typeset t;
    t.startsWithDigit = t.endsWithDigit = true;
    // 1.5e-30 as 1.5·10⁻³⁰.
    const std::size_t e = written.find_first_of("eE");
    if (e == std::string::npos) {
      t.box = text(written, false, size);
      return t;
    }
    std::string exponent = written.substr(e + 1);
    if (!exponent.empty() && exponent[0] == '+') exponent.erase(0, 1);
    if (!exponent.empty() && exponent[0] == '-') exponent.replace(0, 1, "\u2212");
    t.box = text(written.substr(0, e) + "\u00b710", false, size);
    const double small = std::max(kMinSize, size * kScriptScale);
    t.box.place(text(exponent, false, small), t.box.width, -0.42 * size);
    t.prec = kProduct;
    return t;
  }

  Typeset node(int id, double size) {
    const SyntaxNode& n = tree_.nodes[std::size_t(id)];
    Typeset t;
    switch (n.kind) {
      case SyntaxNode::Kind::Number:
        return number(n.text, size);
      case SyntaxNode::Kind::Variable:
      case SyntaxNode::Kind::Param:
        t.box = text(n.text, true, size);
        return t;
      case SyntaxNode::Kind::Constant:
        t.box = n.text == "pi" ? text("\u03c0", false, size) : text(n.text, true, size);
        return t;
      case SyntaxNode::Kind::Equation: {
        append(t.box, node(n.a, size).box);
        append(t.box, text(" = ", false, size));
        append(t.box, node(n.b, size).box);
        t.prec = 0;
        return t;
      }
      case SyntaxNode::Kind::Operation:
        return operation(n, size);
    }
    return t;
  }

  Typeset operation(const SyntaxNode& n, double size) {
    Typeset t;
    switch (n.op) {
      case Op::Neg: {
        t.box = text("\u2212", false, size);
        append(t.box, slot(n.a, kPower, size).box);
        t.prec = kUnary;
        return t;
      }
      case Op::Add:
      case Op::Sub: {
        std::vector<MathBox> pieces;
        terms(int(&n - tree_.nodes.data()), size, pieces);
        for (const MathBox& piece : pieces) append(t.box, piece);
        t.prec = kSum;
        return t;
      }
      case Op::Mul: {
        const std::vector<Link> links = chain(int(&n - tree_.nodes.data()), /*sums=*/false);
        const Typeset first = slot(links.front().operand, kProduct, size);
        t.box = first.box;
        t.startsWithDigit = first.startsWithDigit;
        t.endsWithDigit = first.endsWithDigit;
        for (std::size_t i = 1; i < links.size(); ++i) {
          const Typeset b = slot(links[i].operand, kPower, size);
          // Before a number a dot (2·3, x·2); elsewhere a thin space (2x, x y, 2 sin x).
          if (b.startsWithDigit)
            append(t.box, text("\u00b7", false, size));
          else
            t.box.width += 0.12 * size;
          append(t.box, b.box);
          t.endsWithDigit = b.endsWithDigit;
        }
        t.prec = kProduct;
        return t;
      }
      case Op::Div:
        return fraction(n, size);
      case Op::Pow: {
        Typeset base = slot(n.a, kAtom, size);
        if (base.fraction) base = {parenthesized(base.box, size), kAtom};
        const double small = std::max(kMinSize, size * kScriptScale);
        const MathBox exponent = node(n.b, small).box;
        const double raise = std::max(0.42 * size, base.box.ascent - 0.45 * exponent.ascent);
        t.box = base.box;
        t.box.place(exponent, t.box.width + 0.03 * size, -raise);
        t.prec = kPower;
        t.startsWithDigit = base.startsWithDigit;
        return t;
      }
      case Op::Sqrt:
      case Op::Cbrt:
        return radical(n, size);
      case Op::Abs: {
        const MathBox inner = node(n.a, size).box;
        const double top = std::max(inner.ascent, kAscent * size) + 0.05 * size;
        const double bottom = std::max(inner.descent, kDescent * size) + 0.05 * size;
        const double gap = 0.12 * size;
        t.box.ascent = top;
        t.box.descent = bottom;
        t.box.strokes.push_back({{{gap / 2, -top}, {gap / 2, bottom}}, 0.06 * size});
        t.box.place(inner, gap, 0);
        const double right = t.box.width + gap / 2;
        t.box.strokes.push_back({{{right, -top}, {right, bottom}}, 0.06 * size});
        t.box.width = right + gap / 2;
        return t;
      }
      default:
        return call(n, size);
    }
  }

  bool isNeg(int id) const {
    const SyntaxNode& n = tree_.nodes[std::size_t(id)];
    return n.kind == SyntaxNode::Kind::Operation && n.op == Op::Neg;
  }

  Typeset fraction(const SyntaxNode& n, double size) {
    const double inner = std::max(kMinSize, size * kFractionScale);
    const MathBox num = node(n.a, inner).box, den = node(n.b, inner).box;
    const double pad = 0.12 * size, gap = 0.14 * size, axis = kAxis * size;
    const double width = std::max(num.width, den.width) + 2 * pad;
    Typeset t;
    t.box.width = width;
    t.box.place(num, (width - num.width) / 2, -(axis + gap + num.descent));
    t.box.place(den, (width - den.width) / 2, -axis + gap + den.ascent);
    t.box.strokes.push_back({{{0.03 * size, -axis}, {width - 0.03 * size, -axis}}, 0.05 * size});
    t.box.width = width + 0.05 * size;
    t.fraction = true;
    return t;
  }

  Typeset radical(const SyntaxNode& n, double size) {
    const MathBox inner = node(n.a, size).box;
    const double top = std::max(inner.ascent, kAscent * size) + 0.14 * size;
    const double bottom = std::max(inner.descent, kDescent * size) + 0.04 * size;
    const double sign = 0.55 * size, line = 0.05 * size;
    Typeset t;
    Stroke s;
    s.width = line;
    s.points = {{0.02 * size, -0.32 * size},
                {0.14 * size, -0.4 * size},
                {0.3 * size, bottom},
                {sign, -top},
                {sign + inner.width + 0.12 * size, -top}};
    t.box.strokes.push_back(s);
    t.box.ascent = top + line;
    t.box.descent = bottom;
    if (n.op == Op::Cbrt) {
      const double small = std::max(kMinSize, size * 0.5);
      t.box.place(text("3", false, small), 0.0, -0.5 * size);
    }
    t.box.place(inner, sign + 0.06 * size, 0);
    t.box.width = sign + inner.width + 0.18 * size;
    return t;
  }

  Typeset call(const SyntaxNode& n, double size) {
    const OpInfo& info = opInfo(n.op);
    Typeset t;
    t.box = text(std::string(info.spelling), false, size);
    MathBox args = node(n.a, size).box;
    if (n.b >= 0) {
      append(args, text(", ", false, size));
      append(args, node(n.b, size).box);
    }
    append(t.box, parenthesized(args, size));
    return t;
  }

  const SyntaxTree& tree_;
  const MeasureText& measure_;
};

}  // namespace

MathBox typesetEquation(const SyntaxTree& tree, double size, const MeasureText& measure) {
  return Setter(tree, measure).equation(size);
}

std::vector<MathBox> typesetEquationLines(const SyntaxTree& tree, double size,
                                          const MeasureText& measure, double width) {
  return Setter(tree, measure).lines(size, width);
}

}  // namespace zs::printing
