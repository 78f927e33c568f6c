#pragma once
// Applies a parsed TOML document onto a Scene: takes the toml++ table, the source text it
// came from and the scene to change; walks the keys in file order through the schema, parses
// the formula, checks the keys that constrain each other (domain, camera) and returns the
// first error. Shared by parseScene (onto defaults) and applyOverrides (onto the current
// scene). The scene may be partly changed when an error is returned.
#include <toml++/toml.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/source_text.hpp"

namespace zs::scene_detail {

// Where each key was written, in order, across one or more documents (the sources must
// outlive the history).
struct KeySet {
  std::string key;
  const SourceText* src;
  Position pos;
};
using KeyHistory = std::vector<KeySet>;

// Without `history` the document is complete: the keys that constrain each other are
// checked at its end. With it, the keys read are appended there and the check is left to
// the caller (crossCheck), which runs it once after the last document.
std::optional<SceneError> applyDocument(Scene& scene, const toml::table& doc, const SourceText& src,
                                        KeyHistory* history = nullptr);

// Domain min below max, eye apart from target, up not along the view: an error points at the
// latest-written of the keys involved (`fallback`'s start when no document wrote one).
std::optional<SceneError> crossCheck(const Scene& scene, const KeyHistory& seen,
                                     const SourceText& fallback);

// Parses `formula`; on error, places the parser's byte span at the source position the
// formula's bytes were read from (`byteOffsets`: one source offset per formula byte, plus
// one past the end), with the caret's width covering the span when it stays on one line.
std::optional<SceneError> checkFormula(std::string_view formula, const SourceText& src,
                                       const std::vector<std::size_t>& byteOffsets,
                                       std::string_view key = "formula");

// The same for a function of x, y, z that may not use parameters (a FunctionRef key).
std::optional<SceneError> checkFunctionOfXyz(std::string_view text, const SourceText& src,
                                             const std::vector<std::size_t>& byteOffsets,
                                             std::string_view key);

}  // namespace zs::scene_detail
