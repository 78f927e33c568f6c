// The panel's own sections: formula, parameters (each slider with a play button that sweeps
// it), statistics, keys. Settings widgets live in panel_settings.cpp. Parameter values are
// edited in the scene's params list, which the viewer turns into shader uniforms (and a
// rebuilt hierarchy).
#include "app/viewer/panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include "app/viewer/fonts.hpp"
#include "i18n/translate.hpp"
#include "interact/key_bindings.hpp"
#include "interact/parameter_range.hpp"
#include "parser/parser.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {
// The camera motions and key actions are the interact stage's, shared with the web page.
using namespace zs::interact;
namespace {

double& paramSlot(Scene& scene, const std::string& name) {
  for (auto& [key, value] : scene.params) {
    if (key == name) return value;
  }
  scene.params.emplace_back(name, kDefaultParamValue);
  return scene.params.back().second;
}

void drawFormula(PanelState& state, PanelResult& result) {
  ImGui::TextUnformatted("F(x,y,z) =");
  state.formulaFocus.beforeItem();
  ImGui::SetNextItemWidth(-1);
  ImGui::PushFont(formulaFont());
  const bool enter =
      ImGui::InputText("##formula", &state.formula, ImGuiInputTextFlags_EnterReturnsTrue);
  state.formulaFocus.afterItem();
  if (ImGui::IsItemEdited()) {
    result.formulaEdited = true;
    checkFormulaText(state);
  }
  if (enter) result.formulaSubmitted = true;
  if (!state.formulaError.empty()) {
    // In the box's monospaced font, so the caret stands under the character it means;
    // wrapped at the panel's edge (a kiosk's refusal is one long sentence).
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(state.formulaError.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
  }
  ImGui::PopFont();
}

// Seconds for one sweep from one end of a slider to the other.
constexpr double kSweepSeconds = 4.0;

void drawParams(Scene& scene, PanelState& state, PanelResult& result) {
  if (state.paramNames.empty()) return;
  ImGui::Separator();
  ImGui::TextUnformatted(i18n::tr("parameters"));
  state.playing.resize(state.paramNames.size(), 0);
  for (std::size_t i = 0; i < state.paramNames.size(); ++i) {
    const std::string& name = state.paramNames[i];
    double& value = paramSlot(scene, name);
    auto [lo, hi] = i < state.paramRanges.size() ? state.paramRanges[i] : paramRange(value);
    ImGui::PushID(int(i));
    int& playing = state.playing[i];
    if (ImGui::Button(playing != 0 ? "||" : ">")) playing = playing != 0 ? 0 : 1;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(playing != 0 ? i18n::tr("stop") : i18n::tr("play: sweep %s back and forth"),
                        name.c_str());
    ImGui::PopID();
    ImGui::SameLine();
    if (playing != 0) {
      // Each step edits the scene like a drag would: the viewer shows the value through the
      // uniforms at once and rebuilds the octree on its worker (latest wins).
      value = sweepStep(value, lo, hi, ImGui::GetIO().DeltaTime, kSweepSeconds, playing);
      result.animating = true;
    }
    ImGui::SliderScalar(name.c_str(), ImGuiDataType_Double, &value, &lo, &hi, "%.4g");
  }
}

void drawStats(const PanelStats& s) {
  ImGui::Separator();
  ImGui::Text(i18n::tr("%.1f fps, frame %.1f ms"), s.fps, s.frameMs);
  ImGui::Text(i18n::tr("trace %.1f ms at %dx%d%s"), s.traceMs, s.width / std::max(1, s.traceScale),
              s.height / std::max(1, s.traceScale), s.traceScale > 1 ? i18n::tr(" (reduced)") : "");
  ImGui::Text(i18n::tr("build %.0f ms: %zu leaves, %zu boxes%s"), s.buildMs, s.leaves, s.nodes,
              s.building ? i18n::tr(" (building...)") : "");
  if (s.singularPoints >= 0)
    ImGui::Text(i18n::tr("%d certified singular points"), s.singularPoints);
  if (!s.example.empty()) ImGui::Text(i18n::tr("example %s"), s.example.c_str());
  if (!s.status.empty()) ImGui::TextWrapped("%s", s.status.c_str());
}

// The curvature coloring's legend: the diverging map of raytrace_shading.frag.glsl
// (blue -range, white 0, red +range) with its end values.
void drawLegend(const PanelStats& s) {
  if (s.curvatureRange <= 0) return;
  ImGui::Separator();
  ImGui::TextUnformatted(s.gaussian ? i18n::tr("Gaussian curvature (oriented by grad F)")
                                    : i18n::tr("mean curvature (oriented by grad F)"));
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = ImGui::GetFontSize();
  const ImU32 blue = IM_COL32(38, 77, 217, 255), white = IM_COL32(245, 245, 245, 255),
              red = IM_COL32(204, 26, 26, 255);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 mid(at.x + width / 2, at.y + height), end(at.x + width, at.y + height);
  draw->AddRectFilledMultiColor(at, mid, blue, white, white, blue);
  draw->AddRectFilledMultiColor(ImVec2(mid.x, at.y), end, white, red, red, white);
  ImGui::Dummy(ImVec2(width, height));
  char range[32];
  std::snprintf(range, sizeof range, "%.3g", s.curvatureRange);
  ImGui::Text("-%s", range);
  ImGui::SameLine(width / 2);
  ImGui::TextUnformatted("0");
  ImGui::SameLine(width - ImGui::CalcTextSize(range).x);
  ImGui::Text("+%s", range);
}

// What leaves the viewer as a file: a mesh of the surface for 3-D printing or other tools
// (its level and cap, and the button; the M key does the same) and a printed page
// (Ctrl+P, docs/print.md).
void drawExports(PanelState& state, PanelResult& result) {
  ImGui::Separator();
  ImGui::SetNextItemWidth(120);
  ImGui::SliderInt(i18n::label("mesh level"), &state.meshLevel, 3, 10);
  ImGui::SameLine();
  ImGui::Checkbox(i18n::label("cap"), &state.meshCap);
  // The buttons share a line where their texts (longer in some languages) fit.
  if (ImGui::Button(i18n::label("Export mesh (M)"))) result.exportMesh = true;
  const char* print = i18n::label("Print page (Ctrl+P)");
  const float printWidth =
      ImGui::CalcTextSize(print, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
  if (printWidth + ImGui::GetStyle().ItemSpacing.x <=
      ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x)
    ImGui::SameLine();
  if (ImGui::Button(print)) result.printPage = true;
}

// The language of every text of the viewer; the choice holds until the viewer closes (a
// kiosk goes back to its start language when idle).
void drawLanguage(PanelResult& result) {
  const auto all = i18n::languages();
  int current = 0;
  std::string items;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].code == i18n::currentLanguage()) current = int(i);
    (items += all[i].name) += '\0';
  }
  if (ImGui::Combo(i18n::label("language"), &current, items.c_str()))
    result.languageChanged = i18n::setLanguage(all[std::size_t(current)].code);
}

