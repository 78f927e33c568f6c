#include "scene/description.hpp"

#include <algorithm>

namespace zs {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

}  // namespace

std::string sceneDescription(std::string_view text) {
  std::string out;
  bool started = false;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = trim(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    if (line.empty() && !started) continue;
    if (line.empty() || line.front() != '#') break;
    started = true;
    const std::size_t hashes = line.find_first_not_of('#');
    const std::string_view words =
        trim(hashes == std::string_view::npos ? "" : line.substr(hashes));
    if (words.empty()) continue;
    if (!out.empty()) out += ' ';
    out += words;
  }
  return out;
}

std::string summaryLine(std::string_view text) {
  const std::string description = sceneDescription(text);
  // The first comment line, as sceneDescription strips it.
  const std::string first = sceneDescription(text.substr(
      0, text.find('#') == std::string_view::npos ? 0 : text.find('\n', text.find('#'))));
  if (first.find(" \u2014 ") != std::string::npos && first.find(": ") != std::string::npos)
    return first;
  std::string_view s = description;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (s[i] == '.' && (s[i + 1] == ' ' || s[i + 1] == '\t'))
      return std::string(s.substr(0, i + 1));
  }
  return std::string(s);
}

std::string shortened(std::string_view s, std::size_t maxChars) {
  std::size_t points = 0;
  std::size_t cut = s.size();  // byte where the (maxChars - 3)th code point ends
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) continue;
    if (points == (maxChars > 3 ? maxChars - 3 : 0)) cut = std::min(cut, i);
    ++points;
  }
  if (points <= maxChars) return std::string(s);
  // Shorten at a word boundary when there is one in the last third.
  const std::size_t space = s.substr(0, cut).rfind(' ');
  if (space != std::string_view::npos && space > cut * 2 / 3) cut = space;
  return std::string(trim(s.substr(0, cut))) + "...";
}

}  // namespace zs
