#include "app/repl/scene_edit.hpp"

#include <cstdio>
#include <fstream>
#include <system_error>
#include <variant>

#include "jsurf/jsurf.hpp"
#include "parser/parser.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

std::string applyToScene(const PromptCommand& command, Scene& scene) {
  switch (command.kind) {
    case PromptCommand::Kind::Formula: {
      ParseResult parsed = parseFormula(command.arg);
      if (auto* err = std::get_if<ParseError>(&parsed)) return formatError(command.arg, *err);
      scene.formula = command.arg;
      return {};
    }
    case PromptCommand::Kind::Load: {
      if (jsurf::isJsurfPath(command.arg)) {
        jsurf::ImportResult imported = jsurf::loadJsurf(command.arg);
        if (auto* err = std::get_if<SceneError>(&imported)) return formatSceneError(*err);
        // What SURFER shows differently is worth saying, but the load goes ahead.
        for (const SceneError& w : std::get<jsurf::Imported>(imported).warnings)
          std::fputs(jsurf::formatWarning(w).c_str(), stderr);
        scene = std::get<jsurf::Imported>(std::move(imported)).scene;
        return {};
      }
      SceneResult loaded = loadScene(command.arg);
      if (auto* err = std::get_if<SceneError>(&loaded)) return formatSceneError(*err);
      scene = std::get<Scene>(std::move(loaded));
      return {};
    }
    case PromptCommand::Kind::Set:
      if (auto err = applyOverride(scene, command.arg)) return formatSceneError(*err);
      return {};
    default:
      return "error: internal: not a scene edit\n";
  }
}

std::string checkScene(const Scene& scene) {
  SceneResult reloaded = parseScene(saveScene(scene), "<view>");
  if (auto* err = std::get_if<SceneError>(&reloaded)) return formatSceneError(*err);
  return {};
}

std::string writeSceneFile(const std::filesystem::path& path, const Scene& scene) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return "error: cannot write " + path.string() + "\n";
  out << saveScene(scene);
  out.close();
  if (!out) return "error: writing " + path.string() + " failed\n";
  return {};
}

std::filesystem::path nextFreePath(const std::filesystem::path& dir, const std::string& stem,
                                   const std::string& extension) {
  std::error_code ec;
  for (int i = 1;; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "-%04d", i);
    std::filesystem::path path = dir / (stem + name + extension);
    if (!std::filesystem::exists(path, ec) || i >= 99999) return path;
  }
}

}  // namespace zs::app
