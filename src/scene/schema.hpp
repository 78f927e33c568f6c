#pragma once
// The schema of a .surf file: every leaf key with its type, its allowed range and where it
// lives in a Scene. Reading, writing, --set and the "did you mean" hints all walk this one
// table, so a new setting is one row in schema.cpp plus its entry in docs/surf-format.md.
// `formula` and the free-form `params` table are handled by the reader itself.
#include <cstddef>
#include <span>
#include <string_view>
#include <variant>

#include "scene/scene.hpp"

namespace zs::scene_detail {

using BoolRef = bool& (*)(Scene&);
using IntRef = int& (*)(Scene&);
using SizeRef = std::size_t& (*)(Scene&);
using RealRef = double& (*)(Scene&);
using VecRef = Vec3& (*)(Scene&);

struct EnumRef {
  int (*get)(const Scene&);
  void (*set)(Scene&, int);
  std::span<const std::string_view> names;  // index = the enum's value
};

using Field = std::variant<BoolRef, IntRef, SizeRef, RealRef, VecRef, EnumRef>;

// Closed or open bounds on a number, or on each component of a vector (colors).
struct Range {
  double lo;
  double hi;
  bool loOpen = false;
  bool hiOpen = false;
  bool contains(double v) const {
    return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
  }
};

struct KeySpec {
  std::string_view name;  // dotted: "camera.fov_y"
  Field field;
  Range range;
  bool nonZero = false;  // vectors that get normalized (up, light direction)
  // >= 0: an old name of that entry of lights.sources (lights.directional.*, lights.point.*),
  // read only while the list still has the thesis' shape, and never written.
  int legacyLight = -1;
};

std::span<const KeySpec> keySpecs();
const KeySpec* findKey(std::string_view dottedName);

// The keys of one light of the [[lights.source]] array ("kind", "enabled", ...). Their
// fields address render.lights.sources.front(): the reader and the writer go through a
// scratch Scene holding just the light in question.
std::span<const KeySpec> lightKeySpecs();
const KeySpec* findLightKey(std::string_view name);

// True for "camera", "lights", "lights.point", ...: names that hold other keys.
bool isTableName(std::string_view dottedName);

inline constexpr std::string_view kFormulaKey = "formula";
inline constexpr std::string_view kParamsKey = "params";
inline constexpr std::string_view kLightSourcesKey = "lights.source";  // [[lights.source]]

}  // namespace zs::scene_detail
