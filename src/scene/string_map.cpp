#include "scene/string_map.hpp"

#include <algorithm>
#include <string>

namespace zs::scene_detail {

namespace {

bool isHex(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

// Bytes that the UTF-8 encoding of \uXXXX or \UXXXXXXXX at `pos` (just after the 'u'/'U')
// occupies in the value.
std::size_t utf8Length(std::string_view text, std::size_t pos, std::size_t digits) {
  unsigned long cp = 0;
  for (std::size_t i = 0; i < digits && pos + i < text.size() && isHex(text[pos + i]); ++i) {
    const char c = text[pos + i];
    cp = cp * 16 + static_cast<unsigned long>(c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10);
  }
  return cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4;
}

}  // namespace

std::vector<std::size_t> stringSourceMap(std::string_view text, std::size_t quoteOffset,
                                         std::string_view value) {
  std::vector<std::size_t> map;
  map.reserve(value.size() + 1);
  const char quote = quoteOffset < text.size() ? text[quoteOffset] : '"';
  const bool multiline = text.substr(quoteOffset, 3) == std::string(3, quote);
  const bool basic = quote == '"';
  std::size_t pos = quoteOffset + (multiline ? 3 : 1);
  // TOML drops a newline that immediately follows the opening delimiter.
  if (multiline && text.substr(pos, 2) == "\r\n")
    pos += 2;
  else if (multiline && text.substr(pos, 1) == "\n")
    pos += 1;

  // The decoded value guides the walk: it says how many bytes are left and tells a '\r' the
  // parser dropped from one it kept.
  while (map.size() < value.size() && pos < text.size()) {
    const char c = text[pos];
    if (c == '\r' && value[map.size()] != '\r') {
      ++pos;
      continue;
    }
    if (!basic || c != '\\' || pos + 1 >= text.size()) {
      map.push_back(pos++);
      continue;
    }
    const char e = text[pos + 1];
    if (e == 'u' || e == 'U') {
      const std::size_t digits = e == 'u' ? 4 : 8;
      for (std::size_t n = utf8Length(text, pos + 2, digits); n > 0; --n) map.push_back(pos);
      pos += 2 + digits;
    } else if (e == ' ' || e == '\t' || e == '\r' || e == '\n') {
      // A line-ending backslash: it and all whitespace up to the next text vanish.
      ++pos;
      while (pos < text.size() &&
             (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r' || text[pos] == '\n')) {
        ++pos;
      }
    } else {
      map.push_back(pos);
      pos += 2;
    }
  }
  while (map.size() < value.size()) map.push_back(pos < text.size() ? pos : text.size());
  map.push_back(std::min(pos, text.size()));
  return map;
}

}  // namespace zs::scene_detail
