#include "app/scene_args.hpp"

#include <iostream>

#include "app/formula_args.hpp"
#include "scene/scene_io.hpp"
#include "session/session.hpp"

namespace zs::app {

void addSceneOptions(CLI::App& cmd, SceneArgs& args, bool inputRequired) {
  auto* input =
      cmd.add_option("input", args.input,
                     "a .surf scene file, a SURFER .jsurf file, a surf script .pic, or a formula "
                     "such as \"x^2+y^2+z^2-1\"");
  if (inputRequired) input->required();
  unprotectFormula(*input);
  cmd.add_option("--set", args.sets,
                 "override a scene key: KEY=VALUE with a dotted key and a TOML value, e.g. "
                 "--set camera.eye=[0,0,3] --set params.a=0.2 (repeatable)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  auto* surface = cmd.add_option("--surface", args.surfaces,
                                 "one more surface drawn with the input's, a formula such as "
                                 "\"x^2+y^2-0.3\" (repeatable; --set surface.2.KEY=VALUE sets "
                                 "its level and material)")
                      ->expected(1)
                      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  unprotectFormula(*surface);
  cmd.add_option("--input-format", args.inputFormat,
                 "read the input as a zeroset scene (surf), a SURFER file (jsurf) or a surf script "
                 "(pic) whatever its name (default: by its extension)")
      ->check(CLI::IsMember({"surf", "jsurf", "pic"}));
}

namespace {

// Another program's file (SURFER's .jsurf, surf's .pic) is imported, its warnings printed;
// anything else is a scene or a formula.
SceneResult loadAnyScene(const std::string& input, const std::string& format) {
  if (format == "surf") return loadScene(input);
  std::optional<ImportResult> r = session::importForeignFile(input, format);
  if (!r) return loadSceneOrFormula(input);
  if (auto* err = std::get_if<SceneError>(&*r)) return *err;
  std::cerr << session::formatImportWarnings(std::get<ImportedScene>(*r));
  return std::get<ImportedScene>(std::move(*r)).scene;
}

}  // namespace

std::optional<Scene> loadSceneArgs(const SceneArgs& args) {
  SceneResult loaded = loadAnyScene(args.input, args.inputFormat);
  if (auto* err = std::get_if<SceneError>(&loaded)) {
    std::cerr << formatSceneError(*err);
    return std::nullopt;
  }
  Scene scene = std::get<Scene>(std::move(loaded));
  for (const std::string& formula : args.surfaces) {
    if (std::string err = addSurface(scene, formula); !err.empty()) {
      std::cerr << "--surface:\n" << err;
      return std::nullopt;
    }
  }
  // All --set at once: keys that constrain each other are checked after the last one.
  if (auto err = applyOverrides(scene, args.sets)) {
    std::cerr << formatSceneError(*err);
    return std::nullopt;
  }
  return scene;
}

}  // namespace zs::app
