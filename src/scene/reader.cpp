#include "scene/reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "parser/parser.hpp"
#include "scene/hints.hpp"
#include "scene/string_map.hpp"
#include "scene/values.hpp"

namespace zs::scene_detail {

namespace {

using Entry = std::pair<const toml::key*, const toml::node*>;

// toml++ keeps a table's keys sorted by name; a person reads the file top to bottom, and
// [params] must keep the file's order.
std::vector<Entry> inFileOrder(const toml::table& table) {
  std::vector<Entry> entries;
  for (const auto& [key, node] : table) entries.emplace_back(&key, &node);
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    const Position pa = positionOf(*a.first), pb = positionOf(*b.first);
    return std::pair(pa.line, pa.column) < std::pair(pb.line, pb.column);
  });
  return entries;
}

// A parameter name is whatever the formula language reads as a parameter: asking the parser
// keeps the two in agreement (x, y, z, constants and function names are refused).
bool isParamName(std::string_view name) {
  const ParseResult parsed = parseFormula(name);
  const Formula* f = std::get_if<Formula>(&parsed);
  return f && f->root != kNoNode && f->graph[f->root].op == Op::Param &&
         f->graph.params().size() == 1 && f->graph.params()[0] == name;
}

class Reader {
 public:
  Reader(Scene& scene, const SourceText& src, KeyHistory& seen)
      : scene_(scene), src_(src), seen_(seen) {}

  std::optional<SceneError> table(const toml::table& table, const std::string& prefix) {
    for (const auto& [key, node] : inFileOrder(table)) {
      const std::string name =
          prefix.empty() ? std::string(key->str()) : prefix + "." + std::string(key->str());
      if (auto err = entry(name, *key, *node)) return err;
    }
    return std::nullopt;
  }

 private:
  std::optional<SceneError> entry(const std::string& name, const toml::key& key,
                                  const toml::node& node) {
    seen_.push_back({name, &src_, positionOf(node)});
    if (surfaceListRead_ && describesFirstSurface(name))
      return outsideSurfaceList(positionOf(node), name);
    if (name == kFormulaKey) return formula(node);
    if (name == kParamsKey) return params(node);
    if (const ListSpec* list = findList(name)) return this->list(*list, node);
    if (const KeySpec* spec = findKey(name)) {
      if (spec->legacyLight >= 0) return legacyLight(*spec, node);
      return readLeaf(scene_, *spec, node, src_);
    }
    if (isTableName(name)) {
      if (const toml::table* t = node.as_table()) return table(*t, name);
      return src_.error(positionOf(node), name, name + " must be a table, got " + typeName(node),
                        "write [" + name + "] on its own line, followed by its keys");
    }
    return src_.error(positionOf(key), name, "unknown key \"" + name + "\"", unknownKeyHint(name));
  }

  std::optional<SceneError> formula(const toml::node& node) {
    const std::string key(kFormulaKey);
    if (!node.is_string()) {
      return src_.error(positionOf(node), key, "formula must be a string, got " + typeName(node),
                        "put the formula in double quotes: formula = \"x^2 + y^2 + z^2 - 1\"");
    }
    std::string text = *node.value<std::string>();
    const auto offsets = stringSourceMap(src_.text(), src_.offsetOf(positionOf(node)), text);
    if (auto err = checkFormula(text, src_, offsets)) return err;
    scene_.formula = std::move(text);
    return std::nullopt;
  }

