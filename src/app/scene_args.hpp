#pragma once
// The SCENE|FORMULA argument and the --set KEY=VALUE options shared by the commands that
// show a surface: loads the scene (or a formula with defaults) and applies the overrides
// in order. On failure prints the file:line:column or caret error and returns nothing.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace zs::app {

struct SceneArgs {
  std::string input;
  std::vector<std::string> sets;
  std::vector<std::string> surfaces;  // --surface: more surfaces after the input's
  std::string inputFormat;            // --input-format: "" by the extension, or surf, jsurf, pic
};

// Adds the positional SCENE|FORMULA and the repeatable --set and --surface to a subcommand.
void addSceneOptions(CLI::App& cmd, SceneArgs& args, bool inputRequired = true);

std::optional<Scene> loadSceneArgs(const SceneArgs& args);

}  // namespace zs::app
