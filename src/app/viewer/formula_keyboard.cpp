#include "app/viewer/formula_keyboard.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "i18n/translate.hpp"
#include "interact/formula_keyboard.hpp"

namespace zs::app {
std::pair<float, float> FormulaKeyboardLayout::centre(int row, int column) const {
  return {left + padding + float(column) * (key + gapX) + key / 2,
          top + padding + float(row) * (key + gapY) + key / 2};
}

FormulaKeyboardLayout formulaKeyboardLayout(float displayWidth, float displayHeight,
                                            float fontSize) {
  FormulaKeyboardLayout l;
  l.rows = interact::kFormulaKeyRows;
  l.columns = interact::kFormulaKeyColumns;
  l.key = std::max(44.0f, fontSize * 2.8f);  // a fingertip and more
  l.gapX = l.gapY = std::round(l.key / 8);
  l.padding = l.gapX;
  const float width = float(l.columns) * l.key + float(l.columns - 1) * l.gapX + 2 * l.padding;
  const float height = float(l.rows) * l.key + float(l.rows - 1) * l.gapY + 2 * l.padding;
  l.left = std::max(0.0f, std::round((displayWidth - width) / 2));
  l.top = std::max(0.0f, displayHeight - 8 - height);
  return l;
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
                                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                     ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin(i18n::label("formula keyboard"), nullptr, flags)) {
    for (const auto& row : interact::formulaKeyRows()) {
      for (std::size_t i = 0; i < row.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        const std::string label(row[i]);
        if (label.empty()) {
          ImGui::Dummy(ImVec2(l.key, l.key));
          continue;
        }
        // The two word keys are shown translated; the rest are what they type.
        const bool word = label == "draw" || label == "clear";
        if (!ImGui::Button(word ? i18n::label(label.c_str()) : label.c_str(), ImVec2(l.key, l.key)))
          continue;
        if (label == "draw") {
          result.formulaSubmitted = true;
          continue;
        }
        state.formula = interact::pressFormulaKey(state.formula, label);
        checkFormulaText(state);
        result.formulaEdited = true;
      }
    }
  }
  ImGui::End();
  ImGui::PopStyleVar(3);
}

}  // namespace zs::app
