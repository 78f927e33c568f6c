#pragma once
// The viewer's Dear ImGui panel: takes the current scene (edited in place by the widgets),
// the formula being typed and what the viewer measured; puts out the edits. The formula box
// parses on every keystroke and shows the caret and message under it (the last good surface
// stays on screen); a slider per parameter; every render setting; the octree level,
// criterion and domain; FPS and frame times; the key list. The caller diffs the scene to
// decide between a redraw and a rebuild, and checks that it still loads back.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/viewer/focus_request.hpp"
#include "interact/kiosk.hpp"
#include "scene/scene.hpp"

namespace zs::app {

struct PanelStats {
  double fps = 0;      // window frames per second
  double frameMs = 0;  // one window frame, ray tracing included when it traced
  double traceMs = 0;  // the latest trace alone
  int traceScale = 1;  // 1 = full resolution, 2 = half, ...
  int width = 0, height = 0;
  double buildMs = 0;       // request to upload, for the shown surface
  std::size_t leaves = 0;   // octree leaves of the shown surface
  std::size_t nodes = 0;    // of the box hierarchy
  int singularPoints = -1;  // marked by highlights.singular; -1 when the highlight is off
  bool building = false;
  std::string example;  // name of the example on screen, if any
  std::string status;   // the latest action's message
  // Curvature colorings: the value at the ends of the color map (the legend); 0 otherwise.
  double curvatureRange = 0;
  bool gaussian = false;  // which curvature: Gaussian, or mean
};

struct PanelState {
  std::string formula;                  // text in the box (may not parse)
  std::string formulaError;             // caret + message for `formula`, or the build's error
  FocusRequest formulaFocus;            // asked by the F key: put the cursor in the box
  std::vector<std::string> paramNames;  // of the shown surface
  std::vector<std::pair<double, double>> paramRanges;  // slider bounds, fixed per surface
  int meshLevel = 7;                                   // grid level of "Export mesh" (docs/mesh.md)
  bool meshCap = false;  // close the solid along the domain for printing
  // Per parameter: 0 at rest, +1 or -1 while its play button sweeps it up or down.
  std::vector<int> playing;
  // An exhibit (--kiosk): formulas above its degree are refused like a parse error, the
  // mesh export and the keys that write files are not shown, and the formula keyboard is.
  std::optional<interact::KioskPolicy> kiosk;
  bool formulaRefused = false;  // formulaError is the kiosk's refusal, not a parse error
};

struct PanelResult {
  bool formulaEdited = false;     // the text changed (the viewer debounces the build)
  bool formulaSubmitted = false;  // Enter was pressed in the box
  bool sliderActive = false;      // a widget is being dragged: trace at reduced resolution
  bool exportMesh = false;        // the "Export mesh" button was pressed
  bool printPage = false;         // the "Print page" button was pressed
  bool animating = false;         // a play button is sweeping a parameter
  bool languageChanged = false;   // the language menu picked another language
};

PanelResult drawPanel(Scene& scene, PanelState& state, const PanelStats& stats);

// Re-parses `state.formula` and fills state.formulaError ("" when it parses and, in a
// kiosk, is within its degree limit).
void checkFormulaText(PanelState& state);

// One step of a play button's sweep: `value` moves by `dt / seconds` of the range [lo, hi]
// in `direction` (+1 or -1) and turns back at either end, so a full sweep up and down takes
// 2 * seconds. Returns the new value; `direction` is flipped at a bound.
double sweepStep(double value, double lo, double hi, double dt, double seconds, int& direction);

// The render settings, octree and domain sections (panel_settings.cpp).
void drawSettings(Scene& scene);

}  // namespace zs::app
