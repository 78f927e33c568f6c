// The formula typesetting of the printed page (src/print/typeset.hpp), with a measure of
// fixed widths (0.5 of the size per character), so the layout is checked without a font.
#include "print/typeset.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

namespace zs::printing {
namespace {

double fixedWidth(const std::string& text, bool, double size) {
  std::size_t chars = 0;
  for (char c : text) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // code points
  return 0.5 * size * double(chars);
}

MathBox set(const std::string& formula, double width = 1e9) {
  auto tree = parseSyntax(formula);
  EXPECT_TRUE(std::holds_alternative<SyntaxTree>(tree)) << formula;
  const std::vector<MathBox> lines =
      typesetEquationLines(std::get<SyntaxTree>(tree), 20, fixedWidth, width);
  EXPECT_EQ(lines.size(), 1u) << formula;
  return lines.front();
}

const TextRun* run(const MathBox& box, const std::string& text) {
  for (const TextRun& r : box.runs) {
    if (r.text == text) return &r;
  }
  return nullptr;
}

std::string allText(const MathBox& box) {
  std::string s;
  for (const TextRun& r : box.runs) s += r.text;
  return s;
}

TEST(Typeset, PowersAreRaisedSmallerExponents) {
  const MathBox box = set("x^2 + y^2 + z^2 - 1");
  const TextRun* x = run(box, "x");
  const TextRun* two = run(box, "2");
  ASSERT_TRUE(x && two);
  EXPECT_LT(two->y, x->y - 5);    // raised above the baseline
  EXPECT_LT(two->size, x->size);  // smaller
  EXPECT_TRUE(x->italic);         // variables in italic, numbers upright
  EXPECT_FALSE(two->italic);
  EXPECT_NE(allText(box).find("\u2212"), std::string::npos) << "a real minus sign";
  EXPECT_EQ(box.strokes.size(), 0u) << "no parentheses, bars or radicals";
}

TEST(Typeset, QuotientsAreFractionsWithTheNumeratorAbove) {
  const MathBox box = set("(x + 1)/(y - 2)");
  const TextRun* x = run(box, "x");
  const TextRun* y = run(box, "y");
  ASSERT_TRUE(x && y);
  EXPECT_LT(x->y, 0);  // the numerator above the baseline, the denominator below
  EXPECT_GT(y->y, 0);
  ASSERT_EQ(box.strokes.size(), 1u) << "the bar, and no parentheses around either part";
  const Stroke& bar = box.strokes.front();
  EXPECT_EQ(bar.points.front().second, bar.points.back().second);  // horizontal
}

TEST(Typeset, ParenthesesOnlyWherePrecedenceNeedsThem) {
  EXPECT_EQ(set("x + y*z").strokes.size(), 0u);
  EXPECT_EQ(set("(x + y)*z").strokes.size(), 2u);
  EXPECT_EQ(set("x - (y*z)").strokes.size(), 0u);
  EXPECT_EQ(set("x - (y + z)").strokes.size(), 2u);
  EXPECT_EQ(set("(x + y)^2").strokes.size(), 2u);
  EXPECT_EQ(set("-x^2").strokes.size(), 0u);  // −x², the square of x negated
  EXPECT_EQ(set("(-x)^2").strokes.size(), 2u);
  EXPECT_EQ(set("x*(-y)").strokes.size(), 2u);
  EXPECT_EQ(set("sin(x)").strokes.size(), 2u);  // a function's parentheses
}

TEST(Typeset, RootsAbsoluteValuesAndNamedConstants) {
  EXPECT_EQ(set("sqrt(x)").strokes.size(), 1u);  // the radical sign with its bar
  EXPECT_NE(run(set("cbrt(x)"), "3"), nullptr);  // the cube root's index
  EXPECT_EQ(set("abs(x)").strokes.size(), 2u);   // two bars
  EXPECT_NE(run(set("2 pi x"), "\u03c0"), nullptr);
  // 2·3 with a dot; 2x side by side.
  EXPECT_NE(run(set("2*3*x"), "\u00b7"), nullptr);
  EXPECT_EQ(run(set("2x"), "\u00b7"), nullptr);
  // A number in exponent notation as a power of ten.
  const MathBox small = set("x - 1.5e-3");
  EXPECT_NE(run(small, "1.5\u00b710"), nullptr);
  EXPECT_NE(run(small, "\u22123"), nullptr);
}

TEST(Typeset, AnEquationKeepsItsTwoSides) {
  const std::string text = allText(set("x^2 + y^2 = z^2"));
  EXPECT_NE(text.find(" = "), std::string::npos);
  EXPECT_EQ(text.find(" = 0"), std::string::npos);
  EXPECT_NE(allText(set("x")).find(" = 0"), std::string::npos);
}

TEST(Typeset, LongFormulasBreakBetweenTermsOfTheOutermostSum) {
  auto tree = std::get<SyntaxTree>(parseSyntax("x^4 + y^4 + z^4 - 2*x*y - 3*y*z + 4*z*x - 1"));
  const MathBox whole = typesetEquation(tree, 20, fixedWidth);
  const std::vector<MathBox> lines = typesetEquationLines(tree, 20, fixedWidth, whole.width / 3);
  ASSERT_GE(lines.size(), 3u);
  double sum = 0;
  for (const MathBox& line : lines) {
    EXPECT_LE(line.width, whole.width / 3 + 1e-9);
    sum += line.width;
  }
  EXPECT_NEAR(sum, whole.width, 1e-9);  // the same pieces, only cut
  // A continuation line starts with its sign.
  EXPECT_TRUE(lines[1].runs.front().text.find('+') != std::string::npos ||
              lines[1].runs.front().text.find("\u2212") != std::string::npos);
}

}  // namespace
}  // namespace zs::printing

namespace zs::printing {
namespace {

// Sums and products of many terms are chains the parser's nesting budget does not count:
// typesetting them must not recurse once per term (the parser fuzzer found a stack overflow
// at some 1500 factors).
TEST(Typeset, LongSumsAndProductsDoNotRecursePerTerm) {
  std::string product = "x", sum = "x";
  for (int i = 0; i < 100000; ++i) {
    product += "*y";
    sum += i % 2 ? " + y" : " - 2x";
  }
  for (const std::string& formula : {product, sum}) {
    auto tree = parseSyntax(formula);
    ASSERT_TRUE(std::holds_alternative<SyntaxTree>(tree));
    const std::vector<MathBox> lines =
        typesetEquationLines(std::get<SyntaxTree>(tree), 20, fixedWidth, 500);
    EXPECT_FALSE(lines.empty());
  }
}

}  // namespace
}  // namespace zs::printing
