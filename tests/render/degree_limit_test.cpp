// Where the Bernstein method stops being exact: Chebyshev surfaces
// T_n(x) + T_n(y) + T_n(z) = 0 in [-1.05, 1.05]^3, written out in the power basis as a user
// would type them (coefficients up to 2^(n-1), values near 3: the expansion along a ray
// cancels ever larger terms as n grows). Each render is compared with a reference in double
// precision that samples f(t) = F(o + t d) and f'(t) = grad F . d densely along every pixel
// ray: the first sample step where f changes sign, or where f' changes sign and f at the
// extremum (found by bisecting f') has the other sign, holds the first root, which bisection
// then finds. So two roots closer than a sample step are found too, as long as a step holds
// at most one extremum of f (16 n steps per ray; T_n has at most n - 1 per axis). Pixels
// whose hit or miss changes within half a pixel are left out (either answer is right).
//
// kMaxBernsteinDegree (render/settings.hpp) is the highest degree asserted exact here; the
// degrees above it are measured and printed, not asserted (docs/renderer.md has the table).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "codegen/emit_ray_polynomial.hpp"
#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "parser/parser.hpp"
#include "render/camera.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

constexpr int kSize = 48;
const Domain kBox{{-1.05, -1.05, -1.05}, {1.05, 1.05, 1.05}};
const Vec3 kEye{2.2, 1.6, 3.0};

// T_n(v) in the power basis, from T_{k+1} = 2 v T_k - T_{k-1}, as formula text.
std::string chebyshev(int n, char v) {
  std::vector<double> prev{1}, cur{0, 1};
  for (int k = 1; k < n; ++k) {
    std::vector<double> next(cur.size() + 1, 0.0);
    for (std::size_t i = 0; i < cur.size(); ++i) next[i + 1] += 2 * cur[i];
    for (std::size_t i = 0; i < prev.size(); ++i) next[i] -= prev[i];
    prev = cur;
    cur = next;
  }
  std::string text;
  for (int i = n; i >= 0; --i) {
    if (cur[std::size_t(i)] == 0) continue;
    char term[64];
    std::snprintf(term, sizeof term, "%+.0f*%c^%d", cur[std::size_t(i)], v, i);
    text += term;
  }
  return "(" + text + ")";
}

std::string chebyshevSurface(int n) {
  return chebyshev(n, 'x') + "+" + chebyshev(n, 'y') + "+" + chebyshev(n, 'z');
}

using Measured = test::DepthComparison;

Measured measure(int n) {
  // Large programs (the kernels grow as the degree squared), each drawn once at 48 x 48:
  // llvmpipe's optimization passes would cost more than everything else. Mesa reads this
  // when the driver starts: in this test's own process (ctest runs each test alone).
  setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0);
  Measured m;
  const std::string formula = chebyshevSurface(n);
  std::string error;
  EXPECT_NE(test::context(Backend::Egl, error), nullptr) << error;
  test::SurfaceSpec spec{formula, kBox, 1};
  spec.method = TracingMethod::Bernstein;  // beyond the limit too: this measures it
  auto tracer = test::makeTracer(spec, error);
  EXPECT_NE(tracer, nullptr) << error;
  if (!tracer) return m;
  const RenderSettings s = test::testSettings(kEye);
  const Frame frame = tracer->render(s, kBox, kSize, kSize);
  EXPECT_EQ(frame.error, "");

  Formula f = std::get<Formula>(parseFormula(formula));
  const std::array<NodeId, 3> g = gradient(f.graph, f.root);
  PointEvaluator eval(compileTape(f.graph, {f.root, g[0], g[1], g[2]}));
  // A ray that passes within the tangent tolerance of a sheet (1e-5 of the domain diagonal,
  // docs/renderer.md) counts as touching it.
  const double tolerance = 1e-5 * std::sqrt(3.0) * (kBox.max[0] - kBox.min[0]);
  const test::DepthComparison c = test::compareDepth(
      frame.depth, s.camera, kSize, eval,
      [&](const Ray& r) {
        const auto [t0, t1] = test::rayInBox(r, kBox);
        return t0 <= t1 ? test::sampledFirstHit(eval, r, t0, t1, 16 * n) : NAN;
      },
      [&](double) { return 1.5 * tolerance; });
  m = c;
  std::printf(
      "  T%d (%s): %d reference hits, %d missed, %d extra, worst depth error %.3g; left "
      "out: %d grazing, %d touching within the tolerance%s\n",
      n, n >= kDoubleDegree ? "double" : "float", m.hits, m.missed, m.extra, m.worstDepth,
      m.grazing, m.touching,
      n > kMaxBernsteinDegree ? " (above the limit: the app uses the interval method)" : "");
  return m;
}

TEST(DegreeLimit, ChebyshevSurfacesAreExactUpToTheLimit) {
  // The float expansion, the double one, and the limit itself.
  for (int n : {4, 12, kMaxBernsteinDegree}) {
    SCOPED_TRACE("T" + std::to_string(n));
    const Measured m = measure(n);
    EXPECT_GT(m.hits, kSize * kSize / 10);
    EXPECT_EQ(m.missed, 0);
    EXPECT_EQ(m.extra, 0);
    EXPECT_LT(m.worstDepth, 1e-3);  // the default epsilon
  }
}

// Printed for docs/renderer.md, run by hand (--gtest_also_run_disabled_tests): the app
// traces these degrees with the interval method, and their shaders take 17 s to compile.
TEST(DegreeLimit, DISABLED_AboveTheLimitIsMeasured) {
  for (int n : {24, 32}) {
    const Measured m = measure(n);
    EXPECT_GT(m.hits, 0);  // the reference sees the surface: the comparison means something
  }
}

}  // namespace
}  // namespace zs
