#pragma once
// One TOML value into one scene field: takes a toml++ node and the key's schema row, checks
// the type (booleans, integers, finite numbers, vectors of exactly 3 numbers, enum words)
// and the range, and stores the value or returns an error pointing at the value.
#include <toml++/toml.h>

#include <optional>
#include <string>

#include "scene/schema.hpp"
#include "scene/source_text.hpp"

namespace zs::scene_detail {

Position positionOf(const toml::node& node);
Position positionOf(const toml::key& key);

// "string", "integer", "array", ... for messages.
std::string typeName(const toml::node& node);

// Shortest text that reads back to exactly `v` (std::to_chars), always spelled as a TOML
// float ("1.0", not "1"), with "nan"/"inf" for non-finite values.
std::string formatDouble(double v);

std::optional<SceneError> readLeaf(Scene& scene, const KeySpec& spec, const toml::node& node,
                                   const SourceText& src);

// A finite number (integer or float) anywhere in `range`, for keys outside the schema
// (params).
std::optional<SceneError> readNumber(const toml::node& node, const std::string& key,
                                     const Range& range, const SourceText& src, double& out);

}  // namespace zs::scene_detail