  // [params], or the params of a [[surface]] table (`where` = "surface.2.params"): the
  // surfaces share one set of parameters, so a name this document already gave another
  // value is an error.
  std::optional<SceneError> params(const toml::node& node, const std::string& where = "params") {
    const toml::table* table = node.as_table();
    if (!table) {
      return src_.error(positionOf(node), where, where + " must be a table, got " + typeName(node),
                        "write [params] on its own line, then one name = value per parameter");
    }
    for (const auto& [key, value] : inFileOrder(*table)) {
      const std::string name(key->str());
      const std::string dotted = where + "." + name;
      seen_.push_back({dotted, &src_, positionOf(*value)});
      if (!isParamName(name)) {
        return src_.error(positionOf(*key), dotted, "\"" + name + "\" is not a parameter name",
                          "a parameter is a letter or '_' followed by letters, digits or '_', "
                          "other than x, y, z and the names of functions and constants");
      }
      double v = 0;
      const Range any{-std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity()};
      if (auto err = readNumber(*value, dotted, any, src_, v)) return err;
      if (const auto read = paramsRead_.find(name);
          read != paramsRead_.end() && read->second != v) {
        return src_.error(positionOf(*value), dotted,
                          "parameter " + name + " is " + formatDouble(v) + " here but " +
                              formatDouble(read->second) + " above",
                          "the surfaces of a scene share their parameters: give it one value, or "
                          "name the second one differently");
      }
      paramsRead_.emplace(name, v);
      auto it = std::find_if(scene_.params.begin(), scene_.params.end(),
                             [&](const auto& p) { return p.first == name; });
      if (it != scene_.params.end())
        it->second = v;
      else
        scene_.params.emplace_back(name, v);
    }
    return std::nullopt;
  }

  // lights.directional.* and lights.point.* name the thesis' two lights, sources[0] and [1];
  // they make no sense once a file lists its own lights.
  std::optional<SceneError> legacyLight(const KeySpec& spec, const toml::node& node) {
    const std::vector<Light>& lights = scene_.render.lights.sources;
    const auto i = static_cast<std::size_t>(spec.legacyLight);
    const LightKind kind = i == 0 ? LightKind::Directional : LightKind::Point;
    const std::string key(spec.name);
    if (listRead_ || lights.size() != 2 || lights[i].kind != kind) {
      return src_.error(positionOf(node), key,
                        key + " names one of the thesis' two default lights, but " +
                            (listRead_ ? "this file lists its lights in [[lights.source]]"
                                       : "the scene's lights are no longer those two"),
                        "set the light in its [[lights.source]] entry instead (--set "
                        "lights.source.N.KEY=VALUE, N counted from 1)");
    }
    legacyRead_ = true;
    return readLeaf(scene_, spec, node, src_);
  }

