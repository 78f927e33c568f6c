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
#include "scene/schema.hpp"
#include "session/session.hpp"

namespace zs {
namespace {

using namespace scene_detail;

constexpr int kWidth = 48, kHeight = 36;  // every picture of the test: small and fast

const char* kGoodFormulas[] = {
    "x^2+y^2+z^2-1",          "x^2+y^2-z^2-a",      "x^4+y^4+z^4-1",
    "x*y*z",                   "sin(3*x)+y^2+z^2-1", "x^2+y^2+z^2-1+a*(x^3-3*x*y^2)",
    "(x^2+y^2+z^2+0.8)^2-4*(x^2+y^2)",
};
const char* kBadFormulas[] = {"x^2+(", "x^2+foo(y)", "", "x^^2", "sqrt(x"};
const char* kFunctions[] = {"x", "x+y+z", "x^2+y^2", "sin(", "z*a"};

// Keys whose largest values cost seconds per build or frame: the test keeps them small.
double costCap(std::string_view key) {
  if (key == "octree.level") return 5;
  if (key == "samples") return 2;
  if (key == "tracing.intervals") return 96;
  if (key == "tracing.hits") return 4;
  if (key == "tracing.max_bisections") return 60;
  if (key == "volume.steps") return 200;
  if (key == "octree.node_budget") return 200000;
  return std::numeric_limits<double>::infinity();
}

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// A random value for `spec` (whose current value is read from `scene`): within its range,
// or, when `valid` is false, outside it or of the wrong type.
std::string randomValue(std::mt19937_64& rng, const KeySpec& spec, Scene& scene,
                        std::string_view key, bool valid) {
  std::uniform_real_distribution<double> unit(0, 1);
  const Range& r = spec.range;
  if (!valid) {
    switch (rng() % 3) {
      case 0: return "\"not a value\"";
      case 1:
        if (std::isfinite(r.lo)) return number(r.lo - 1 - unit(rng));
        [[fallthrough]];
      default:
        if (std::isfinite(r.hi)) return number(r.hi + 1 + unit(rng));
        return "[1, 2";  // not TOML
    }
  }
  auto inRange = [&](double current) {
    const double hi = std::min(r.hi, costCap(key));
    double v;
    if (std::isfinite(r.lo) && std::isfinite(hi)) v = r.lo + unit(rng) * (hi - r.lo);
    else v = current * (0.5 + unit(rng)) + (unit(rng) - 0.5);
    v = std::clamp(v, r.lo, hi);
    if (r.loOpen && v <= r.lo) v = r.lo + 1e-3;
    if (r.hiOpen && v >= r.hi) v = r.hi - 1e-3;
    return v;
  };
  std::string out;
  std::visit(
      [&](const auto& field) {
        using F = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<F, BoolRef>) {
          out = rng() % 2 ? "true" : "false";
        } else if constexpr (std::is_same_v<F, IntRef> || std::is_same_v<F, SizeRef>) {
          out = number(std::floor(inRange(double(field(scene)))));
        } else if constexpr (std::is_same_v<F, RealRef>) {
          out = number(inRange(field(scene)));
        } else if constexpr (std::is_same_v<F, VecRef>) {
          const Vec3 v = field(scene);
          out = "[";
          for (int i = 0; i < 3; ++i) {
            out += (i ? ", " : "") + number(std::isfinite(r.lo) && std::isfinite(r.hi)
                                                ? r.lo + unit(rng) * (r.hi - r.lo)
                                                : v[i] + unit(rng) - 0.5);
          }
          out += "]";
        } else if constexpr (std::is_same_v<F, EnumRef>) {
          out = "\"" + std::string(field.names[rng() % field.names.size()]) + "\"";
        } else {
          out = "\"" + std::string(kFunctions[rng() % std::size(kFunctions)]) + "\"";
        }
      },
      spec.field);
  return out;
}

// One random `--set` assignment: a key of the schema, of a list's entry, or a whole list.
std::string randomAssignment(std::mt19937_64& rng, const session::Session& session) {
  Scene scene = session.scene();
  const bool valid = rng() % 4 != 0;
  switch (rng() % 8) {
    case 0: {
      const char* lists[] = {
          "lights.source=[{kind = \"point\", position = [0, 0, 5]}]",
          "lights.source=[{kind = \"directional\", direction = [1, 1, 1]}, "
          "{kind = \"point\", position = [2, 0, 3], intensity = 0.5}]",
          "clip.plane=[{normal = [0, 0, 1], offset = 0}]",
          "clip.plane=[]",
          "surface=[{formula = \"x^2+y^2+z^2-1\"}, {formula = \"z\"}]",
          "surface=[{formula = \"x^2+y^2+z^2-1\"}, {formula = \"sin(\"}]",
          "no.such.key=1",
      };
      return lists[rng() % std::size(lists)];
    }
    case 1: {
      const ListSpec& list = listSpecs()[rng() % listSpecs().size()];
      const std::size_t n = list.size(scene);
      if (n == 0) break;
      const std::size_t i = rng() % n;
      const KeySpec& spec = list.keys[rng() % list.keys.size()];
      Scene scratch;
      list.entry(scene, i, scratch);
      const std::string key = std::string(list.name) + "." + std::to_string(i + 1) + "." +
                              std::string(spec.name);
      return key + "=" + randomValue(rng, spec, scratch, spec.name, valid);
    }
    default: break;
  }
  std::vector<const KeySpec*> keys;
  for (const KeySpec& spec : keySpecs()) {
    // image.* sizes the file, not this test's pictures; old light names are read only.
    if (spec.legacyLight < 0 && !spec.name.starts_with("image.")) keys.push_back(&spec);
  }
  const KeySpec& spec = *keys[rng() % keys.size()];
  return std::string(spec.name) + "=" + randomValue(rng, spec, scene, spec.name, valid);
}

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
  ASSERT_EQ(session.loadFormula(kGoodFormulas[seed % std::size(kGoodFormulas)]), "");
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
      case 0: case 1: {
        const bool good = rng() % 3 != 0;
        what = good ? kGoodFormulas[rng() % std::size(kGoodFormulas)]
                    : kBadFormulas[rng() % std::size(kBadFormulas)];
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
        const bool good = rng() % 2;
        const std::string text =
            good ? "formula = \"" + std::string(kGoodFormulas[rng() % std::size(kGoodFormulas)]) +
                       "\"\n[tracing]\nmethod = \"" +
                       (rng() % 2 ? "interval" : "auto") + "\"\n"
                 : "formula = \"x^2+y^2+z^2-1\"\n[tracing]\nepsilon = -1\n";
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
        const std::string assignment = randomAssignment(rng, session);
        what = "--set " + assignment;
        error = session.applyOverrides(std::vector<std::string>{assignment});
        break;
      }
    }
    if (error.empty()) error = session.prepare();
    SCOPED_TRACE("seed " + std::to_string(seed) + ", step " + std::to_string(step) + ": " +
                 what);
    ++counts.steps;
    if (!error.empty()) {
      ++counts.refused;
      ASSERT_TRUE(session.scene() == before) << "a refused edit changed the scene: " << error;
      ASSERT_EQ(session.generation(), generationBefore) << error;
    }
    if (session.generation() != loaded) {
      ASSERT_EQ(loadSurface(tracer, *session.surface(), session.scene().render), "")
          << "scene before:\n" << saveScene(before) << "scene after:\n" << saveScene(session.scene());
      loaded = session.generation();
    }
    const Image picture = gl.draw(tracer, session.scene(), failure);
    ASSERT_EQ(failure, "");
    if (!error.empty()) {
      const ImageDiff same = compareImages(picture, last);
      ASSERT_TRUE(withinTolerance(same)) << "a refused edit changed the picture: "
                                         << describe(same) << "\n" << error;
      continue;
    }
    // A fresh render of the scene, as `zeroset render` of its .surf text makes it.
    auto fresh = prepareSurface(session.scene(), session.prepareOptions());
    ASSERT_TRUE(std::holds_alternative<PreparedSurface>(fresh))
        << "the session took a scene that a fresh render refuses: "
        << std::get<std::string>(fresh) << "\n" << saveScene(session.scene());
    RayTracer freshTracer;
    ASSERT_EQ(loadSurface(freshTracer, std::get<PreparedSurface>(fresh), session.scene().render), "");
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
