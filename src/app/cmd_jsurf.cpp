// `zeroset import FILE.jsurf -o FILE.surf` and `zeroset export SCENE -o FILE.jsurf`: SURFER's
// scene files to zeroset's and back (src/jsurf, docs/jsurf.md). Warnings — what one program
// shows differently from the other — go to stderr; the file is written all the same.
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "app/text_output.hpp"
#include "jsurf/jsurf.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {
namespace {

struct ImportArgs {
  std::string input;
  std::string output;
};

int runImport(const ImportArgs& args) {
  jsurf::ImportResult r = jsurf::loadJsurf(args.input);
  if (auto* err = std::get_if<SceneError>(&r)) {
    std::cerr << formatSceneError(*err);
    return 1;
  }
  const jsurf::Imported& imported = std::get<jsurf::Imported>(r);
  for (const SceneError& w : imported.warnings) std::cerr << jsurf::formatWarning(w);
  // The first comment is the scene's description (`zeroset gallery` shows it).
  const std::string text = "# Imported from the SURFER file " +
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
  auto* cmd =
      app.add_subcommand("import", "Convert a SURFER .jsurf file to a .surf scene (docs/jsurf.md)");
  auto args = std::make_shared<ImportArgs>();
  cmd->add_option("input", args->input, "the SURFER file, e.g. kummer.jsurf")->required();
  cmd->add_option("-o,--output", args->output, "the .surf file to write")->required();
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
