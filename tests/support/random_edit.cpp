#include "support/random_edit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <type_traits>
#include <variant>
#include <vector>

#include "scene/schema.hpp"

namespace zs::test {
namespace {

using namespace scene_detail;

constexpr const char* kGoodFormulas[] = {
    "x^2+y^2+z^2-1",
    "x^2+y^2-z^2-a",
    "x^4+y^4+z^4-1",
    "x*y*z",
    "sin(3*x)+y^2+z^2-1",
    "x^2+y^2+z^2-1+a*(x^3-3*x*y^2)",
    "(x^2+y^2+z^2+0.8)^2-4*(x^2+y^2)",
};
constexpr const char* kBadFormulas[] = {"x^2+(", "x^2+foo(y)", "", "x^^2", "sqrt(x"};
constexpr const char* kFunctions[] = {"x", "x+y+z", "x^2+y^2", "sin(", "z*a"};

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

}  // namespace

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

namespace {

// A random value for `spec` (whose current value is read from `scene`): within its range,
// or, when `valid` is false, outside it or of the wrong type.
std::string randomValue(std::mt19937_64& rng, const KeySpec& spec, Scene& scene,
                        std::string_view key, bool valid) {
  std::uniform_real_distribution<double> unit(0, 1);
  const Range& r = spec.range;
  if (!valid) {
    switch (rng() % 3) {
      case 0:
        return "\"not a value\"";
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
    if (std::isfinite(r.lo) && std::isfinite(hi))
      v = r.lo + unit(rng) * (hi - r.lo);
    else
      v = current * (0.5 + unit(rng)) + (unit(rng) - 0.5);
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

}  // namespace

std::string randomAssignment(std::mt19937_64& rng, const Scene& current) {
  Scene scene = current;  // the schema's fields address a mutable Scene
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
      const std::string key =
          std::string(list.name) + "." + std::to_string(i + 1) + "." + std::string(spec.name);
      return key + "=" + randomValue(rng, spec, scratch, spec.name, valid);
    }
    default:
      break;
  }
  std::vector<const KeySpec*> keys;
  for (const KeySpec& spec : keySpecs()) {
    // image.* sizes the file, not this test's pictures; old light names are read only.
    if (spec.legacyLight < 0 && !spec.name.starts_with("image.")) keys.push_back(&spec);
  }
  const KeySpec& spec = *keys[rng() % keys.size()];
  return std::string(spec.name) + "=" + randomValue(rng, spec, scene, spec.name, valid);
}

std::span<const char* const> goodFormulas() {
  return kGoodFormulas;
}
std::span<const char* const> badFormulas() {
  return kBadFormulas;
}

std::string randomSurfText(std::mt19937_64& rng, bool good) {
  if (!good) return "formula = \"x^2+y^2+z^2-1\"\n[tracing]\nepsilon = -1\n";
  return "formula = \"" + std::string(kGoodFormulas[rng() % std::size(kGoodFormulas)]) +
         "\"\n[tracing]\nmethod = \"" + (rng() % 2 ? "interval" : "auto") + "\"\n";
}

}  // namespace zs::test
