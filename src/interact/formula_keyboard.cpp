#include "interact/formula_keyboard.hpp"

#include <algorithm>

namespace zs::interact {
namespace {

// The rows of a calculator, with the variables and the square on top, where a visitor
// starts.
constexpr FormulaKeyRows kRows{{
    {"x", "y", "z", "a", "^2", "^", "(", ")", "<-"},
    {"7", "8", "9", "+", "-", "sin", "cos", "sqrt", "clear"},
    {"4", "5", "6", "*", "/", "exp", "abs", "pi", ""},
    {"1", "2", "3", "0", ".", "b", "c", "e", "draw"},
}};

constexpr std::array<std::string_view, 8> kFunctions{"sin", "cos", "tan", "sqrt", "exp",
                                                     "log", "abs", "atan"};

bool isFunction(std::string_view key) {
  return std::find(kFunctions.begin(), kFunctions.end(), key) != kFunctions.end();
}

bool isKey(std::string_view key) {
  for (const auto& row : kRows) {
    if (!key.empty() && std::find(row.begin(), row.end(), key) != row.end()) return true;
  }
  return false;
}

}  // namespace

const FormulaKeyRows& formulaKeyRows() { return kRows; }

std::string pressFormulaKey(const std::string& text, std::string_view key) {
  if (key == "clear") return "";
  if (key == "<-") {
    for (std::string_view f : kFunctions) {
      const std::string call = std::string(f) + "(";
      if (text.size() >= call.size() &&
          text.compare(text.size() - call.size(), call.size(), call) == 0)
        return text.substr(0, text.size() - call.size());
    }
    std::size_t end = text.size();
    // One character, not one byte: step back over UTF-8 continuation bytes.
    while (end > 0 && (static_cast<unsigned char>(text[end - 1]) & 0xC0) == 0x80) --end;
    return text.substr(0, end > 0 ? end - 1 : 0);
  }
  if (key == "draw" || !isKey(key)) return text;
  return text + std::string(key) + (isFunction(key) ? "(" : "");
}

}  // namespace zs::interact
