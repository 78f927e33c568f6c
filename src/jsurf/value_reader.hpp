#pragma once
// Reads the values of .jsurf properties — numbers, vectors, colours, 4x4 matrices, words —
// the way Java's Scanner and parseDouble would, and turns a problem into a SceneError that
// points at the offending character of the file (with the line shown for the caret).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jsurf/properties.hpp"
#include "scene/scene_io.hpp"

namespace zs::jsurf {

class ValueReader {
 public:
  ValueReader(std::string_view text, std::string_view fileName);

  // An error (or warning) at byte `offset` of the property's value, `width` code points wide.
  SceneError at(const Property& p, std::size_t offset, std::string message, std::string hint = {},
                int width = 1) const;
  // At the property's key.
  SceneError atKey(const Property& p, std::string message, std::string hint = {}) const;
  // With no place in the text (a key that is missing).
  SceneError nowhere(std::string key, std::string message, std::string hint = {}) const;

  // Exactly `count` whitespace-separated finite numbers; extra ones are an error too, since
  // they are almost surely a mistake in a hand-written file.
  std::optional<std::vector<double>> numbers(const Property& p, std::size_t count,
                                             SceneError& error) const;
  std::optional<double> number(const Property& p, SceneError& error) const;

 private:
  std::string file_;
  std::vector<std::string_view> lines_;
};

}  // namespace zs::jsurf