void drawKeys(bool kiosk) {
  if (!ImGui::CollapsingHeader(i18n::label("keys and mouse"))) return;
  // Two columns: what to press, what it does (key names are the keyboard's, not translated).
  // The first is as wide as its widest entry, which depends on the language.
  const char* pointer[][2] = {{N_("left drag"), N_("rotate (arcball)")},
                              {N_("wheel"), N_("zoom")},
                              {N_("right drag"), N_("turn the key light")}};
  float column = ImGui::CalcTextSize("Shift+D").x;
  for (const auto& p : pointer) column = std::max(column, ImGui::CalcTextSize(i18n::tr(p[0])).x);
  column += ImGui::GetFontSize();
  auto row = [column](const char* what, const char* does) {
    ImGui::TextUnformatted(what);
    ImGui::SameLine(column);
    ImGui::TextWrapped("%s", does);
  };
  for (const auto& p : pointer) row(i18n::tr(p[0]), i18n::tr(p[1]));
  for (const KeyBinding& b : keyBindings()) {
    if (!kiosk || kioskAllows(b.action)) row(b.keyName, i18n::tr(b.description));
  }
}

}  // namespace

double sweepStep(double value, double lo, double hi, double dt, double seconds, int& direction) {
  if (!(hi > lo) || seconds <= 0) return value;
  double v = std::clamp(value, lo, hi) + direction * (hi - lo) * std::max(0.0, dt) / seconds;
  // Reflect at the bounds; a long dt (a slow frame) cannot carry it past both.
  if (v > hi) {
    v = std::max(lo, 2 * hi - v);
    direction = -1;
  } else if (v < lo) {
    v = std::min(hi, 2 * lo - v);
    direction = 1;
  }
  return v;
}

void checkFormulaText(PanelState& state) {
  ParseResult parsed = parseFormula(state.formula);
  state.formulaRefused = false;
  if (auto* err = std::get_if<ParseError>(&parsed)) {
    state.formulaError = formatError(state.formula, *err);
  } else if (state.kiosk) {
    state.formulaError = kioskRefusal(std::get<Formula>(parsed), *state.kiosk);
    state.formulaRefused = !state.formulaError.empty();
  } else {
    state.formulaError.clear();
  }
}

PanelResult drawPanel(Scene& scene, PanelState& state, const PanelStats& stats) {
  PanelResult result;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  // Grows with the open sections up to the window's height, then scrolls.
  const float maxHeight = ImGui::GetIO().DisplaySize.y - 16;
  ImGui::SetNextWindowSizeConstraints(ImVec2(360, 0), ImVec2(360, std::max(100.0f, maxHeight)));
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("zeroset", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    drawFormula(state, result);
    drawParams(scene, state, result);
    // surface.level: the surface drawn is F = level (a level set of F).
    ImGui::DragScalar(i18n::label("level"), ImGuiDataType_Double, &scene.level, 0.01f, nullptr,
                      nullptr, "%.4g");
    result.sliderActive = result.sliderActive || ImGui::IsItemActive();
    drawStats(stats);
    drawLegend(stats);
    if (!state.kiosk) drawExports(state, result);
    drawSettings(scene);
    drawKeys(state.kiosk.has_value());
    drawLanguage(result);
  }
  ImGui::End();
  result.sliderActive = ImGui::IsAnyItemActive() && !ImGui::GetIO().WantTextInput;
  return result;
}

}  // namespace zs::app
