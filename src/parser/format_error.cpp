#include <algorithm>

#include "i18n/translate.hpp"
#include "parser/parser.hpp"

namespace zs {

namespace {

constexpr std::size_t kWindow = 72;  // characters of formula shown around a long error

bool isContinuationByte(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// One display column per code point; control bytes shown as '?', so the caret stays aligned.
struct Display {
  std::string text;
  std::vector<std::size_t> columnOfByte;  // size = bytes + 1
};

Display displayOf(std::string_view s) {
  Display d;
  std::size_t column = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    d.columnOfByte.push_back(column);
    const auto c = static_cast<unsigned char>(s[i]);
    if (isContinuationByte(s[i])) {
      d.text += s[i];
      continue;
    }
    d.text += (c < 0x20 || c == 0x7f) ? '?' : s[i];
    ++column;
  }
  d.columnOfByte.push_back(column);
  return d;
}

// Cuts the displayed text to the columns [from, to), keeping UTF-8 sequences whole.
std::string columns(std::string_view text, std::size_t from, std::size_t to) {
  std::string out;
  std::size_t column = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!isContinuationByte(text[i]) && i > 0) ++column;
    if (i == 0) column = 0;
    if (column >= from && column < to) out += text[i];
  }
  return out;
}

}  // namespace

std::string formatError(std::string_view text, const ParseError& error) {
  const Display d = displayOf(text);
  const std::size_t total = d.columnOfByte.back();
  const std::size_t b = std::min(error.span.begin, text.size());
  const std::size_t e = std::clamp(error.span.end, b, text.size());
  const std::size_t c0 = d.columnOfByte[b], c1 = std::max(d.columnOfByte[e], c0 + 1);
  std::size_t from = 0, to = total;
  std::string prefix, suffix;
  if (total > kWindow) {
    from = c0 > kWindow / 2 ? c0 - kWindow / 2 : 0;
    to = std::min(total, from + kWindow);
    if (from > 0) prefix = "...";
    if (to < total) suffix = "...";
  }
  std::string out = "  " + prefix + columns(d.text, from, to) + suffix + "\n";
  const std::size_t caretStart = c0 - from + prefix.size();
  const std::size_t caretLen = std::min(c1, to + 1) - c0;
  out += "  " + std::string(caretStart, ' ') +
         std::string(std::max<std::size_t>(caretLen, 1), '^') + "\n";
  out += i18n::format(i18n::tr("error: %s (at column %zu)"), error.message.c_str(), c0 + 1) + "\n";
  if (!error.hint.empty()) out += i18n::format(i18n::tr("hint: %s"), error.hint.c_str()) + "\n";
  return out;
}

}  // namespace zs
