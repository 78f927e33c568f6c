#pragma once
// The schema of a .surf file: every leaf key with its type, its allowed range and where it
// lives in a Scene. Reading, writing, --set and the "did you mean" hints all walk this one
// table, so a new setting is one row in schema.cpp plus its entry in docs/surf-format.md.
// `formula` and the free-form `params` table are handled by the reader itself.
#include <cstddef>
#include <span>
#include <string_view>
#include <variant>

#include "scene/invalidation.hpp"
#include "scene/scene.hpp"

namespace zs::scene_detail {

using BoolRef = bool& (*)(Scene&);
using IntRef = int& (*)(Scene&);
using SizeRef = std::size_t& (*)(Scene&);
using RealRef = double& (*)(Scene&);
using VecRef = Vec3& (*)(Scene&);
// A formula kept as its text: of x, y, z alone (shading.contours.function), or with the
// scene's parameters too where the key says `takesParams` (a [[surface]]'s formula).
using FunctionRef = std::string& (*)(Scene&);

struct EnumRef {
  int (*get)(const Scene&);
  void (*set)(Scene&, int);
  std::span<const std::string_view> names;  // index = the enum's value
};

using Field = std::variant<BoolRef, IntRef, SizeRef, RealRef, VecRef, EnumRef, FunctionRef>;

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
  // What a change of this key invalidates (scene/invalidation.hpp): the one place that says
  // what an edit rebuilds.
  Invalidation invalidates;
  Field field;
  Range range;
  bool nonZero = false;  // vectors that get normalized (up, light direction)
  // >= 0: an old name of that entry of lights.sources (lights.directional.*, lights.point.*),
  // read only while the list still has the thesis' shape, and never written.
  int legacyLight = -1;
  bool takesParams = false;  // FunctionRef: the formula may use parameters
};

std::span<const KeySpec> keySpecs();
const KeySpec* findKey(std::string_view dottedName);

// An array of tables in a scene: [[lights.source]], [[clip.plane]]. Each entry's keys
// ("kind", "enabled", ...) have fields that address the first element of the list: the
// reader and the writer go through a scratch Scene whose list holds just the entry in
// question (`entry` puts element i there, `store` takes it back).
struct ListSpec {
  std::string_view name;          // dotted: "lights.source"
  std::string_view noun;          // "light"
  std::span<const KeySpec> keys;  // of one entry
  std::size_t maxSize;
  std::string_view example;  // one entry as an inline table, for messages
  std::string_view tooManyHint;
  std::size_t (*size)(const Scene&);
  void (*resize)(Scene&, std::size_t);
  void (*entry)(const Scene& from, std::size_t i, Scene& scratch);
  void (*store)(const Scene& scratch, Scene& to, std::size_t i);
  // The key of the table after whose keys the writer puts the entries ("" : at the end).
  std::string_view writtenAfter;
  // An entry's key that must be given (the reader refuses an entry without it); "" : none.
  std::string_view requiredKey = {};
  // Entry i as a new entry of the list starts out (null: as the first entry of a default
  // scene).
  void (*fresh)(Scene& scratch, std::size_t i) = nullptr;
};

std::span<const ListSpec> listSpecs();
const ListSpec* findList(std::string_view dottedName);
std::span<const KeySpec> lightKeySpecs();  // the keys of one [[lights.source]] entry
const KeySpec* findListKey(const ListSpec& list, std::string_view name);

// The keys of the first surface that a file with [[surface]] tables keeps inside the first
// of them instead: formula, surface.level and materials.*.
bool describesFirstSurface(std::string_view dottedName);

// True for "camera", "lights", "lights.point", "clip", ...: names that hold other keys.
bool isTableName(std::string_view dottedName);

inline constexpr std::string_view kFormulaKey = "formula";
inline constexpr std::string_view kParamsKey = "params";
inline constexpr std::string_view kLightSourcesKey = "lights.source";  // [[lights.source]]
inline constexpr std::string_view kClipPlanesKey = "clip.plane";       // [[clip.plane]]
// [[surface]]: a scene with several surfaces lists all of them, the first included, in
// these entries; one with a single surface may use formula, surface.level and materials.
inline constexpr std::string_view kSurfacesKey = "surface";

}  // namespace zs::scene_detail
