// formatSceneError: the compiler-style one-line summary, then the source line with a caret
// under the offending text, then the hint.
#include <string>

#include "scene/scene_io.hpp"

namespace zs {

std::string formatSceneError(const SceneError& e) {
  std::string out = e.file;
  if (e.line > 0) out += ":" + std::to_string(e.line) + ":" + std::to_string(e.column);
  out += ": error: " + e.message + "\n";
  if (e.line > 0 && !e.sourceLine.empty()) {
    out += "  " + e.sourceLine + "\n  ";
    // Copy tabs from the source so the caret lines up however the terminal sets tab stops;
    // everything else becomes one space per code point.
    int col = 1;
    for (const char c : e.sourceLine) {
      if (col >= e.column) break;
      if ((static_cast<unsigned char>(c) & 0xC0) == 0x80) continue;
      out += c == '\t' ? '\t' : ' ';
      ++col;
    }
    out += "^" + std::string(static_cast<std::size_t>(e.width > 1 ? e.width - 1 : 0), '~') + "\n";
  }
  if (!e.hint.empty()) out += "  hint: " + e.hint + "\n";
  return out;
}

std::string formatSceneWarning(const SceneError& warning) {
  std::string text = formatSceneError(warning);
  const std::size_t at = text.find(": error: ");
  if (at != std::string::npos) text.replace(at, 9, ": warning: ");
  return text;
}

}  // namespace zs
