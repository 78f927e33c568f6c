#include "app/repl/scene_edit.hpp"

#include <cstdio>
#include <fstream>
#include <system_error>

#include "scene/scene_io.hpp"

namespace zs::app {

std::string applyPromptEdit(const PromptCommand& command, session::Session& session) {
  switch (command.kind) {
    case PromptCommand::Kind::Formula:
      return session.setFormula(command.arg);
    case PromptCommand::Kind::Load:
      return session.loadFile(command.arg);
    case PromptCommand::Kind::Set:
      return session.applyOverrides(std::span(&command.arg, 1));
    default:
      return "error: internal: not a scene edit\n";
  }
}

std::string writeSceneFile(const std::filesystem::path& path, const Scene& scene) {
  // Written beside the target and renamed over it: a failed write leaves no half file.
  std::filesystem::path partial = path;
  partial += ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) return "error: cannot write " + path.string() + "\n";
    out << saveScene(scene);
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(partial, ignored);
      return "error: writing " + path.string() + " failed\n";
    }
  }
  std::error_code ec;
  std::filesystem::rename(partial, path, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    return "error: cannot write " + path.string() + "\n";
  }
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
