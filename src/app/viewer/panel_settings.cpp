// The settings sections of the panel, built from the .surf schema (scene/schema.hpp) as the
// page's are: one widget per key, with the key's own type and range, grouped as
// session::panelGroup says, and the lists ([[lights.source]], [[clip.plane]], [[surface]])
// as one block per entry. Nothing here knows a setting by name but the clip planes' axis
// buttons; the viewer hands the edited scene to its session, which checks it as a .surf file
// would be (a value typed with Ctrl+click beyond a range is refused, not saved).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "app/viewer/panel.hpp"
#include "i18n/translate.hpp"
#include "scene/schema.hpp"
#include "session/session.hpp"

namespace zs::app {
namespace {

using namespace scene_detail;

// "shading.contours.fov_y" -> "shading · contours · fov y", each word translated where the
// catalog has it, as the page's keyLabel; the key itself is the widget's identity.
std::string keyLabel(std::string_view key, std::string_view id) {
  std::string shown;
  std::size_t start = 0;
  while (start <= key.size()) {
    std::size_t end = key.find('.', start);
    if (end == std::string_view::npos) end = key.size();
    std::string word(key.substr(start, end - start));
    std::replace(word.begin(), word.end(), '_', ' ');
    if (!shown.empty()) shown += " \xc2\xb7 ";
    shown += i18n::tr(word.c_str());
    start = end + 1;
  }
  return shown + "###" + std::string(id);
}

// The bounds a widget clamps to: the range's, an open end moved just inside it, and none
// (ImGui's unbounded drag) where the range is unbounded.
struct Bounds {
  double lo, hi;
  bool clamp;
};

Bounds boundsOf(const Range& r) {
  const double inf = std::numeric_limits<double>::infinity();
  if (r.lo == -inf && r.hi == inf) return {0, 0, false};
  auto inside = [](double end, bool open, double toward) {
    if (!open || !std::isfinite(end)) return end;
    return end + (toward - end > 0 ? 1 : -1) * std::max(1e-9, std::abs(end) * 1e-9);
  };
  const double lo = std::isfinite(r.lo) ? inside(r.lo, r.loOpen, r.hi) : -1e300;
  const double hi = std::isfinite(r.hi) ? inside(r.hi, r.hiOpen, r.lo) : 1e300;
  return {lo, hi, true};
}

// A drag step of about 1/200 of a bounded range, or 1 % of the value.
float speedOf(const Range& r, double value) {
  if (std::isfinite(r.lo) && std::isfinite(r.hi)) return float((r.hi - r.lo) / 200);
  return float(std::max(std::abs(value) * 0.01, 0.001));
}

bool isColor(std::string_view key) {
  return key.find("color") != std::string_view::npos || key == "background";
}

// The texts being typed into function fields, kept until Enter, and the scene's text each
// started from (a scene loaded meanwhile replaces it). One panel per process.
struct Typed {
  std::string typed, shown;
};
std::map<std::string, Typed>& typedFunctions() {
  static std::map<std::string, Typed> texts;
  return texts;
}

// One key's widget on `scene`; `id` is its full name ("lights.source.2.intensity").
void keyWidget(const KeySpec& spec, Scene& scene, const std::string& id) {
  const std::string label = keyLabel(spec.name, id);
  std::visit(
      [&](const auto& field) {
        using F = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<F, BoolRef>) {
          ImGui::Checkbox(label.c_str(), &field(scene));
        } else if constexpr (std::is_same_v<F, IntRef> || std::is_same_v<F, SizeRef>) {
          auto& value = field(scene);
          const Bounds b = boundsOf(spec.range);
          const double lo = std::max(b.lo, -2e9), hi = std::min(b.hi, 2e9);
          int v = int(std::clamp(double(value), lo, hi));
          if (ImGui::DragInt(label.c_str(), &v, 0.1f, b.clamp ? int(std::ceil(lo)) : 0,
                             b.clamp ? int(std::floor(hi)) : 0, "%d",
                             b.clamp ? ImGuiSliderFlags_AlwaysClamp : 0))
            value = static_cast<std::remove_reference_t<decltype(value)>>(v);
        } else if constexpr (std::is_same_v<F, RealRef>) {
          double& value = field(scene);
          const Bounds b = boundsOf(spec.range);
          ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &value, speedOf(spec.range, value),
                            b.clamp ? &b.lo : nullptr, b.clamp ? &b.hi : nullptr, "%.4g",
                            b.clamp ? ImGuiSliderFlags_AlwaysClamp : 0);
        } else if constexpr (std::is_same_v<F, VecRef>) {
          Vec3& v = field(scene);
          if (isColor(spec.name)) {
            float f[3] = {float(v[0]), float(v[1]), float(v[2])};
            if (ImGui::ColorEdit3(label.c_str(), f, ImGuiColorEditFlags_Float))
              v = {f[0], f[1], f[2]};
          } else {
            Vec3 edited = v;
            const Bounds b = boundsOf(spec.range);
            const bool changed = ImGui::DragScalarN(
                label.c_str(), ImGuiDataType_Double, edited.data(), 3,
                speedOf(spec.range, std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])})),
                b.clamp ? &b.lo : nullptr, b.clamp ? &b.hi : nullptr, "%.3g");
            // A direction of zero length has no meaning: the drag stops short of it.
            const bool zero = edited[0] == 0 && edited[1] == 0 && edited[2] == 0;
            if (changed && !(spec.nonZero && zero)) v = edited;
          }
        } else if constexpr (std::is_same_v<F, EnumRef>) {
          std::string items;
          for (std::string_view name : field.names)
            (items += i18n::tr(std::string(name).c_str())) += '\0';
          int current = field.get(scene);
          if (ImGui::Combo(label.c_str(), &current, items.c_str())) field.set(scene, current);
        } else {  // FunctionRef: applied on Enter, a text that does not parse is refused
          std::string& text = field(scene);
          Typed& t = typedFunctions()[id];
          if (t.shown != text) t.typed = t.shown = text;
          if (ImGui::InputText(label.c_str(), &t.typed, ImGuiInputTextFlags_EnterReturnsTrue))
            text = t.typed;
        }
      },
      spec.field);
}

