// Float literals: every finite double in float range must come back as the float nearest to
// it when read the way glslang reads literals (strtod to double, then rounded to float);
// values outside float range are mapped as documented in codegen/glsl_literal.hpp.
#include "codegen/glsl_literal.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

namespace zs {
namespace {

float readBack(const std::string& text) {
  return static_cast<float>(std::strtod(text.c_str(), nullptr));
}

// A GLSL float literal: digits with a '.' or an exponent, no sign, no inf/nan spelling.
bool isGlslFloatLiteral(std::string text) {
  if (!text.empty() && text[0] == '-') text.erase(0, 1);
  if (text.empty() || text.find_first_not_of("0123456789.e+-") != std::string::npos) return false;
  return text.find_first_of(".e") != std::string::npos;
}

TEST(GlslLiteral, RoundTripsRandomFloatBitPatterns) {
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const float f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
    if (!std::isfinite(f) || std::fabs(f) < std::numeric_limits<float>::min()) continue;
    const GlslLiteral lit = glslFloatLiteral(f);
    ASSERT_EQ(lit.kind, LiteralKind::Nearest) << f;
    ASSERT_TRUE(isGlslFloatLiteral(lit.text)) << lit.text;
    ASSERT_EQ(readBack(lit.text), f) << lit.text;
    ++checked;
  }
  EXPECT_GT(checked, 150000);
}

TEST(GlslLiteral, DoublesBecomeTheNearestFloat) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 100000; ++i) {
    const double d = std::ldexp(double(rng() >> 11) * 0x1.0p-53 + 0.5, int(rng() % 240) - 120);
    const GlslLiteral lit = glslFloatLiteral(d);
    ASSERT_EQ(readBack(lit.text), static_cast<float>(d)) << d << " -> " << lit.text;
  }
}

TEST(GlslLiteral, ShortestSpellingForCommonConstants) {
  EXPECT_EQ(glslFloatLiteral(2.0).text, "2.0");
  EXPECT_EQ(glslFloatLiteral(0.4).text, "0.4");
  EXPECT_EQ(glslFloatLiteral(-2.5).text, "-2.5");
  EXPECT_EQ(glslFloatLiteral(1e-3).text, "0.001");
  EXPECT_EQ(glslFloatLiteral(1024.0).text, "1024.0");
}

TEST(GlslLiteral, ZeroAndNegativeZero) {
  EXPECT_EQ(glslFloatLiteral(0.0).text, "0.0");
  EXPECT_EQ(glslFloatLiteral(-0.0).text, "0.0");
}

TEST(GlslLiteral, HugeValuesClampToFloatMaxWithTheirSign) {
  const float max = std::numeric_limits<float>::max();
  for (double v : {1e39, 1e300, std::numeric_limits<double>::infinity()}) {
    const GlslLiteral pos = glslFloatLiteral(v), neg = glslFloatLiteral(-v);
    EXPECT_EQ(pos.kind, LiteralKind::ClampedHuge);
    EXPECT_EQ(neg.kind, LiteralKind::ClampedHuge);
    EXPECT_EQ(readBack(pos.text), max) << pos.text;
    EXPECT_EQ(readBack(neg.text), -max) << neg.text;
  }
  EXPECT_EQ(glslFloatLiteral(double(max)).kind, LiteralKind::Nearest);
}

TEST(GlslLiteral, TinyValuesStayNonZeroWithTheirSign) {
  const float min = std::numeric_limits<float>::min();
  for (double v : {1e-39, 1e-45, 1e-300, std::numeric_limits<double>::denorm_min()}) {
    const GlslLiteral pos = glslFloatLiteral(v), neg = glslFloatLiteral(-v);
    EXPECT_EQ(pos.kind, LiteralKind::ClampedTiny);
    EXPECT_EQ(readBack(pos.text), min) << pos.text;
    EXPECT_EQ(readBack(neg.text), -min) << neg.text;
  }
  EXPECT_EQ(glslFloatLiteral(double(min)).kind, LiteralKind::Nearest);
}

TEST(GlslLiteral, NanIsReportedNotPrinted) {
  const GlslLiteral lit = glslFloatLiteral(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(lit.kind, LiteralKind::NotANumber);
  EXPECT_TRUE(isGlslFloatLiteral(lit.text));
}

}  // namespace
}  // namespace zs
