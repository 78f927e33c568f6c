#include "scene/invalidation.hpp"

#include <algorithm>
#include <type_traits>
#include <variant>

#include "parser/parser.hpp"
#include "scene/schema.hpp"

namespace zs {
namespace {

using scene_detail::KeySpec;
using scene_detail::ListSpec;

// Whether one schema key holds the same value in both scenes (the fields address a mutable
// Scene, so they read copies).
bool sameValue(const KeySpec& spec, Scene& a, Scene& b) {
  return std::visit(
      [&](const auto& field) {
        using F = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<F, scene_detail::EnumRef>)
          return field.get(a) == field.get(b);
        else
          return field(a) == field(b);
      },
      spec.field);
}

// The flags of the keys of `keys` whose values differ between `a` and `b`.
Invalidation changedKeys(std::span<const KeySpec> keys, Scene& a, Scene& b) {
  Invalidation what = invalidates::Frame;
  for (const KeySpec& spec : keys) {
    if (spec.legacyLight >= 0) continue;  // old names of lights.source entries, read only
    if (!sameValue(spec, a, b)) what |= spec.invalidates;
  }
  return what;
}

// The flags of a list's entries that differ; an entry added or removed counts as every key
// of the list changed.
Invalidation changedEntries(const ListSpec& list, const Scene& a, const Scene& b) {
  const std::size_t na = list.size(a), nb = list.size(b);
  Invalidation what = invalidates::Frame;
  if (na != nb) {
    for (const KeySpec& spec : list.keys) what |= spec.invalidates;
    return what;
  }
  for (std::size_t i = 0; i < na; ++i) {
    Scene entryA, entryB;
    list.entry(a, i, entryA);
    list.entry(b, i, entryB);
    what |= changedKeys(list.keys, entryA, entryB);
  }
  return what;
}

// A parameter's value as the pipeline takes it: the scene's entry, or the default.
double paramValue(const Scene& scene, const std::string& name) {
  for (const auto& [key, value] : scene.params) {
    if (key == name) return value;
  }
  return kDefaultParamValue;
}

bool sameParams(const Scene& a, const Scene& b, const std::vector<std::string>* used) {
  if (!used) {
    // Every name either scene has, an entry missing on one side counting as the default.
    for (const Scene* s : {&a, &b}) {
      for (const auto& [name, value] : s->params) {
        if (paramValue(a, name) != paramValue(b, name)) return false;
      }
    }
    return true;
  }
  return std::all_of(used->begin(), used->end(), [&](const std::string& name) {
    return paramValue(a, name) == paramValue(b, name);
  });
}

}  // namespace

Invalidation invalidation(const Scene& before, const Scene& after,
                          const std::vector<std::string>* formulaParams) {
  Scene a = before, b = after;
  Invalidation what = changedKeys(scene_detail::keySpecs(), a, b);
  // The first surface's formula and level are a [[surface]] entry's too: the list covers
  // them, and the other surfaces.
  for (const ListSpec& list : scene_detail::listSpecs()) what |= changedEntries(list, a, b);
  if (before.formula != after.formula) what |= invalidates::Surface;
  if (!sameParams(before, after, formulaParams))
    what |= invalidates::Geometry | invalidates::ShaderIfMarked;

  const bool several = !before.moreSurfaces.empty() || !after.moreSurfaces.empty();
  const bool marked = before.render.singular.enabled || after.render.singular.enabled;
  if ((what & invalidates::ShaderIfSeveralSurfaces) && several) what |= invalidates::Shader;
  if ((what & invalidates::ShaderIfMarked) && marked) what |= invalidates::Shader;
  return what & (invalidates::Variant | invalidates::Shader | invalidates::Geometry);
}

}  // namespace zs
