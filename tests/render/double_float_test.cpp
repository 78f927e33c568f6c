// The web's double-float expansion (GLSL ES has no double) drawn by the desktop's GL, whose
// GLSL reads it as well: with every convolution a loop (zs_dfConvolve, which the page uses
// for expansions too long for a software WebGL's JIT, codegen/emit_ray_polynomial.hpp), the
// Endraß octic's picture is the one the desktop's double expansion draws. (The Sarti
// dodecic's own expansion, whose long convolutions are loops in the page, takes seconds to
// compile here; its page picture is compared in the browser: tests/web, the gallery case.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <variant>

#include "codegen/emit_ray_polynomial.hpp"
#include "codegen/shader_assembly.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/image.hpp"
#include "render_support.hpp"
#include "scene/scene_io.hpp"

namespace zs {
namespace {

TEST(DoubleFloat, LoopedConvolutionsDrawWhatTheDoubleExpansionDraws) {
  // llvmpipe's optimization passes over the double-float program buy nothing for two small
  // pictures (Mesa reads this when the driver starts, in this process).
  setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0);
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  SceneResult loaded = loadScene(test::sourceDir() + "/examples/endrass-octic.surf");
  ASSERT_TRUE(std::holds_alternative<Scene>(loaded));
  Scene scene = std::get<Scene>(loaded);
  scene.render.reflection.enabled = false;  // one ray a pixel: the expansion is what differs
  auto prepared = prepareSurface(scene);
  ASSERT_TRUE(std::holds_alternative<PreparedSurface>(prepared)) << std::get<std::string>(prepared);
  const PreparedSurface& desktop = std::get<PreparedSurface>(prepared);
  ASSERT_EQ(desktop.method, TracingMethod::Bernstein);

  PreparedSurface web = desktop;
  web.rayPolynomial = emitRayPolynomialGlsl(web.formula.graph, web.formula.root, /*fp64=*/false,
                                            DoubleFloatLoops{.products = 0, .terms = 1});
  ASSERT_TRUE(web.rayPolynomial);
  ASSERT_NE(web.rayPolynomial->source.find("zs_dfConvolve("), std::string::npos);
  web.fragmentShader = assembleFragmentShader(web.glsl, *web.rayPolynomial);

  constexpr int kWidth = 96, kHeight = 72;
  Image pictures[2];
  for (int i = 0; i < 2; ++i) {
    RayTracer tracer;
    ASSERT_EQ(loadSurface(tracer, i == 0 ? desktop : web, scene.render), "");
    const Frame frame = tracer.render(scene.render, scene.domain, kWidth, kHeight);
    ASSERT_EQ(frame.error, "");
    pictures[i] = frame.color;
    int hits = 0;
    for (float depth : frame.depth.values) hits += std::isfinite(depth);
    EXPECT_GT(hits, kWidth * kHeight / 5) << "the surface is in the picture";
  }
  const ImageDiff diff = compareImages(pictures[0], pictures[1], 24);
  // The page's double-float against the desktop's double: 0.00 % of the gallery picture's
  // pixels (0.02 % for the Sarti dodecic), where a ray grazes the surface.
  EXPECT_LE(diff.fractionOver, 0.005) << "rmse " << diff.rmse;
}

}  // namespace
}  // namespace zs
