#pragma once
// Applies a parsed TOML document onto a Scene: takes the toml++ table, the source text it
// came from and the scene to change; walks the keys in file order through the schema, parses
// the formula, checks the keys that constrain each other (domain, camera) and returns the
// first error. Shared by parseScene (onto defaults) and applyOverride (onto the current
// scene). The scene may be partly changed when an error is returned.
#include <toml++/toml.h>

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "scene/source_text.hpp"

namespace zs::scene_detail {

std::optional<SceneError> applyDocument(Scene& scene, const toml::table& doc,
                                        const SourceText& src);

// Parses `formula`; on error, places the parser's byte span at the source position the
// formula's bytes were read from (`byteOffsets`: one source offset per formula byte, plus
// one past the end), with the caret's width covering the span when it stays on one line.
std::optional<SceneError> checkFormula(std::string_view formula, const SourceText& src,
                                       const std::vector<std::size_t>& byteOffsets);

}  // namespace zs::scene_detail
