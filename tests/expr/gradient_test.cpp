// The symbolic gradient against central finite differences at random points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "parsed.hpp"
#include "parser/parser.hpp"

namespace zs {
namespace {

using test::parsed;

const char* const kFormulas[] = {
    "x^2 + z^2 - y",
    "x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)",
    "x^4 + y^4 + z^4 - 1",
    "x^2 + y^3 + z^5 - 1",
    "x^3*y + y^3*z + z^3*x",
    "x^4 - z^4 - y",
    "x^2*y^2 + y^2*z^2 + z^2*x^2 - 1",
    "sin(x*y) + cos(z) - 0.5",
    "exp(x)*log(y^2 + 1) - z",
    "sqrt(x^2 + y^2 + 1) - z",
    "atan2(y, x + 3) + atan(z)",
    "sinh(x) + cosh(y)*tanh(z)",
    "cbrt(x + 2)*y - z",
    "(x^2 + 1)^1.5 - y*z",
    "1/(x^2 + 1) + x/(y^2 + 2)",
    "tan(0.5x) + asin(0.5y) + acos(0.3z)",
    "min(x, y) + max(y*z, x)",
    "abs(x) - y + z^-2",
    "(x + y + z)^5 - 1",
    "a*x^2 + b*y^3 - c*z",
    "pow(y^2 + 2, x) + x^y^2",
    "4*(2.618034^2*x^2 - y^2)*(2.618034^2*y^2 - z^2)*(2.618034^2*z^2 - x^2) - (1 + "
    "2*2.618034)*(x^2 + y^2 + z^2 - 1)^2",
};

TEST(Gradient, AgreesWithCentralDifferences) {
  // h = 1e-5 balances truncation (~h^2 f''') against cancellation (~1e-16 |f| / h). The
  // allowed error is 1e-6 of the local scale plus the difference between the estimates at
  // h and 2h, which bounds the truncation error near poles such as z^-2 at z ~ 0.
  constexpr double h = 1e-5, tol = 1e-6;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> coord(-1.5, 1.5);
  for (const char* text : kFormulas) {
    Formula f = parsed(text);
    const auto grad = gradient(f.graph, f.root);
    const Tape tape = compileTape(f.graph, {f.root, grad[0], grad[1], grad[2]});
    PointEvaluator ev(tape);
    const std::vector<double> params = {0.7, -1.3, 2.1};
    int checked = 0;
    for (int i = 0; i < 1000; ++i) {
      const double p[3] = {coord(rng), coord(rng), coord(rng)};
      double out[4];
      ev.eval(p[0], p[1], p[2], params, out);
      for (int axis = 0; axis < 3; ++axis) {
        auto central = [&](double step) {
          double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
          a[axis] += step;
          b[axis] -= step;
          return (ev.eval1(a[0], a[1], a[2], params) - ev.eval1(b[0], b[1], b[2], params)) /
                 (2 * step);
        };
        const double fd = central(h), fd2 = central(2 * h);
        if (!std::isfinite(fd) || !std::isfinite(fd2) || !std::isfinite(out[1 + axis])) {
          continue;  // outside the domain
        }
        const double scale = 1.0 + std::fabs(out[0]) + std::fabs(fd);
        EXPECT_NEAR(out[1 + axis], fd, tol * scale + 2 * std::fabs(fd - fd2))
            << text << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ") axis " << axis;
        ++checked;
      }
    }
    EXPECT_GT(checked, 1000) << text;  // at least a third of the points are in every domain
  }
}

// dF/dt along a direction given by three nodes (here parameters, as the interval GLSL's ray
// direction) is grad F . d, from one forward pass.
TEST(DirectionalDerivative, IsTheGradientAlongTheDirection) {
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> coord(-1.5, 1.5);
  for (const char* text : kFormulas) {
    Formula f = parsed(text);
    const auto grad = gradient(f.graph, f.root);
    std::vector<double> params = {0.7, -1.3, 2.1};
    params.resize(f.graph.params().size());
    const NodeId dd = directionalDerivative(
        f.graph, f.root, {f.graph.param("dx"), f.graph.param("dy"), f.graph.param("dz")});
    const Tape tape = compileTape(f.graph, {f.root, grad[0], grad[1], grad[2], dd});
    PointEvaluator ev(tape);
    const std::size_t first = params.size();
    params.resize(first + 3);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
      for (int k = 0; k < 3; ++k) params[first + k] = coord(rng);
      double out[5];
      ev.eval(coord(rng), coord(rng), coord(rng), params, out);
      if (!std::isfinite(out[4]) || !std::isfinite(out[1]) || !std::isfinite(out[2]) ||
          !std::isfinite(out[3]))
        continue;  // outside the domain
      double dot = 0, scale = 1;
      for (int k = 0; k < 3; ++k) {
        dot += out[1 + k] * params[first + k];
        scale += std::fabs(out[1 + k] * params[first + k]);
      }
      EXPECT_NEAR(out[4], dot, 1e-12 * scale) << text;
      ++checked;
    }
    EXPECT_GT(checked, 100) << text;
  }
}

TEST(Gradient, OfAVariableFreeFormulaIsZero) {
  Formula f = parsed("a^2 + sin(b)");
  for (NodeId d : gradient(f.graph, f.root)) {
    ASSERT_TRUE(f.graph.isConst(d));
    EXPECT_EQ(f.graph[d].value, 0.0);
  }
}

TEST(Gradient, SharesSubexpressionsWithF) {
  Formula f = parsed("sin(x^2 + y^2 + z^2)");
  const std::size_t before = f.graph.size();
  gradient(f.graph, f.root);
  // cos(x^2+y^2+z^2) is built once and reused by all three partials.
  EXPECT_LT(f.graph.size() - before, 16u);
}

}  // namespace
}  // namespace zs