  // An array of tables ([[lights.source]], [[clip.plane]]) replaces the whole list; a table
  // of numbered entries (what --set lights.source.2.intensity=0.3 reads as) changes
  // existing entries.
  std::optional<SceneError> list(const ListSpec& spec, const toml::node& node) {
    const std::string key(spec.name), noun(spec.noun);
    const std::size_t size = spec.size(scene_);
    if (const toml::table* numbered = node.as_table()) {
      for (const auto& [index, value] : inFileOrder(*numbered)) {
        const std::string name = key + "." + std::string(index->str());
        // [surface] level = 1: a key of the table that shares the list's name (whose
        // unknown keys get the usual hint).
        if (entryNumber(index->str()) == 0 && sharesItsNameWithATable(spec)) {
          if (!findKey(name) && findListKey(spec, index->str())) {
            return src_.error(positionOf(*index), name,
                              name + " is a key of a [[" + key + "]] table, not of [" + key + "]",
                              "write [[" + key +
                                  "]] (two brackets) above it, one such table "
                                  "per " +
                                  noun);
          }
          if (auto err = this->entry(name, *index, *value)) return err;
          continue;
        }
        const std::size_t n = entryNumber(index->str());
        if (n == 0 || n > size) {
          return src_.error(positionOf(*index), name,
                            "the scene has no " + noun + " " + std::string(index->str()),
                            size == 0 ? "the scene has no [[" + key +
                                            "]] entries yet: add one "
                                            "as an array, e.g. --set '" +
                                            key + "=[" + std::string(spec.example) + "]'"
                                      : noun + "s are numbered from 1 to " + std::to_string(size) +
                                            ", in the order of the [[" + key + "]] entries");
        }
        if (auto err = entry(spec, *value, name, scene_, n - 1, false)) return err;
      }
      return std::nullopt;
    }
    const toml::array* array = node.as_array();
    if (!array) {
      return src_.error(positionOf(node), key,
                        key + " must be an array of tables, got " + typeName(node),
                        "write each " + noun + " as its own [[" + key + "]] table");
    }
    if (spec.name == kLightSourcesKey && legacyRead_) {
      return src_.error(positionOf(node), key,
                        "[[lights.source]] and lights.directional / lights.point both describe "
                        "the lights",
                        "list every light as a [[lights.source]] entry and drop "
                        "[lights.directional] and [lights.point]");
    }
    if (array->size() > spec.maxSize) {
      return src_.error(positionOf((*array)[spec.maxSize]), key,
                        "at most " + std::to_string(spec.maxSize) + " " + noun + "s, got " +
                            std::to_string(array->size()),
                        std::string(spec.tooManyHint));
    }
    if (spec.name == kSurfacesKey) {
      if (array->empty()) {
        return src_.error(positionOf(node), key, "a scene needs at least one surface",
                          "give each surface a [[surface]] table with its formula");
      }
      for (auto it = seen_.rbegin(); it != seen_.rend(); ++it) {
        if (it->src != &src_) break;  // only this document's keys conflict
        if (describesFirstSurface(it->key)) return outsideSurfaceList(it->pos, it->key);
      }
    }
    Scene read = scene_;
    spec.resize(read, array->size());
    for (std::size_t i = 0; i < array->size(); ++i) {
      Scene fresh;  // a new entry starts from an entry's defaults, not from the old list's
      if (spec.fresh) {
        spec.fresh(fresh, i);
      } else {
        spec.resize(fresh, 0);
        spec.resize(fresh, 1);
      }
      spec.store(fresh, read, i);
      if (auto err = entry(spec, (*array)[i], key + "." + std::to_string(i + 1), read, i, true))
        return err;
    }
    spec.resize(scene_, array->size());
    for (std::size_t i = 0; i < array->size(); ++i) {
      Scene scratch;
      spec.entry(read, i, scratch);
      spec.store(scratch, scene_, i);
    }
    if (spec.name == kLightSourcesKey) listRead_ = true;
    if (spec.name == kSurfacesKey) surfaceListRead_ = true;
    return std::nullopt;
  }

  static bool sharesItsNameWithATable(const ListSpec& spec) {
    const std::string prefix = std::string(spec.name) + ".";
    return std::any_of(keySpecs().begin(), keySpecs().end(),
                       [&](const KeySpec& k) { return k.name.starts_with(prefix); });
  }

  SceneError outsideSurfaceList(Position pos, const std::string& key) const {
    return src_.error(pos, key,
                      key +
                          " describes the first surface, but this file lists its surfaces in "
                          "[[surface]] tables",
                      "move it into the first [[surface]] table (formula = ..., front.color = "
                      "...)");
  }

  // "3" -> 3; 0 for anything that is not a plain positive number.
  static std::size_t entryNumber(std::string_view text) {
    if (text.empty() || text.size() > 2) return 0;
    std::size_t n = 0;
    for (const char c : text) {
      if (c < '0' || c > '9') return 0;
      n = n * 10 + static_cast<std::size_t>(c - '0');
    }
    return n;
  }

  // The keys of entry i of `spec`'s list in `target`, through a scratch scene holding just
  // that entry (the list's key specs address its first element). A whole entry (`complete`,
  // an element of an array) must have the list's required key.
  std::optional<SceneError> entry(const ListSpec& spec, const toml::node& node,
                                  const std::string& name, Scene& target, std::size_t i,
                                  bool complete) {
    const toml::table* table = node.as_table();
    if (!table) {
      return src_.error(
          positionOf(node), name, name + " must be a table, got " + typeName(node),
          "a " + std::string(spec.noun) + " is a table: " + std::string(spec.example));
    }
    if (complete && !spec.requiredKey.empty() && !table->contains(spec.requiredKey)) {
      const std::string required(spec.requiredKey);
      return src_.error(
          positionOf(node), name + "." + required,
          "this " + std::string(spec.noun) + " has no " + required,
          "every [[" + std::string(spec.name) + "]] table needs one: " + std::string(spec.example));
    }
    Scene scratch;
    spec.entry(target, i, scratch);
    if (auto err = entryKeys(spec, *table, name, "", scratch)) return err;
    spec.store(scratch, target, i);
    return std::nullopt;
  }

