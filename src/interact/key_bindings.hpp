#pragma once
// The viewer's keyboard: takes a GLFW key code with its modifier bits, puts out the action
// bound to it, and applies the actions that are plain scene edits (the thesis prototype's
// options: light intensities, highlight toggles, epsilon, octree level, interval count).
// One table serves the key handler, the panel's key list and docs/viewer.md.
#include <span>
#include <string>

#include "scene/scene.hpp"

namespace zs::interact {

enum class Action {
  NextExample,
  PrevExample,
  DirLightUp,
  DirLightDown,
  PointLightUp,
  PointLightDown,
  ToggleBorder,
  ToggleSilhouette,
  EpsilonUp,
  EpsilonDown,
  LevelUp,
  LevelDown,
  IntervalsUp,
  IntervalsDown,
  Screenshot,
  WindowShot,
  SaveScene,
  ExportMesh,
  PrintPage,
  FocusFormula,
  TogglePanel,
  ToggleGallery,
  ResetView,
  Quit,
};

struct KeyBinding {
  int key;   // GLFW_KEY_*
  int mods;  // exact GLFW_MOD_SHIFT / GLFW_MOD_CONTROL bits required
  Action action;
  const char* keyName;  // as shown to the user: "Shift+E"
  const char* description;
};

std::span<const KeyBinding> keyBindings();

// Caps Lock and Num Lock bits are ignored; null when nothing is bound.
const KeyBinding* findBinding(int key, int mods);

// Applies an editing action to `scene`; false for the others, which leave it unchanged. What
// the edit rebuilds is the schema's to say (scene/invalidation.hpp), as for every edit.
// Values stay inside the .surf ranges, so a saved scene always loads back; `message` says
// what changed ("epsilon 0.001"), for the panel's status line.
bool applyAction(Action action, Scene& scene, std::string& message);

// Octree level reachable with the keys; deeper levels are set in the panel, on purpose.
inline constexpr int kMaxKeyLevel = 8;

}  // namespace zs::interact
