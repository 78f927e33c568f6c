#include "app/viewer/formula_keyboard.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace zs::app {
namespace {

// What each key writes; "sin" writes "sin(". The rows of a calculator, with the variables
// and the square on top, where a visitor starts.
constexpr std::array<std::array<std::string_view, 9>, 4> kRows{{
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

}  // namespace

std::string pressFormulaKey(const std::string& text, const std::string& key) {
  if (key == "clear") return "";
  if (key == "<-") {
    for (std::string_view f : kFunctions) {
      const std::string call = std::string(f) + "(";
      if (text.size() >= call.size() && text.compare(text.size() - call.size(), call.size(), call) == 0)
        return text.substr(0, text.size() - call.size());
    }
    std::size_t end = text.size();
    // One character, not one byte: step back over UTF-8 continuation bytes.
    while (end > 0 && (static_cast<unsigned char>(text[end - 1]) & 0xC0) == 0x80) --end;
    return text.substr(0, end > 0 ? end - 1 : 0);
  }
  return text + key + (isFunction(key) ? "(" : "");
}

std::pair<float, float> FormulaKeyboardLayout::centre(int row, int column) const {
  return {left + padding + float(column) * (key + gapX) + key / 2,
          top + padding + float(row) * (key + gapY) + key / 2};
}

FormulaKeyboardLayout formulaKeyboardLayout(float displayWidth, float displayHeight,
                                            float fontSize) {
  FormulaKeyboardLayout l;
  l.rows = int(kRows.size());
  l.columns = int(kRows[0].size());
  l.key = std::max(44.0f, fontSize * 2.8f);  // a fingertip and more
  l.gapX = l.gapY = std::round(l.key / 8);
  l.padding = l.gapX;
  const float width = float(l.columns) * l.key + float(l.columns - 1) * l.gapX + 2 * l.padding;
  const float height = float(l.rows) * l.key + float(l.rows - 1) * l.gapY + 2 * l.padding;
  l.left = std::max(0.0f, std::round((displayWidth - width) / 2));
  l.top = std::max(0.0f, displayHeight - 8 - height);
  return l;
}

std::optional<std::pair<int, int>> findFormulaKey(const std::string& label) {
  for (std::size_t r = 0; r < kRows.size(); ++r) {
    for (std::size_t c = 0; c < kRows[r].size(); ++c) {
      if (!label.empty() && kRows[r][c] == label) return std::pair{int(r), int(c)};
    }
  }
  return std::nullopt;
}

void drawFormulaKeyboard(PanelState& state, PanelResult& result) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const FormulaKeyboardLayout l = formulaKeyboardLayout(display.x, display.y, ImGui::GetFontSize());
  ImGui::SetNextWindowPos(ImVec2(l.left, l.top), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(l.padding, l.padding));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(l.gapX, l.gapY));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                     ImGuiWindowFlags_AlwaysAutoResize |
                                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("formula keyboard", nullptr, flags)) {
    for (const auto& row : kRows) {
      for (std::size_t i = 0; i < row.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        const std::string label(row[i]);
        if (label.empty()) {
          ImGui::Dummy(ImVec2(l.key, l.key));
          continue;
        }
        if (!ImGui::Button(label.c_str(), ImVec2(l.key, l.key))) continue;
        if (label == "draw") {
          result.formulaSubmitted = true;
          continue;
        }
        state.formula = pressFormulaKey(state.formula, label);
        checkFormulaText(state);
        result.formulaEdited = true;
      }
    }
  }
  ImGui::End();
  ImGui::PopStyleVar(3);
}

}  // namespace zs::app
