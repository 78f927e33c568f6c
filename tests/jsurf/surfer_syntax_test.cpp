// Which formulas SURFER's parser reads (jsurf's AlgebraicExpression.g and its tree walker),
// and where the first thing it would refuse stands.
#include "jsurf/surfer_syntax.hpp"

#include <gtest/gtest.h>

namespace zs::jsurf {
namespace {

TEST(SurferSyntax, ReadsWhatSurferReads) {
  for (const char* f : {"x^2+y^2+z^2-1", "-x^2", "2*-x", "x^(2)", "a^2^3*x", "a*x^3 - sqrt(2)*y",
                        "(x+y)^4/(3+a)", "1.5e-3*x + .5*y + 2.*z", "sin(a)*x + abs(b - 1)",
                        "x^4 + y^4 + z^4 - 1*(0.5+2*a)^2", "1E5*z"}) {
    EXPECT_EQ(checkSurferSyntax(f), std::nullopt) << f;
  }
}

struct Refused {
  const char* formula;
  std::size_t offset;
};

TEST(SurferSyntax, RefusesWhatSurferRefusesAtThePlace) {
  const Refused cases[] = {
      {"2x", 1},           // implicit product
      {"x y", 2},          //
      {"x**2", 2},         // '**'
      {"x^-2", 2},         // a sign after '^'
      {"--x", 1},          // two signs
      {"+x", 0},           // unary plus
      {"x^2 = y", 4},      // equation
      {"[x+1]^2", 0},      // brackets
      {"sin(x)", 0},       // a function of x
      {"sinh(a)*x", 0},    // a function SURFER lacks
      {"atan2(a, b)", 0},  // and two arguments
      {"x/y", 1},          // division by a variable
      {"x^a", 2},          // a non-integer power of x
      {"x^2.0", 2},        //
      {"x^2^1", 2},        // SURFER wants the exponent of x as one integer
      {"x^2 + ", 6},       // the end
      {"07*x", 0},         // a leading zero
  };
  for (const Refused& c : cases) {
    const auto problem = checkSurferSyntax(c.formula);
    ASSERT_NE(problem, std::nullopt) << c.formula;
    EXPECT_EQ(problem->offset, c.offset) << c.formula << ": " << problem->message;
    EXPECT_FALSE(problem->message.empty());
  }
}

TEST(SurferSyntax, DeepNestingIsRefusedNotOverflowed) {
  const std::string deep = std::string(100000, '(') + "x" + std::string(100000, ')');
  EXPECT_NE(checkSurferSyntax(deep), std::nullopt);
  std::string tower = "x";
  for (int i = 0; i < 100000; ++i) tower += "^2";
  EXPECT_NE(checkSurferSyntax(tower), std::nullopt);
}

}  // namespace
}  // namespace zs::jsurf
