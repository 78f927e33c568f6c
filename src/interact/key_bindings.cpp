// Key table and the scene edits behind the keys. Lowercase increases or toggles, Shift
// decreases: two keys per ± option, as in the thesis prototype's list (chapter 5.1).
#include "interact/key_bindings.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "i18n/translate.hpp"

namespace zs::interact {
namespace {

constexpr int S = GLFW_MOD_SHIFT;
constexpr int C = GLFW_MOD_CONTROL;

constexpr std::array<KeyBinding, 26> kBindings{{
    {GLFW_KEY_N, 0, Action::NextExample, "N", N_("next example surface")},
    {GLFW_KEY_P, 0, Action::PrevExample, "P", N_("previous example surface")},
    {GLFW_KEY_D, 0, Action::DirLightUp, "D", N_("first directional light brighter (+0.1)")},
    {GLFW_KEY_D, S, Action::DirLightDown, "Shift+D", N_("first directional light dimmer (-0.1)")},
    {GLFW_KEY_L, 0, Action::PointLightUp, "L", N_("first point light brighter (+0.1)")},
    {GLFW_KEY_L, S, Action::PointLightDown, "Shift+L", N_("first point light dimmer (-0.1)")},
    {GLFW_KEY_B, 0, Action::ToggleBorder, "B", N_("toggle the domain border highlight")},
    {GLFW_KEY_S, 0, Action::ToggleSilhouette, "S", N_("toggle the silhouette highlight")},
    {GLFW_KEY_E, 0, Action::EpsilonUp, "E", N_("epsilon x10 (coarser roots, faster)")},
    {GLFW_KEY_E, S, Action::EpsilonDown, "Shift+E", N_("epsilon /10 (finer roots)")},
    {GLFW_KEY_O, 0, Action::LevelUp, "O", N_("octree level +1 (tighter boxes)")},
    {GLFW_KEY_O, S, Action::LevelDown, "Shift+O", N_("octree level -1")},
    {GLFW_KEY_I, 0, Action::IntervalsUp, "I", N_("intervals per segment +1")},
    {GLFW_KEY_I, S, Action::IntervalsDown, "Shift+I", N_("intervals per segment -1")},
    {GLFW_KEY_C, 0, Action::Screenshot, "C", N_("screenshot: write a PNG at window size")},
    {GLFW_KEY_C, S, Action::WindowShot, "Shift+C", N_("screenshot of the window, panel included")},
    {GLFW_KEY_S, C, Action::SaveScene, "Ctrl+S", N_("save the current view as a .surf")},
    {GLFW_KEY_M, 0, Action::ExportMesh, "M", N_("export a mesh (.stl) at the panel's mesh level")},
    {GLFW_KEY_P, C, Action::PrintPage, "Ctrl+P",
     N_("print: a PDF page with the picture, the typeset formula and the values")},
    {GLFW_KEY_F, 0, Action::FocusFormula, "F", N_("type a formula (focus the text box)")},
    {GLFW_KEY_H, 0, Action::TogglePanel, "H", N_("hide / show the panel")},
    {GLFW_KEY_G, 0, Action::ToggleGallery, "G", N_("gallery: search the examples, pick one")},
    {GLFW_KEY_R, 0, Action::ResetView, "R", N_("reset camera and lights to the loaded scene")},
    {GLFW_KEY_Q, C, Action::Quit, "Ctrl+Q", N_("quit")},
    {GLFW_KEY_RIGHT, 0, Action::NextExample, "Right", N_("next example surface")},
    {GLFW_KEY_LEFT, 0, Action::PrevExample, "Left", N_("previous example surface")},
}};

std::string format(const char* what, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%s %g", i18n::tr(what), value);
  return text;
}

bool step(double& value, double delta, const char* what, std::string& message) {
  value = std::max(0.0, std::round((value + delta) * 1000) / 1000);
  message = format(what, value);
  return true;
}

}  // namespace

std::span<const KeyBinding> keyBindings() {
  return kBindings;
}

const KeyBinding* findBinding(int key, int mods) {
  mods &= GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;
  for (const KeyBinding& b : kBindings) {
    if (b.key == key && b.mods == mods) return &b;
  }
  return nullptr;
}

bool applyAction(Action action, Scene& scene, std::string& message) {
  RenderSettings& r = scene.render;
  switch (action) {
    case Action::DirLightUp:
    case Action::DirLightDown:
    case Action::PointLightUp:
    case Action::PointLightDown: {
      const bool directional = action == Action::DirLightUp || action == Action::DirLightDown;
      const bool up = action == Action::DirLightUp || action == Action::PointLightUp;
      const char* what = directional ? N_("directional light") : N_("point light");
      Light* light = firstLight(r.lights, directional ? LightKind::Directional : LightKind::Point);
      if (!light) {
        message = directional
                      ? i18n::tr("no directional light is on (the panel's lights section adds one)")
                      : i18n::tr("no point light is on (the panel's lights section adds one)");
        return false;
      }
      return step(light->intensity, up ? 0.1 : -0.1, what, message);
    }
    case Action::ToggleBorder:
      r.border.enabled = !r.border.enabled;
      message = i18n::tr(r.border.enabled ? N_("border highlight on") : N_("border highlight off"));
      return true;
    case Action::ToggleSilhouette:
      r.silhouette.enabled = !r.silhouette.enabled;
      message = i18n::tr(r.silhouette.enabled ? N_("silhouette on") : N_("silhouette off"));
      return true;
    case Action::EpsilonUp:
    case Action::EpsilonDown: {
      // Bounded to [1e-9, 1]: beyond that the bisection either never stops or finds nothing.
      const double factor = action == Action::EpsilonUp ? 10.0 : 0.1;
      r.tracing.epsilon = std::clamp(r.tracing.epsilon * factor, 1e-9, 1.0);
      message = format(N_("epsilon"), r.tracing.epsilon);
      return true;
    }
    case Action::LevelUp:
    case Action::LevelDown: {
      const int before = scene.octree.level;
      const int wanted = before + (action == Action::LevelUp ? 1 : -1);
      scene.octree.level = std::clamp(wanted, 0, std::max(before, kMaxKeyLevel));
      message = format(N_("octree level"), scene.octree.level);
      return scene.octree.level != before;
    }
    case Action::IntervalsUp:
    case Action::IntervalsDown:
      r.tracing.intervals =
          std::clamp(r.tracing.intervals + (action == Action::IntervalsUp ? 1 : -1), 1, 1000);
      message = format(N_("intervals"), r.tracing.intervals);
      return true;
    case Action::NextExample:
    case Action::PrevExample:
    case Action::Screenshot:
    case Action::WindowShot:
    case Action::SaveScene:
    case Action::ExportMesh:
    case Action::PrintPage:
    case Action::FocusFormula:
    case Action::TogglePanel:
    case Action::ToggleGallery:
    case Action::ResetView:
    case Action::Quit:
      return false;
  }
  return false;
}

}  // namespace zs::interact
