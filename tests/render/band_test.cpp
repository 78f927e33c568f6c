// A picture rendered in bands (RayTracer::renderBand, zeroset render --tile) is the whole
// picture pixel for pixel: the same rays, the same beam tiles, the same curvature range.
#include <gtest/gtest.h>

#include <cmath>

#include "render/program_variant.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

struct BandCase {
  const char* name;
  const char* formula;
  TracingMethod method = TracingMethod::Auto;
  bool curvature = false;
};

class BandRender : public ::testing::TestWithParam<BandCase> {};

TEST_P(BandRender, BandsReassembleIntoTheWholePicture) {
  std::string error;
  if (!test::context(Backend::Egl, error)) GTEST_SKIP() << error;
  const BandCase& c = GetParam();
  test::SurfaceSpec spec{c.formula};
  spec.method = c.method;
  spec.hessian = c.curvature;
  auto tracer = test::makeTracer(spec, error);
  ASSERT_NE(tracer, nullptr) << error;
  RenderSettings settings = test::testSettings({1.1, 1.7, 2.6});
  if (c.curvature) settings.shading.color = ColorMode::Gauss;
  const Domain domain = spec.domain;
  const int w = 52, h = 45;  // no multiple of the beam tile: a partial tile row on top
  const Frame whole = tracer->render(settings, domain, w, h);
  ASSERT_EQ(whole.error, "");
  // Bands whose bottom edges lie on the tile grid from the bottom: rows 0-12, 13-36, 37-44.
  const int cuts[] = {0, h - 32, h - 8, h};
  int row = 0;
  for (int b = 0; b + 1 < 4; ++b) {
    const Frame band = tracer->renderBand(settings, domain, w, h, cuts[b], cuts[b + 1] - cuts[b]);
    ASSERT_EQ(band.error, "") << "band " << b;
    ASSERT_EQ(band.color.height, cuts[b + 1] - cuts[b]);
    for (int y = 0; y < band.color.height; ++y, ++row) {
      for (int x = 0; x < w; ++x) {
        const auto* a = whole.color.pixel(x, row);
        const auto* p = band.color.pixel(x, y);
        ASSERT_TRUE(a[0] == p[0] && a[1] == p[1] && a[2] == p[2] && a[3] == p[3])
            << c.name << ": pixel (" << x << ", " << row << ") differs in band " << b;
        const float da = whole.depth.at(x, row), dp = band.depth.at(x, y);
        ASSERT_TRUE(da == dp || (std::isinf(da) && std::isinf(dp))) << c.name;
      }
    }
  }
  EXPECT_EQ(row, h);
  // A band off the tile grid is refused, not drawn differently.
  EXPECT_NE(tracer->renderBand(settings, domain, w, h, 0, 10).error, "");
}

const BandCase kBandCases[] = {
    {"bernstein", "x^4+y^4+z^4-x^2-y^2-z^2+0.3"},
    {"interval_with_beam", "x^2+y^2+z^2-1+0.2*sin(4x)*sin(4y)"},
    {"sampling", "x^2+y^2-z^2-0.2", TracingMethod::Sampling},
    {"curvature", "x^2+y^2+z^2-1+0.1*x*y*z", TracingMethod::Auto, true},
};
INSTANTIATE_TEST_SUITE_P(Cases, BandRender, ::testing::ValuesIn(kBandCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace zs
