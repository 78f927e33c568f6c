// `zeroset import FILE.jsurf|FILE.pic -o FILE.surf` and `zeroset export SCENE -o FILE.jsurf`:
// SURFER's scene files and surf's scripts to zeroset's, and zeroset's to SURFER's (src/jsurf,
// src/surfscript; docs/jsurf.md, docs/surf-scripts.md). Warnings — what one program shows
// differently from the other — go to stderr; the file is written all the same.
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "app/text_output.hpp"
#include "jsurf/jsurf.hpp"
#include "scene/scene_io.hpp"
#include "session/session.hpp"
#include "surfscript/surf_import.hpp"

namespace zs::app {
namespace {

struct ImportArgs {
  std::string input;
  std::string output;
  std::string format;  // "" by the extension, else jsurf or pic
};

int runImport(const ImportArgs& args) {
  // By its name, else as SURFER's (the command's first use).
  std::optional<ImportResult> found = session::importForeignFile(args.input, args.format);
  ImportResult r = found ? std::move(*found) : jsurf::loadJsurf(args.input);
  if (auto* err = std::get_if<SceneError>(&r)) {
    std::cerr << formatSceneError(*err);
    return 1;
  }
  const ImportedScene& imported = std::get<ImportedScene>(r);
  std::cerr << session::formatImportWarnings(imported);
  const bool script =
      args.format == "pic" || (args.format.empty() && surfscript::isSurfScriptPath(args.input));
  // The first comment is the scene's description (`zeroset gallery` shows it).
  const std::string text = std::string("# Imported from the ") +
                           (script ? "surf script " : "SURFER file ") +
                           std::filesystem::path(args.input).filename().string() +
                           " by zeroset import.\n" + saveScene(imported.scene);
  if (!writeTextFile(args.output, text)) return 1;
  std::cout << "wrote " << args.output << "\n";
  return 0;
}

struct ExportArgs {
  SceneArgs scene;
  std::string output;
};

int runExport(const ExportArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  auto r = jsurf::exportJsurf(*scene);
  if (auto* err = std::get_if<std::string>(&r)) {
    std::cerr << *err;
    return 1;
  }
  const jsurf::Exported& exported = std::get<jsurf::Exported>(r);
  for (const std::string& w : exported.warnings) std::cerr << "warning: " << w << "\n";
  if (!writeTextFile(args.output, exported.text)) return 1;
  std::cout << "wrote " << args.output << "\n";
  return 0;
}

}  // namespace

void addImportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("import",
                                 "Convert a SURFER .jsurf file or a surf script (.pic) to a .surf "
                                 "scene (docs/jsurf.md, docs/surf-scripts.md)");
  auto args = std::make_shared<ImportArgs>();
  cmd->add_option("input", args->input,
                  "the SURFER file or surf script, e.g. kummer.jsurf, A1pm.pic")
      ->required();
  cmd->add_option("-o,--output", args->output, "the .surf file to write")->required();
  cmd->add_option(
         "--input-format", args->format,
         "read the input as a SURFER file (jsurf) or a surf script (pic) whatever its name")
      ->check(CLI::IsMember({"jsurf", "pic"}));
  cmd->callback([args] { std::exit(runImport(*args)); });
}

void addExportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("export", "Write a scene as a SURFER .jsurf file (docs/jsurf.md)");
  auto args = std::make_shared<ExportArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option("-o,--output", args->output, "the .jsurf file to write")->required();
  cmd->callback([args] { std::exit(runExport(*args)); });
}

}  // namespace zs::app
