#include "scene/source_text.hpp"

#include <algorithm>
#include <utility>

namespace zs::scene_detail {

namespace {
bool isContinuation(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}
}  // namespace

int codePoints(std::string_view utf8) {
  return static_cast<int>(
      std::count_if(utf8.begin(), utf8.end(), [](char c) { return !isContinuation(c); }));
}

SourceText::SourceText(std::string_view file, std::string_view text) : file_(file), text_(text) {
  lineStarts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') lineStarts_.push_back(i + 1);
  }
}

std::size_t SourceText::offsetOf(Position pos) const {
  if (pos.line < 1) return 0;
  if (static_cast<std::size_t>(pos.line) > lineStarts_.size()) return text_.size();
  std::size_t offset = lineStarts_[static_cast<std::size_t>(pos.line) - 1];
  // Walk code points, so a column after a multi-byte character lands on the right byte.
  for (int col = 1; col < pos.column && offset < text_.size() && text_[offset] != '\n'; ++col) {
    ++offset;
    while (offset < text_.size() && isContinuation(text_[offset])) ++offset;
  }
  return offset;
}

Position SourceText::positionOf(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  const auto line = static_cast<int>(it - lineStarts_.begin());
  const std::size_t start = lineStarts_[static_cast<std::size_t>(line) - 1];
  return {line, codePoints(text_.substr(start, offset - start)) + 1};
}

std::string_view SourceText::lineText(int line) const {
  if (line < 1 || static_cast<std::size_t>(line) > lineStarts_.size()) return {};
  const std::size_t start = lineStarts_[static_cast<std::size_t>(line) - 1];
  std::size_t end = text_.find('\n', start);
  if (end == std::string_view::npos) end = text_.size();
  if (end > start && text_[end - 1] == '\r') --end;
  return text_.substr(start, end - start);
}

SceneError SourceText::error(Position pos, std::string key, std::string message, std::string hint,
                             int width) const {
  SceneError e;
  e.file = file_;
  e.line = pos.line;
  e.column = pos.column;
  e.key = std::move(key);
  e.message = std::move(message);
  e.hint = std::move(hint);
  e.sourceLine = std::string(lineText(pos.line));
  e.width = std::max(width, 1);
  return e;
}

}  // namespace zs::scene_detail
