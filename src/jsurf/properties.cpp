// The rules are those of java.util.Properties.load: a logical line continues while a
// natural line ends in an odd number of backslashes; leading blanks are skipped on every
// natural line; '#' or '!' first makes a comment; the key ends at an unescaped '=', ':' or
// blank, and one '=' or ':' with blanks around it separates it from the value.
#include "jsurf/properties.hpp"

#include <cstdint>

namespace zs::jsurf {
namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\f';
}
bool isLineEnd(char c) {
  return c == '\n' || c == '\r';
}

// One character of the logical line with where it came from.
struct Char {
  char c;
  TextPos pos;
};

class Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {}
  bool done() const { return i_ >= text_.size(); }
  char peek() const { return text_[i_]; }
  TextPos pos() const { return {line_, column_}; }
  void advance() {
    const char c = text_[i_++];
    if (c == '\n' || (c == '\r' && (done() || text_[i_] != '\n'))) {
      ++line_;
      column_ = 1;
    } else if (c != '\r' && (static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++column_;
    }
  }

 private:
  std::string_view text_;
  std::size_t i_ = 0;
  int line_ = 1;
  int column_ = 1;
};

// The next logical line, continuations joined, leading blanks of each natural line dropped;
// a comment line comes back empty.
std::vector<Char> logicalLine(Cursor& in) {
  std::vector<Char> out;
  while (!in.done() && (isBlank(in.peek()) || isLineEnd(in.peek()))) in.advance();
  if (in.done()) return out;
  if (in.peek() == '#' || in.peek() == '!') {
    while (!in.done() && !isLineEnd(in.peek())) in.advance();
    return out;
  }
  for (;;) {
    while (!in.done() && !isLineEnd(in.peek())) {
      out.push_back({in.peek(), in.pos()});
      in.advance();
    }
    std::size_t backslashes = 0;
    while (backslashes < out.size() && out[out.size() - 1 - backslashes].c == '\\') ++backslashes;
    if (backslashes % 2 == 0 || in.done()) {
      if (backslashes % 2 == 1) out.pop_back();  // a final lone backslash is dropped
      return out;
    }
    out.pop_back();
    if (in.peek() == '\r') in.advance();
    if (!in.done() && in.peek() == '\n') in.advance();
    while (!in.done() && isBlank(in.peek())) in.advance();
  }
}

void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Decodes one character at line[i] (an escape or a plain byte) into out; returns the index
// after it.
std::size_t decodeOne(const std::vector<Char>& line, std::size_t i, std::string& out,
                      std::vector<TextPos>& pos) {
  const TextPos at = line[i].pos;
  const std::size_t before = out.size();
  if (line[i].c != '\\' || i + 1 >= line.size()) {
    out += line[i].c;
    ++i;
  } else {
    const char e = line[i + 1].c;
    i += 2;
    if (e == 'u') {
      std::uint32_t cp = 0;
      int digits = 0;
      while (digits < 4 && i < line.size() && hexValue(line[i].c) >= 0) {
        cp = cp * 16 + static_cast<std::uint32_t>(hexValue(line[i].c));
        ++i;
        ++digits;
      }
      // Java throws on a malformed \u; taking what is there is kinder and never worse.
      appendUtf8(out, cp);
    } else {
      out += e == 't' ? '\t' : e == 'n' ? '\n' : e == 'r' ? '\r' : e == 'f' ? '\f' : e;
    }
  }
  pos.insert(pos.end(), out.size() - before, at);
  return i;
}

}  // namespace

std::vector<Property> readProperties(std::string_view text) {
  std::vector<Property> props;
  Cursor in(text);
  while (!in.done()) {
    const std::vector<Char> line = logicalLine(in);
    if (line.empty()) continue;
    Property p;
    p.keyPos = line.front().pos;
    std::vector<TextPos> keyPos;
    std::size_t i = 0;
    while (i < line.size()) {
      const char c = line[i].c;
      if (c == '=' || c == ':' || isBlank(c)) break;
      i = decodeOne(line, i, p.key, keyPos);
    }
    while (i < line.size() && isBlank(line[i].c)) ++i;
    if (i < line.size() && (line[i].c == '=' || line[i].c == ':')) ++i;
    while (i < line.size() && isBlank(line[i].c)) ++i;
    while (i < line.size()) i = decodeOne(line, i, p.value, p.valuePos);
    TextPos end = line.back().pos;
    ++end.column;
    p.valuePos.push_back(end);
    props.push_back(std::move(p));
  }
  return props;
}

std::string escapeProperty(std::string_view text, bool isKey) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (c) {
      case '\\':
        out += "\\\\";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\f':
        out += "\\f";
        break;
      case '=':
      case ':':
      case '#':
      case '!':
        out += '\\';
        out += c;
        break;
      case ' ':
        // A leading blank of a value, and any blank of a key, would be dropped.
        if (isKey || i == 0) out += '\\';
        out += ' ';
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace zs::jsurf
