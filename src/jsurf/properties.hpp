#pragma once
// Java .properties text, the container format of SURFER's .jsurf files: takes the text and
// puts out its key/value pairs in file order, each with the line and column of its key and
// of every byte of its value (escapes and continued lines make the two differ), so that an
// error inside a value — a formula, say — can point at the very character. Reading never
// fails: Java's Properties.load accepts any text, and so does this.
#include <string>
#include <string_view>
#include <vector>

namespace zs::jsurf {

struct TextPos {
  int line = 0;    // 1-based
  int column = 0;  // 1-based, in code points
};

struct Property {
  std::string key;
  std::string value;  // escapes decoded (\uXXXX becomes UTF-8)
  TextPos keyPos;
  std::vector<TextPos> valuePos;  // one per byte of `value`, plus one past its end
};

std::vector<Property> readProperties(std::string_view text);

// `text` escaped so that readProperties gives it back as a value (or, with isKey, a key).
std::string escapeProperty(std::string_view text, bool isKey = false);

}  // namespace zs::jsurf
