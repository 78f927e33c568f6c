#include "jsurf/value_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "expr/number_text.hpp"

namespace zs::jsurf {
namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

}  // namespace

ValueReader::ValueReader(std::string_view text, std::string_view fileName) : file_(fileName) {
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == '\n' || text[i] == '\r') {
      lines_.push_back(text.substr(start, i - start));
      if (i + 1 < text.size() && text[i] == '\r' && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
}

SceneError ValueReader::at(const Property& p, std::size_t offset, std::string message,
                           std::string hint, int width) const {
  const TextPos pos = p.valuePos[std::min(offset, p.valuePos.size() - 1)];
  SceneError e;
  e.file = file_;
  e.line = pos.line;
  e.column = pos.column;
  e.key = p.key;
  e.message = std::move(message);
  e.hint = std::move(hint);
  e.width = width;
  if (pos.line >= 1 && static_cast<std::size_t>(pos.line) <= lines_.size())
    e.sourceLine = std::string(lines_[static_cast<std::size_t>(pos.line - 1)]);
  return e;
}

SceneError ValueReader::atKey(const Property& p, std::string message, std::string hint) const {
  SceneError e = at(p, 0, std::move(message), std::move(hint));
  e.line = p.keyPos.line;
  e.column = p.keyPos.column;
  if (p.keyPos.line >= 1 && static_cast<std::size_t>(p.keyPos.line) <= lines_.size())
    e.sourceLine = std::string(lines_[static_cast<std::size_t>(p.keyPos.line - 1)]);
  return e;
}

SceneError ValueReader::nowhere(std::string key, std::string message, std::string hint) const {
  SceneError e;
  e.file = file_;
  e.key = std::move(key);
  e.message = std::move(message);
  e.hint = std::move(hint);
  return e;
}

std::optional<std::vector<double>> ValueReader::numbers(const Property& p, std::size_t count,
                                                        SceneError& error) const {
  std::vector<double> out;
  const std::string& v = p.value;
  std::size_t i = 0;
  for (;;) {
    while (i < v.size() && isSpace(v[i])) ++i;
    if (i >= v.size()) break;
    std::size_t end = i;
    while (end < v.size() && !isSpace(v[end])) ++end;
    const std::string_view word(v.data() + i, end - i);
    if (out.size() == count) {
      error = at(p, i, p.key + " takes " + std::to_string(count) + " numbers; this one is extra");
      return std::nullopt;
    }
    // from_chars does not take a leading '+', which Java does.
    const std::string_view digits = word.starts_with('+') ? word.substr(1) : word;
    const std::optional<double> parsed = parseDecimal(digits);
    const double x = parsed.value_or(0);
    if (!parsed || !std::isfinite(x)) {
      error = at(p, i, "'" + std::string(word) + "' is not a finite number",
                 "write numbers like 0.5 or -1.25e-3, separated by spaces",
                 static_cast<int>(word.size()));
      return std::nullopt;
    }
    out.push_back(x);
    i = end;
  }
  if (out.size() < count) {
    error = at(
        p, v.size(),
        p.key + " takes " + std::to_string(count) + " numbers, found " + std::to_string(out.size()),
        count == 16 ? "a 4x4 matrix is 16 numbers, row by row" : "");
    return std::nullopt;
  }
  return out;
}

std::optional<double> ValueReader::number(const Property& p, SceneError& error) const {
  auto n = numbers(p, 1, error);
  if (!n) return std::nullopt;
  return n->front();
}

}  // namespace zs::jsurf
