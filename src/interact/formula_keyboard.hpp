#pragma once
// The formula keyboard of kiosk mode, shared by the viewer (ImGui) and the web page (HTML
// buttons): its keys in rows, and what a key does to the formula's text. A visitor with a
// touch screen and no keyboard types with it.
#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace zs::interact {

// Labels row by row; "" is a gap. "sin" writes "sin(", "<-" deletes, "clear" empties,
// "draw" submits (the front end's job), every other key writes its label.
inline constexpr int kFormulaKeyRows = 4, kFormulaKeyColumns = 9;
using FormulaKeyRows =
    std::array<std::array<std::string_view, kFormulaKeyColumns>, kFormulaKeyRows>;
const FormulaKeyRows& formulaKeyRows();

// The text after one key: `key` appended (after a space where it would run into a name:
// "a x", not the parameter "ax"), or for "<-" the last character (or the last function
// name with its parenthesis) removed, or for "clear" nothing left. "draw" and unknown
// labels leave it as it is.
std::string pressFormulaKey(const std::string& text, std::string_view key);

// The row and column of the key labelled `label`, or {-1, -1}.
std::pair<int, int> findFormulaKey(std::string_view label);

}  // namespace zs::interact