// Entry i of `list` moved out of the scene into a scratch scene and back.
void entryWidgets(const ListSpec& list, Scene& scene, std::size_t i) {
  Scene scratch;
  list.entry(scene, i, scratch);
  const Scene before = scratch;
  const std::string prefix = std::string(list.name) + "." + std::to_string(i + 1) + ".";
  for (const KeySpec& spec : list.keys) keyWidget(spec, scratch, prefix + std::string(spec.name));
  if (list.name == kClipPlanesKey) {
    // Axis presets and a flip keep the plane's place: quicker than typing a normal.
    ClipPlane& plane = scratch.render.clipPlanes.front();
    for (int a = 0; a < 3; ++a) {
      const char* axis[] = {"x", "y", "z"};
      if (a) ImGui::SameLine();
      if (ImGui::SmallButton(axis[a]))
        plane.normal = {a == 0 ? 1.0 : 0.0, a == 1 ? 1.0 : 0.0, a == 2 ? 1.0 : 0.0};
    }
    ImGui::SameLine();
    if (ImGui::SmallButton(i18n::label("flip"))) {
      plane.normal = {-plane.normal[0], -plane.normal[1], -plane.normal[2]};
      plane.offset = -plane.offset;
    }
  }
  if (scratch != before) list.store(scratch, scene, i);
}

void removeEntry(const ListSpec& list, Scene& scene, std::size_t removed) {
  const std::size_t n = list.size(scene);
  for (std::size_t j = removed; j + 1 < n; ++j) {
    Scene scratch;
    list.entry(scene, j + 1, scratch);
    list.store(scratch, scene, j);
  }
  list.resize(scene, n - 1);
}

struct ListView {
  std::string_view list;
  const char* legend;  // "light %d"
  const char* add;     // "add light"
  std::size_t first;   // entries before it are shown elsewhere (the first surface)
};

// Each entry of the list with its keys and a remove button, and a button that adds one.
void listWidgets(const ListView& view, Scene& scene) {
  const ListSpec* list = findList(view.list);
  if (!list) return;
  std::size_t removed = list->size(scene);
  for (std::size_t i = view.first; i < list->size(scene); ++i) {
    ImGui::PushID(std::string(view.list).c_str());
    ImGui::PushID(int(i));
    ImGui::Separator();
    ImGui::TextUnformatted(i18n::format(i18n::tr(view.legend), int(i) + 1).c_str());
    entryWidgets(*list, scene, i);
    if (ImGui::SmallButton(i18n::label("remove"))) removed = i;
    ImGui::PopID();
    ImGui::PopID();
  }
  if (removed < list->size(scene)) removeEntry(*list, scene, removed);
  const std::size_t n = list->size(scene);
  if (n < list->maxSize && ImGui::Button(i18n::label(view.add))) {
    list->resize(scene, n + 1);
    if (list->fresh) {
      Scene scratch;
      list->entry(scene, n, scratch);
      list->fresh(scratch, n);
      list->store(scratch, scene, n);
    }
  }
}

constexpr ListView kListViews[] = {
    {kLightSourcesKey, N_("light %d"), N_("add light"), 0},
    {kClipPlanesKey, N_("plane %d"), N_("add plane"), 0},
    // The first surface's formula is the formula box, its level and materials are keys.
    {kSurfacesKey, N_("surface %d"), N_("add surface"), 1},
};

}  // namespace

void drawSettings(Scene& scene) {
  for (std::string_view group : session::panelGroups()) {
    const std::string name(group);
    if (!ImGui::CollapsingHeader(i18n::label(name.c_str()))) continue;
    for (const KeySpec& spec : keySpecs()) {
      if (spec.legacyLight >= 0 || session::panelGroup(spec.name) != group) continue;
      keyWidget(spec, scene, std::string(spec.name));
    }
    if (group == session::panelGroup(kLightSourcesKey))
      ImGui::TextDisabled("%s", i18n::tr("right drag moves the first point light"));
    for (const ListView& view : kListViews) {
      if (session::panelGroup(view.list) == group) listWidgets(view, scene);
    }
  }
}

}  // namespace zs::app
