#pragma once
// The viewer's font: takes the monitor's content scale, loads DejaVu Sans (Debian's
// fonts-dejavu-core, a dependency of the package) into the current ImGui context at a size
// that reads the same on every screen, with the glyphs the gallery's names, descriptions
// and formulas use (Latin, Greek, dashes, super- and subscripts, math symbols), and scales
// ImGui's spacing to match. Where the font file is missing, ImGui's built-in font stays and
// the reason comes back.
#include <string>

struct ImFont;

namespace zs::app {

// Points of the panel's text at a content scale of 1.
inline constexpr float kViewerFontSize = 15.0f;

// The first DejaVu Sans found, or "" ($ZS_FONT names another TrueType file to use instead).
std::string findViewerFont();

// Call after ImGui::CreateContext and before the first frame. "" on success, else why
// ImGui's built-in font (ASCII only, 13 px) is used. Also loads DejaVu Sans Mono beside it
// for formulas (formulaFont).
std::string loadViewerFont(float contentScale);

// The monospaced font of the formula box and its error, so the caret under a message lines
// up with the character it points at; the default font where none was loaded.
ImFont* formulaFont();

}  // namespace zs::app
