// Hostile and degenerate input: limits, error formatting, byte-level oddities.
#include <gtest/gtest.h>

#include <string>

#include "parser/parser.hpp"

namespace zs {
namespace {

ParseError errorOf(const ParseResult& r) {
  EXPECT_TRUE(std::holds_alternative<ParseError>(r));
  return std::holds_alternative<ParseError>(r) ? std::get<ParseError>(r) : ParseError{};
}

TEST(ParserLimits, OneMegabyteOfOpenParenthesesIsAnErrorNotACrash) {
  const std::string text(kMaxFormulaBytes, '(');
  const ParseError e = errorOf(parseFormula(text));
  EXPECT_NE(e.message.find("nested too deeply"), std::string::npos);
  EXPECT_EQ(e.span.begin, std::size_t(kMaxNesting));  // the first '(' past the limit
}

TEST(ParserLimits, HundredThousandBalancedParentheses) {
  const std::string text = std::string(100000, '(') + "x" + std::string(100000, ')');
  EXPECT_NE(errorOf(parseFormula(text)).message.find("nested too deeply"), std::string::npos);
}

TEST(ParserLimits, DeepUnaryMinusAndExponentChains) {
  EXPECT_NE(errorOf(parseFormula(std::string(100000, '-') + "x")).message.find("nested"),
            std::string::npos);
  std::string chain = "x";
  for (int i = 0; i < 50000; ++i) chain += "^x";
  EXPECT_NE(errorOf(parseFormula(chain)).message.find("nested"), std::string::npos);
}

TEST(ParserLimits, NestingJustBelowTheLimitParses) {
  const int depth = kMaxNesting - 1;
  const std::string text = std::string(depth, '(') + "x" + std::string(depth, ')');
  EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula(text)));
}

TEST(ParserLimits, TooLongFormula) {
  std::string text = "x";
  while (text.size() <= kMaxFormulaBytes) text += "+x";
  const ParseError e = errorOf(parseFormula(text));
  EXPECT_EQ(e.span.begin, kMaxFormulaBytes);
  EXPECT_NE(e.message.find("longer than"), std::string::npos);
}

TEST(ParserLimits, LongFlatSumParses) {
  std::string text = "x";
  for (int i = 0; i < 100000; ++i) text += "+y*" + std::to_string(i);
  EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula(text)));
}

TEST(ParserLimits, ExponentLimit) {
  EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula("x^1024")));
  EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula("x^-1024")));
  EXPECT_EQ(errorOf(parseFormula("x^1025")).span.begin, 2u);
  EXPECT_TRUE(std::holds_alternative<Formula>(parseFormula("x^1025.5")));  // real power: pow
  // Exponents far beyond any integer type are reported, not converted (found by fuzzing).
  EXPECT_EQ(errorOf(parseFormula("x^-2288230376151711744")).span.begin, 2u);
  EXPECT_NE(errorOf(parseFormula("x^3^3^4")).message.find("3^3^4"), std::string::npos);
  EXPECT_EQ(errorOf(parseFormula("x^1e300")).span.end, 7u);
}

TEST(ParserErrors, CaretSitsUnderTheSpan) {
  const std::string text = "x^2 + sinn(y)";
  const std::string out = formatError(text, errorOf(parseFormula(text)));
  EXPECT_EQ(out,
            "  x^2 + sinn(y)\n"
            "        ^^^^\n"
            "error: unknown function 'sinn' \u2014 did you mean sin? (at column 7)\n"
            "hint: the functions are listed in docs/formula.md\n");
}

TEST(ParserErrors, CaretCountsCharactersNotBytes) {
  const std::string text = "\u00e9 + x +";  // é is two bytes, one column
  const std::string out = formatError(text, errorOf(parseFormula(text)));
  EXPECT_EQ(out.substr(0, out.find("error")), "  \u00e9 + x +\n  ^\n");
}

TEST(ParserErrors, ControlBytesAreShownAsQuestionMarks) {
  const std::string text("x +\0", 4);
  const std::string out = formatError(text, errorOf(parseFormula(text)));
  EXPECT_EQ(out.substr(0, out.find("error")), "  x +?\n     ^\n");
}

TEST(ParserErrors, LongFormulasShowAWindowAroundTheError) {
  std::string text(300, '+');
  text = "x" + std::string(200, ' ') + "+ y +";
  const ParseError e = errorOf(parseFormula(text));
  const std::string out = formatError(text, e);
  const std::string firstLine = out.substr(0, out.find('\n'));
  EXPECT_LE(firstLine.size(), 2 + 3 + 72 + 3u);
  EXPECT_NE(out.find("(at column " + std::to_string(e.span.begin + 1) + ")"), std::string::npos);
}

TEST(ParserErrors, EmptySpanAtEndStillGetsACaret) {
  ParseError e{{3, 3}, "m", ""};
  EXPECT_EQ(formatError("abc", e), "  abc\n     ^\nerror: m (at column 4)\n");
}

}  // namespace
}  // namespace zs
