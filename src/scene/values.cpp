#include "scene/values.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "expr/number_text.hpp"
#include "scene/hints.hpp"
#include "scene/reader.hpp"
#include "scene/string_map.hpp"

namespace zs::scene_detail {

namespace {

std::string rangeText(const Range& r, bool integer) {
  auto num = [&](double v) {
    return integer ? std::to_string(static_cast<long long>(v)) : formatDouble(v);
  };
  if (std::isinf(r.hi)) return std::string(r.loOpen ? "> " : ">= ") + num(r.lo);
  return std::string(r.loOpen ? "(" : "[") + num(r.lo) + ", " + num(r.hi) + (r.hiOpen ? ")" : "]");
}

SceneError typeError(const toml::node& node, const std::string& key, std::string_view expected,
                     const SourceText& src) {
  std::string hint;
  if (expected.starts_with("a vector") && node.is_number()) hint = "write a vector as [x, y, z]";
  if (expected == "an integer" && node.is_floating_point())
    hint = "write it without a decimal point";
  if (expected == "a boolean" && node.is_string()) hint = "write true or false without quotes";
  if (expected == "a string" && !node.is_string()) hint = "put the text in double quotes";
  return src.error(positionOf(node), key,
                   key + " must be " + std::string(expected) + ", got " + typeName(node), hint);
}

std::optional<SceneError> readInteger(const toml::node& node, const KeySpec& spec,
                                      const SourceText& src, std::int64_t& out) {
  const std::string key(spec.name);
  if (!node.is_integer()) return typeError(node, key, "an integer", src);
  out = *node.value<std::int64_t>();
  if (!spec.range.contains(static_cast<double>(out))) {
    return src.error(
        positionOf(node), key,
        key + " must be " + rangeText(spec.range, true) + ", got " + std::to_string(out));
  }
  return std::nullopt;
}

std::optional<SceneError> readVector(const toml::node& node, const KeySpec& spec,
                                     const SourceText& src, Vec3& out) {
  const std::string key(spec.name);
  const toml::array* array = node.as_array();
  if (!array) return typeError(node, key, "a vector of 3 numbers", src);
  if (array->size() != 3) {
    return src.error(positionOf(node), key,
                     key + " must have exactly 3 numbers, got " + std::to_string(array->size()),
                     "write a vector as [x, y, z]");
  }
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  Vec3 v{};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string component = key + "." + kAxis[i];
    if (auto err = readNumber((*array)[i], component, spec.range, src, v[i])) return err;
  }
  if (spec.nonZero && v[0] == 0 && v[1] == 0 && v[2] == 0) {
    return src.error(positionOf(node), key, key + " must not be the zero vector",
                     "it is a direction and gets normalized; any non-zero length works");
  }
  out = v;
  return std::nullopt;
}

}  // namespace

Position positionOf(const toml::node& node) {
  const auto& b = node.source().begin;
  return {static_cast<int>(b.line), static_cast<int>(b.column)};
}

Position positionOf(const toml::key& key) {
  const auto& b = key.source().begin;
  return {static_cast<int>(b.line), static_cast<int>(b.column)};
}

std::string typeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::none:
      return "nothing";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
  }
  return "an unknown value";
}

std::string formatDouble(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::string s = shortestText(v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::optional<SceneError> readNumber(const toml::node& node, const std::string& key,
                                     const Range& range, const SourceText& src, double& out) {
  if (!node.is_number()) {
    return src.error(positionOf(node), key, key + " must be a number, got " + typeName(node));
  }
  const double v = *node.value<double>();
  if (!std::isfinite(v)) {
    return src.error(positionOf(node), key,
                     key + " must be a finite number, got " + formatDouble(v));
  }
  if (!range.contains(v)) {
    return src.error(positionOf(node), key,
                     key + " must be " + rangeText(range, false) + ", got " + formatDouble(v));
  }
  out = v;
  return std::nullopt;
}

std::optional<SceneError> readLeaf(Scene& scene, const KeySpec& spec, const toml::node& node,
                                   const SourceText& src) {
  const std::string key(spec.name);
  return std::visit(
      [&](const auto& ref) -> std::optional<SceneError> {
        using Ref = std::decay_t<decltype(ref)>;
        if constexpr (std::is_same_v<Ref, BoolRef>) {
          if (!node.is_boolean()) return typeError(node, key, "a boolean", src);
          ref(scene) = *node.value<bool>();
        } else if constexpr (std::is_same_v<Ref, IntRef> || std::is_same_v<Ref, SizeRef>) {
          std::int64_t v = 0;
          if (auto err = readInteger(node, spec, src, v)) return err;
          ref(scene) = static_cast<std::remove_reference_t<decltype(ref(scene))>>(v);
        } else if constexpr (std::is_same_v<Ref, RealRef>) {
          return readNumber(node, key, spec.range, src, ref(scene));
        } else if constexpr (std::is_same_v<Ref, VecRef>) {
          return readVector(node, spec, src, ref(scene));
        } else if constexpr (std::is_same_v<Ref, FunctionRef>) {
          if (!node.is_string()) return typeError(node, key, "a string", src);
          std::string text = *node.value<std::string>();
          const auto offsets = stringSourceMap(src.text(), src.offsetOf(positionOf(node)), text);
          if (auto err = spec.takesParams ? checkFormula(text, src, offsets, key)
                                          : checkFunctionOfXyz(text, src, offsets, key))
            return err;
          ref(scene) = std::move(text);
        } else {
          static_assert(std::is_same_v<Ref, EnumRef>);
          if (!node.is_string()) return typeError(node, key, "a string", src);
          const std::string word = *node.value<std::string>();
          for (std::size_t i = 0; i < ref.names.size(); ++i) {
            if (ref.names[i] == word) {
              ref.set(scene, static_cast<int>(i));
              return std::nullopt;
            }
          }
          return src.error(positionOf(node), key, key + " has no option \"" + word + "\"",
                           choiceHint(word, ref.names));
        }
        return std::nullopt;
      },
      spec.field);
}

}  // namespace zs::scene_detail
