#pragma once
// A text being read (a .surf file, a --set assignment, a formula) with its line table:
// converts toml++ positions (line, column in code points) to byte offsets and back, and
// builds SceneErrors that carry the offending line for the caret.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_io.hpp"

namespace zs::scene_detail {

struct Position {
  int line = 0;  // 1-based; 0 = unknown
  int column = 0;
};

class SourceText {
 public:
  SourceText(std::string_view file, std::string_view text);

  std::string_view file() const { return file_; }
  std::string_view text() const { return text_; }
  std::size_t offsetOf(Position pos) const;       // clamped to the text
  Position positionOf(std::size_t offset) const;  // offset clamped to the text
  std::string_view lineText(int line) const;      // without the line break

  SceneError error(Position pos, std::string key, std::string message, std::string hint = {},
                   int width = 1) const;

 private:
  std::string file_;
  std::string_view text_;
  std::vector<std::size_t> lineStarts_;
};

// Code points in a UTF-8 byte range (continuation bytes are not counted).
int codePoints(std::string_view utf8);

}  // namespace zs::scene_detail