  // The keys of one entry's table; a sub-table (front = { color = ... }) holds the keys
  // that start with its name (front.color).
  std::optional<SceneError> entryKeys(const ListSpec& spec, const toml::table& table,
                                      const std::string& name, const std::string& prefix,
                                      Scene& scratch) {
    for (const auto& [key, value] : inFileOrder(table)) {
      const std::string local = prefix + std::string(key->str());
      const std::string dotted = name + "." + local;
      seen_.push_back({dotted, &src_, positionOf(*value)});
      if (spec.name == kSurfacesKey && local == kParamsKey) {
        if (auto err = params(*value, dotted)) return err;
        continue;
      }
      const KeySpec* keySpec = findListKey(spec, local);
      const toml::table* sub = value->as_table();
      if (!keySpec && sub) {
        const bool holdsKeys =
            std::any_of(spec.keys.begin(), spec.keys.end(),
                        [&](const KeySpec& k) { return k.name.starts_with(local + "."); });
        if (holdsKeys) {
          if (auto err = entryKeys(spec, *sub, name, local + ".", scratch)) return err;
          continue;
        }
      }
      if (!keySpec) {
        std::vector<std::string_view> names;
        for (const KeySpec& k : spec.keys) names.push_back(k.name);
        return src_.error(positionOf(*key), dotted, "unknown key \"" + dotted + "\"",
                          choiceHint(local, names));
      }
      KeySpec named = *keySpec;
      named.name = dotted;  // messages name the entry
      if (auto err = readLeaf(scratch, named, *value, src_)) return err;
    }
    return std::nullopt;
  }

  Scene& scene_;
  const SourceText& src_;
  KeyHistory& seen_;
  bool legacyRead_ = false;       // this document set lights.directional.* or lights.point.*
  bool listRead_ = false;         // this document replaced the list with [[lights.source]]
  bool surfaceListRead_ = false;  // this document listed its surfaces as [[surface]]
  std::map<std::string, double> paramsRead_;  // the parameters this document gave, by name
};

// An error about keys that constrain each other, placed at the latest-written of `keys`
// (the one that made the set inconsistent); at `fallback`'s start when none was written.
SceneError errorAt(const KeyHistory& seen, const SourceText& fallback,
                   std::initializer_list<std::string_view> keys, std::string message,
                   std::string hint) {
  for (auto it = seen.rbegin(); it != seen.rend(); ++it) {
    if (std::find(keys.begin(), keys.end(), it->key) != keys.end())
      return it->src->error(it->pos, it->key, std::move(message), std::move(hint));
  }
  return fallback.error(Position{}, std::string(*keys.begin()), std::move(message),
                        std::move(hint));
}

}  // namespace

