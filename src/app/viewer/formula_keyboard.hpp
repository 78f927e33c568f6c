#pragma once
// The formula keyboard of kiosk mode (interact/formula_keyboard.hpp) as a window of keys
// big enough for a finger (a touch screen's tap reaches the viewer as a left click) that
// writes into the panel's formula box at its end. Takes the panel's state; puts out what
// typing in the box would: the edit (parsed and checked at once, so the first picture
// follows every key) and, for the draw key, the submission.
#include <string>
#include <utility>

#include "app/viewer/panel.hpp"

namespace zs::app {

void drawFormulaKeyboard(PanelState& state, PanelResult& result);

// Where the keyboard lies on a display of the given size with text of `fontSize` pixels:
// centred at the bottom, square keys in rows (what the window tests click).
struct FormulaKeyboardLayout {
  float key = 0;             // side of a key, pixels
  float gapX = 0, gapY = 0;  // between keys
  float padding = 0;         // inside the window's edge
  float left = 0, top = 0;   // the window's corner
  int rows = 0, columns = 0;
  std::pair<float, float> centre(int row, int column) const;
};
FormulaKeyboardLayout formulaKeyboardLayout(float displayWidth, float displayHeight,
                                            float fontSize);

}  // namespace zs::app
