// The web build writes numbers with printf and strtod (its libc++ has no floating-point
// to_chars): that text must be exactly what std::to_chars writes natively, so scenes, shader
// literals and printed formulas are the same on both.
#include "expr/number_text.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

namespace zs {
namespace {

template <class T>
std::string toChars(T v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

TEST(NumberText, PortableWritesWhatToCharsWrites) {
  const double cases[] = {0.0,
                          -0.0,
                          1.0,
                          -1.0,
                          0.1,
                          0.4,
                          2.5,
                          100.0,
                          1e5,
                          123456.0,
                          1e15,
                          1e16,
                          1e22,
                          1e-4,
                          1e-5,
                          3.0e-7,
                          1.0 / 3.0,
                          9.55,
                          1e300,
                          5e-324,
                          std::numeric_limits<double>::max(),
                          std::numeric_limits<double>::min()};
  for (double v : cases) {
    EXPECT_EQ(shortestTextPortable(v), toChars(v)) << v;
    EXPECT_EQ(shortestTextPortable(float(v)), toChars(float(v))) << v;
  }
  std::mt19937_64 random(7);
  for (int i = 0; i < 20000; ++i) {
    const auto bits = random();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    ASSERT_EQ(shortestTextPortable(v), toChars(v)) << v;
    const float f = float(std::ldexp(double(random() % 100000) - 50000, int(random() % 60) - 30));
    ASSERT_EQ(shortestTextPortable(f), toChars(f)) << f;
  }
  // Powers of two, where the rounding interval below is half as wide as above.
  for (int e = -1074; e <= 1023; ++e) {
    const double v = std::ldexp(1.0, e);
    ASSERT_EQ(shortestTextPortable(v), toChars(v)) << "2^" << e;
  }
  for (int e = -149; e <= 127; ++e) {
    const float f = std::ldexp(1.0f, e);
    ASSERT_EQ(shortestTextPortable(f), toChars(f)) << "2^" << e << " as float";
  }
  EXPECT_EQ(shortestTextPortable(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(shortestTextPortable(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(NumberText, ParseDecimalTakesTheWholeTextOnly) {
  EXPECT_EQ(parseDecimal("1.25"), 1.25);
  EXPECT_EQ(parseDecimal("-1e-3"), -1e-3);
  EXPECT_EQ(parseDecimal("1E3"), 1000.0);
  EXPECT_FALSE(parseDecimal(""));
  EXPECT_FALSE(parseDecimal("1.5x"));
  EXPECT_FALSE(parseDecimal(" 1"));
  EXPECT_FALSE(parseDecimal("+1"));
}

}  // namespace
}  // namespace zs
