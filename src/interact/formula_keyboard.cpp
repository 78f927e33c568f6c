#include "interact/formula_keyboard.hpp"

#include <algorithm>
#include <cctype>

#include "i18n/translate.hpp"

namespace zs::interact {
namespace {

// The rows of a calculator, with the variables and the square on top, where a visitor
// starts.
constexpr FormulaKeyRows kRows{{
    {"x", "y", "z", "a", "^2", "^", "(", ")", "<-"},
    {"7", "8", "9", "+", "-", "sin", "cos", "sqrt", N_("clear")},
    {"4", "5", "6", "*", "/", "exp", "abs", "pi", ""},
    {"1", "2", "3", "0", ".", "b", "c", "e", N_("draw")},
}};

constexpr std::array<std::string_view, 8> kFunctions{"sin", "cos", "tan", "sqrt",
                                                     "exp", "log", "abs", "atan"};

bool isFunction(std::string_view key) {
  return std::find(kFunctions.begin(), kFunctions.end(), key) != kFunctions.end();
}

}  // namespace

std::pair<int, int> findFormulaKey(std::string_view label) {
  for (std::size_t r = 0; r < kRows.size(); ++r) {
    for (std::size_t c = 0; c < kRows[r].size(); ++c) {
      if (!label.empty() && kRows[r][c] == label) return {int(r), int(c)};
    }
  }
  return {-1, -1};
}

const FormulaKeyRows& formulaKeyRows() {
  return kRows;
}

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
  if (key == "draw" || findFormulaKey(key).first < 0) return text;
  // A name and what follows it would run together into one longer name (a x into the
  // parameter "ax", x 2 into "x2"): a space keeps them a product.
  const auto isNameChar = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  };
  std::size_t start = text.size();
  while (start > 0 && isNameChar(text[start - 1])) --start;
  const bool endsInName =
      start < text.size() && std::isalpha(static_cast<unsigned char>(text[start])) != 0;
  const bool space = endsInName && isNameChar(key.front());
  return text + (space ? " " : "") + std::string(key) + (isFunction(key) ? "(" : "");
}

}  // namespace zs::interact