std::optional<SceneError> crossCheck(const Scene& scene, const KeyHistory& seen,
                                     const SourceText& fallback) {
  auto errorAt = [&](std::initializer_list<std::string_view> keys, std::string message,
                     std::string hint) {
    return scene_detail::errorAt(seen, fallback, keys, std::move(message), std::move(hint));
  };
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  const Domain& d = scene.domain;
  for (int i = 0; i < 3 && d.shape == DomainShape::Box; ++i) {  // a sphere ignores min, max
    if (!(d.min[i] < d.max[i])) {
      return errorAt({"domain.min", "domain.max"},
                     std::string("domain.min.") + kAxis[i] + " (" + formatDouble(d.min[i]) +
                         ") must be less than domain.max." + kAxis[i] + " (" +
                         formatDouble(d.max[i]) + ")",
                     "the domain is the box from min to max; each component of min must be "
                     "below the same component of max");
    }
  }
  const Camera& c = scene.render.camera;
  const Vec3 f{c.target[0] - c.eye[0], c.target[1] - c.eye[1], c.target[2] - c.eye[2]};
  if (f[0] == 0 && f[1] == 0 && f[2] == 0) {
    return errorAt({"camera.eye", "camera.target"},
                   "camera.eye and camera.target are the same point",
                   "the camera looks from eye towards target; move one of them");
  }
  const Vec3& u = c.up;
  const Vec3 cross{f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2], f[0] * u[1] - f[1] * u[0]};
  const double norm = std::hypot(cross[0], cross[1], cross[2]);
  // Relative test: an up vector along the view direction leaves the camera's right axis
  // undefined (right = normalize(forward x up)).
  if (norm <= 1e-9 * std::hypot(f[0], f[1], f[2]) * std::hypot(u[0], u[1], u[2])) {
    return errorAt({"camera.up", "camera.eye", "camera.target"},
                   "camera.up is parallel to the view direction (target - eye)",
                   "choose an up vector that is not along the line from eye to target");
  }
  return std::nullopt;
}

namespace {

// An error about formula[span] at its place in the source, `byteOffsets` mapping the
// formula's bytes to the source's.
SceneError formulaError(Span span, const SourceText& src,
                        const std::vector<std::size_t>& byteOffsets, std::string_view key,
                        const std::string& message, const std::string& hint) {
  const std::size_t last = byteOffsets.size() - 1;
  const std::size_t begin = byteOffsets[std::min(span.begin, last)];
  const std::size_t end = std::max(begin, byteOffsets[std::min(span.end, last)]);
  const std::string_view covered = src.text().substr(begin, end - begin);
  const int width = covered.find('\n') == std::string_view::npos ? codePoints(covered) : 1;
  return src.error(src.positionOf(begin), std::string(key), std::string(key) + ": " + message, hint,
                   width);
}

}  // namespace

std::optional<SceneError> checkFormula(std::string_view formula, const SourceText& src,
                                       const std::vector<std::size_t>& byteOffsets,
                                       std::string_view key) {
  const ParseResult parsed = parseFormula(formula);
  const ParseError* err = std::get_if<ParseError>(&parsed);
  if (!err) return std::nullopt;
  return formulaError(err->span, src, byteOffsets, key, err->message, err->hint);
}

std::optional<SceneError> checkFunctionOfXyz(std::string_view text, const SourceText& src,
                                             const std::vector<std::size_t>& byteOffsets,
                                             std::string_view key) {
  if (auto err = checkFormula(text, src, byteOffsets, key)) return err;
  const ParseResult parsed = parseFormula(text);
  const std::vector<std::string>& params = std::get<Formula>(parsed).graph.params();
  if (params.empty()) return std::nullopt;
  // Point at the parameter's first use as a whole word.
  std::size_t at = 0;
  for (std::size_t pos = text.find(params[0]); pos != std::string_view::npos;
       pos = text.find(params[0], pos + 1)) {
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    const std::size_t end = pos + params[0].size();
    if ((pos == 0 || !word(text[pos - 1])) && (end >= text.size() || !word(text[end]))) {
      at = pos;
      break;
    }
  }
  return formulaError({at, at + params[0].size()}, src, byteOffsets, key,
                      "\"" + params[0] +
                          "\" is a parameter; this function may use only x, y, z "
                          "and constants",
                      "write the value in its place, e.g. z - 0.5 rather than z - a");
}

std::optional<SceneError> applyDocument(Scene& scene, const toml::table& doc, const SourceText& src,
                                        KeyHistory* history) {
  KeyHistory own;
  KeyHistory& seen = history ? *history : own;
  Reader reader(scene, src, seen);
  if (auto err = reader.table(doc, "")) return err;
  return history ? std::nullopt : crossCheck(scene, seen, src);
}

}  // namespace zs::scene_detail
