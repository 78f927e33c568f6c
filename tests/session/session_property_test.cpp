// A session driven through random sequences of edits: formulas (some that fail), --set of
// every key of the schema with random valid and invalid values, list edits, parameters,
// .surf loads, drags and the wheel. After each step the picture of the session's surface
// must equal a fresh render of the session's scene (prepareSurface from scratch, as
// `zeroset render` makes it; the image tests' tolerance), and a refused edit must leave
// the scene and the picture as they were. This is the test that catches an edit whose
// rebuild rule is wrong (a stale shader, a stale octree): the bug of the prompt that kept
// a shader without zs_FHess after `:set shading.color="gauss"`.
//
// ZS_PROPERTY_SEQUENCES=N runs N sequences instead of the few the suite's time allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/ray_tracer.hpp"
#include "scene/scene_io.hpp"
#include "session/session.hpp"
#include "support/random_edit.hpp"

namespace zs {
namespace {

using test::badFormulas;
using test::goodFormulas;
using test::number;

constexpr int kWidth = 48, kHeight = 36;  // every picture of the test: small and fast

struct Renderer {
  std::unique_ptr<GlContext> context;
  std::string error;
  Renderer() {
    ContextResult c = createHeadlessContext(Backend::Egl);
    if (!c.context) c = createHeadlessContext(Backend::OsMesa);
    context = std::move(c.context);
    error = c.error;
  }
  // The picture of `surface` with `scene`'s frame settings; an empty image and `error` on
  // failure.
  Image draw(RayTracer& tracer, const Scene& scene, std::string& failure) const {
    Frame frame = tracer.render(scene.render, scene.domain, kWidth, kHeight);
    failure = frame.error;
    return frame.color;
  }
};

std::string describe(const ImageDiff& d) {
  return std::to_string(d.fractionOver * 100) + "% of pixels over threshold, rmse " +
         std::to_string(d.rmse);
}

struct Counts {
  int steps = 0, refused = 0, drawn = 0;
};

// One sequence of `steps` random edits from `seed`; stops at the first failure.
void runSequence(std::uint64_t seed, int steps, Counts& counts) {
  static Renderer gl;
  ASSERT_NE(gl.context, nullptr) << gl.error;
  gl.context->makeCurrent();
  std::mt19937_64 rng(seed);
  session::Session session;
  ASSERT_EQ(session.loadFormula(goodFormulas()[seed % goodFormulas().size()]), "");
  ASSERT_EQ(session.prepare(), "");
  RayTracer tracer;
  ASSERT_EQ(loadSurface(tracer, *session.surface(), session.scene().render), "");
  int loaded = session.generation();
  std::string failure;
  Image last = gl.draw(tracer, session.scene(), failure);
  ASSERT_EQ(failure, "");

  for (int step = 0; step < steps; ++step) {
    const Scene before = session.scene();
    const int generationBefore = session.generation();
    std::string what, error;
    switch (rng() % 10) {
      case 0:
      case 1: {
        const bool good = rng() % 3 != 0;
        what = good ? goodFormulas()[rng() % goodFormulas().size()]
                    : badFormulas()[rng() % badFormulas().size()];
        error = session.setFormula(what);
        what = "formula " + what;
        break;
      }
      case 2: {
        const auto params = session.params();
        const double v = std::uniform_real_distribution<double>(-1, 1)(rng);
        what = "param a=" + number(v);
        error = session.setParam(params.empty() ? "a" : params[0].first, v);
        break;
      }
      case 3: {
        const std::string text = test::randomSurfText(rng, rng() % 2);
        what = "load .surf " + text;
        error = session.loadSurf(text, "edit.surf");
        break;
      }
      case 4: {
        std::uniform_real_distribution<double> px(0, kWidth);
        what = "drag";
        session.beginDrag();
        session.drag(px(rng), px(rng), px(rng), px(rng), kWidth, kHeight);
        break;
      }
      case 5:
        what = "wheel";
        session.zoom(std::uniform_real_distribution<double>(-2, 2)(rng));
        break;
      default: {
        const std::string assignment = test::randomAssignment(rng, session.scene());
        what = "--set " + assignment;
        error = session.applyOverrides(std::vector<std::string>{assignment});
        break;
      }
    }
    if (error.empty()) error = session.prepare();
    SCOPED_TRACE("seed " + std::to_string(seed) + ", step " + std::to_string(step) + ": " + what);
    ++counts.steps;
    if (!error.empty()) {
      ++counts.refused;
      ASSERT_TRUE(session.scene() == before) << "a refused edit changed the scene: " << error;
      ASSERT_EQ(session.generation(), generationBefore) << error;
    }
    if (session.generation() != loaded) {
      ASSERT_EQ(loadSurface(tracer, *session.surface(), session.scene().render), "")
          << "scene before:\n"
          << saveScene(before) << "scene after:\n"
          << saveScene(session.scene());
      loaded = session.generation();
    }
    const Image picture = gl.draw(tracer, session.scene(), failure);
    ASSERT_EQ(failure, "");
    if (!error.empty()) {
      const ImageDiff same = compareImages(picture, last);
      ASSERT_TRUE(withinTolerance(same))
          << "a refused edit changed the picture: " << describe(same) << "\n"
          << error;
      continue;
    }
    // A fresh render of the scene, as `zeroset render` of its .surf text makes it.
    auto fresh = prepareSurface(session.scene(), session.prepareOptions());
    ASSERT_TRUE(std::holds_alternative<PreparedSurface>(fresh))
        << "the session took a scene that a fresh render refuses: " << std::get<std::string>(fresh)
        << "\n"
        << saveScene(session.scene());
    RayTracer freshTracer;
    ASSERT_EQ(loadSurface(freshTracer, std::get<PreparedSurface>(fresh), session.scene().render),
              "");
    const Image reference = gl.draw(freshTracer, session.scene(), failure);
    ASSERT_EQ(failure, "");
    const ImageDiff diff = compareImages(picture, reference);
    ASSERT_TRUE(withinTolerance(diff))
        << "the session's picture differs from a fresh render: " << describe(diff) << "\n"
        << saveScene(session.scene());
    ++counts.drawn;
    last = picture;
  }
}

TEST(SessionProperty, EveryEditSequenceDrawsWhatAFreshRenderDraws) {
  int sequences = 8, steps = 14;
  if (const char* n = std::getenv("ZS_PROPERTY_SEQUENCES")) sequences = std::max(1, std::atoi(n));
  Counts counts;
  for (int s = 0; s < sequences; ++s) {
    runSequence(0x5e55'0000u + std::uint64_t(s), steps, counts);
    if (HasFatalFailure()) return;
  }
  std::printf("%d sequences, %d steps: %d refused, %d compared with a fresh render\n", sequences,
              counts.steps, counts.refused, counts.drawn);
  EXPECT_GT(counts.refused, 0);  // the sequences did try edits that fail
  EXPECT_GT(counts.drawn, counts.refused);
}

}  // namespace
}  // namespace zs
