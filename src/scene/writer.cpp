// saveScene: every key of the schema, in the schema's order, so that the file documents the
// whole scene and parseScene(saveScene(s)) == s.
#include <algorithm>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>

#include "scene/scene_io.hpp"
#include "scene/schema.hpp"
#include "scene/values.hpp"

namespace zs {

namespace {

using namespace scene_detail;

std::string tomlString(std::string_view s) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  static constexpr std::pair<char, std::string_view> kEscapes[] = {
      {'"', "\\\""}, {'\\', "\\\\"}, {'\b', "\\b"}, {'\t', "\\t"},
      {'\n', "\\n"}, {'\f', "\\f"},  {'\r', "\\r"}};
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    const auto* e = std::find_if(std::begin(kEscapes), std::end(kEscapes),
                                 [c](const auto& p) { return p.first == c; });
    if (e != std::end(kEscapes)) {
      out += e->second;
    } else if (u < 0x20 || u == 0x7F) {
      // TOML forbids raw control characters in basic strings; bytes >= 0x80 are UTF-8.
      out += "\\u00";
      out += kHex[u >> 4];
      out += kHex[u & 15];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

bool isBareKey(std::string_view s) {
  if (s.empty()) return false;
  for (const char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

std::string vectorText(const Vec3& v) {
  return "[" + formatDouble(v[0]) + ", " + formatDouble(v[1]) + ", " + formatDouble(v[2]) + "]";
}

std::string valueText(Scene& scene, const KeySpec& spec) {
  return std::visit(
      [&](const auto& ref) -> std::string {
        using Ref = std::decay_t<decltype(ref)>;
        if constexpr (std::is_same_v<Ref, BoolRef>) {
          return ref(scene) ? "true" : "false";
        } else if constexpr (std::is_same_v<Ref, IntRef> || std::is_same_v<Ref, SizeRef>) {
          return std::to_string(ref(scene));
        } else if constexpr (std::is_same_v<Ref, RealRef>) {
          return formatDouble(ref(scene));
        } else if constexpr (std::is_same_v<Ref, VecRef>) {
          return vectorText(ref(scene));
        } else if constexpr (std::is_same_v<Ref, FunctionRef>) {
          return tomlString(ref(scene));
        } else {
          static_assert(std::is_same_v<Ref, EnumRef>);
          return tomlString(ref.names[static_cast<std::size_t>(ref.get(scene))]);
        }
      },
      spec.field);
}

// The entries of a list as [[name]] tables. An empty list is written only where the default
// has entries (the lights), as `leaf = []` inside the parent table the writer is in.
std::string listText(const Scene& scene, const ListSpec& spec) {
  const std::size_t n = spec.size(scene);
  if (n == 0) {
    if (spec.size(Scene{}) == 0) return {};
    return std::string(spec.name.substr(spec.name.rfind('.') + 1)) + " = []\n";
  }
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    Scene scratch;  // the entry keys address the list's first element (schema.hpp)
    spec.entry(scene, i, scratch);
    out += "\n[[" + std::string(spec.name) + "]]\n";
    for (const KeySpec& key : spec.keys)
      out += std::string(key.name) + " = " + valueText(scratch, key) + "\n";
  }
  return out;
}

}  // namespace

std::string saveScene(const Scene& scene) {
  // The schema hands out mutable references (the reader needs them); a copy keeps `scene`
  // untouched without casting const away.
  Scene copy = scene;
  std::string out = "# zeroset scene: every key is described in docs/surf-format.md\n";
  // Several surfaces are all written as [[surface]] tables, the first one's formula, level
  // and materials included (TOML cannot have both [surface] and [[surface]]).
  const bool surfaceList = !scene.moreSurfaces.empty();
  if (!surfaceList) out += "formula = " + tomlString(scene.formula) + "\n";
  bool paramsWritten = false;
  std::string_view table;
  for (const KeySpec& spec : keySpecs()) {
    if (spec.legacyLight >= 0) continue;  // the lights are written as [[lights.source]]
    if (surfaceList && describesFirstSurface(spec.name)) continue;
    const auto dot = spec.name.rfind('.');
    const std::string_view prefix = dot == std::string_view::npos ? "" : spec.name.substr(0, dot);
    const std::string_view leaf =
        dot == std::string_view::npos ? spec.name : spec.name.substr(dot + 1);
    // [params] follows the top-level keys: TOML wants those before the first table.
    if (!prefix.empty() && !paramsWritten) {
      out += "\n[params]\n";
      for (const auto& [name, value] : scene.params) {
        out += (isBareKey(name) ? name : tomlString(name)) + " = " + formatDouble(value) + "\n";
      }
      paramsWritten = true;
    }
    if (prefix != table) {
      out += "\n[" + std::string(prefix) + "]\n";
      table = prefix;
    }
    out += std::string(leaf) + " = " + valueText(copy, spec) + "\n";
    // The last key of a list's parent table: the list's [[...]] tables follow it.
    for (const ListSpec& list : listSpecs())
      if (spec.name == list.writtenAfter) out += listText(scene, list);
  }
  for (const ListSpec& list : listSpecs()) {
    if (list.name == kSurfacesKey && !surfaceList) continue;  // the formula said it all
    if (list.writtenAfter.empty()) out += listText(scene, list);
  }
  return out;
}

}  // namespace zs
