#pragma once
// Kiosk mode (`zeroset view --kiosk`, the web page's kiosk=1): the policy of an unattended
// exhibit, shared by the desktop viewer and the web page. Takes an action or a typed
// formula, puts out whether the exhibit allows it: no quitting and nothing that writes a
// file, and no polynomial above a degree limit (a visitor's (x^2+y^2)^20 would make every
// frame slow for the next visitor). What the front ends do with it: fullscreen, the gallery
// as the start screen, and back to it after `idleSeconds` without input.
#include <string>
#include <string_view>

#include "expr/graph.hpp"
#include "interact/key_bindings.hpp"

namespace zs::interact {

struct KioskPolicy {
  double idleSeconds = 210;  // 3.5 minutes without input, as SURFER's exhibitions
  int maxDegree = 10;        // of typed polynomials; other formulas have no degree
};

// False for the actions an exhibit refuses: quit, screenshots, saving, mesh export, print.
bool kioskAllows(Action action);

// "" when `formula` may be drawn, otherwise the message for the visitor (a formula that does
// not parse is the parser's to report, and "" here).
std::string kioskRefusal(std::string_view formula, const KioskPolicy& policy);
// The same for a formula already parsed.
std::string kioskRefusal(const Formula& formula, const KioskPolicy& policy);

}  // namespace zs::interact
