#include "i18n/po.hpp"

#include <optional>
#include <unordered_set>

namespace zs::i18n {
namespace {

// The quoted string that starts `line` (after optional blanks), with its escapes undone;
// nothing, and `error` says why, when the line holds no well-formed string.
std::optional<std::string> quoted(std::string_view line, std::string& error) {
  std::size_t i = 0;
  while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
  if (i >= line.size() || line[i] != '"') {
    error = "expected a string in double quotes";
    return std::nullopt;
  }
  std::string out;
  for (++i; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      for (++i; i < line.size(); ++i)
        if (line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
          error = "text after the closing quote";
          return std::nullopt;
        }
      return out;
    }
    if (c != '\\') {
      out += c;
      continue;
    }
    if (++i >= line.size()) break;
    switch (line[i]) {
      case 'n':
        out += '\n';
        break;
      case 't':
        out += '\t';
        break;
      case 'r':
        out += '\r';
        break;
      case '"':
        out += '"';
        break;
      case '\\':
        out += '\\';
        break;
      default:
        error = std::string("unknown escape \\") + line[i];
        return std::nullopt;
    }
  }
  error = "the string has no closing quote";
  return std::nullopt;
}

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::string headerField(const std::string& header, std::string_view name) {
  std::size_t at = 0;
  while (at < header.size()) {
    const std::size_t end = header.find('\n', at);
    const std::string_view line(header.data() + at,
                                (end == std::string::npos ? header.size() : end) - at);
    if (startsWith(line, name) && line.size() > name.size() && line[name.size()] == ':') {
      std::string_view v = line.substr(name.size() + 1);
      while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
      while (!v.empty() && (v.back() == ' ' || v.back() == '\r')) v.remove_suffix(1);
      return std::string(v);
    }
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return {};
}

}  // namespace

std::variant<Catalog, PoError> parsePo(std::string_view text) {
  Catalog catalog;
  std::string id, str;
  bool haveId = false, haveStr = false, fuzzy = false;
  int idLine = 0;  // where the message being read starts
  std::optional<std::string> header;

  std::unordered_set<std::string> seen;
  std::optional<int> duplicate;  // the line of the first msgid seen twice
  auto finish = [&]() {
    if (haveId && haveStr) {
      if (id.empty())
        header = str;
      else if (!seen.insert(id).second)
        duplicate = duplicate.value_or(idLine);
      else if (!fuzzy && !str.empty())
        catalog.messages[id] = str;
    }
    id.clear();
    str.clear();
    haveId = haveStr = fuzzy = false;
  };

  int lineNumber = 0;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = text.find('\n', at);
    std::string_view line =
        text.substr(at, (end == std::string_view::npos ? text.size() : end) - at);
    at = end == std::string_view::npos ? text.size() + 1 : end + 1;
    ++lineNumber;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    if (line.empty()) {  // messages are separated by blank lines: flags do not carry over
      if (haveStr)
        finish();
      else if (!haveId)
        fuzzy = false;
      continue;
    }
    std::string error;
    if (line[0] == '#') {
      // Flags belong to the next message; obsolete ones ("#~", kept by msgmerge for the
      // translators) and the other comments are not part of the catalog.
      if (startsWith(line, "#,")) {
        if (haveStr) finish();
        if (line.find("fuzzy") != std::string_view::npos) fuzzy = true;
      }
      continue;
    }
    if (startsWith(line, "msgctxt") || startsWith(line, "msgid_plural") ||
        startsWith(line, "msgstr[")) {
      return PoError{lineNumber,
                     "contexts and plural forms are not used by zeroset's "
                     "messages; write one msgid and one msgstr"};
    }
    if (startsWith(line, "msgid")) {
      if (haveId) {
        if (!haveStr) return PoError{lineNumber, "a msgid without a msgstr before it"};
        finish();  // a "#," line after the last entry has finished it already
      }
      auto s = quoted(line.substr(5), error);
      if (!s) return PoError{lineNumber, error};
      id = *s;
      haveId = true;
      idLine = lineNumber;
      continue;
    }
    if (startsWith(line, "msgstr")) {
      if (!haveId || haveStr) return PoError{lineNumber, "a msgstr without its msgid"};
      auto s = quoted(line.substr(6), error);
      if (!s) return PoError{lineNumber, error};
      str = *s;
      haveStr = true;
      continue;
    }
    if (line[0] == '"') {
      auto s = quoted(line, error);
      if (!s) return PoError{lineNumber, error};
      if (haveStr)
        str += *s;  // continues the msgstr, or the msgid before it
      else if (haveId)
        id += *s;
      else
        return PoError{lineNumber, "a continued string outside a msgid or msgstr"};
      continue;
    }
    return PoError{lineNumber, "expected msgid, msgstr, a quoted string or a # comment"};
  }
  if (haveId && !haveStr) return PoError{idLine, "this msgid has no msgstr"};
  finish();
  if (duplicate)
    return PoError{*duplicate, "this msgid is in the file twice; keep one (msgfmt refuses it too)"};
  if (header) catalog.language = headerField(*header, "Language");
  return catalog;
}

}  // namespace zs::i18n
