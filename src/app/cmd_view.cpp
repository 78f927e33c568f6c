// `zeroset view [SCENE|FORMULA] [--set KEY=VALUE]... [--output-dir DIR] [--drag-scale N]
// [--log] [--language CODE] [--kiosk [--kiosk-idle S] [--kiosk-max-degree N]]`: the
// interactive viewer
// (docs/viewer.md). Without an input it opens on the first example surface.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <variant>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"

namespace zs::app {
namespace {

struct ViewArgs {
  SceneArgs scene;
  std::string outputDir;
  int dragScale = 0;
  bool log = false;
  std::string language;  // "" : from the environment (LANGUAGE, LC_ALL, LC_MESSAGES, LANG)
  bool kiosk = false;
  interact::KioskPolicy kioskPolicy;
};

int runView(const ViewArgs& args) {
  i18n::setLanguage(args.language.empty() ? i18n::languageFromEnvironment() : args.language);
  ViewerOptions options;
  if (args.scene.input.empty()) {
    std::vector<Example> examples = listExamples(findExamplesDir());
    auto first = loadExample(examples.front());  // never empty: built-ins at worst
    if (auto* err = std::get_if<std::string>(&first)) {
      std::cerr << *err;
      return 1;
    }
    options.scene = std::get<Scene>(first);
    options.title = "zeroset - " + examples.front().name;
    options.exampleIndex = 0;
  } else {
    std::optional<Scene> scene = loadSceneArgs(args.scene);
    if (!scene) return 1;
    options.scene = *scene;
    options.title = "zeroset - " + args.scene.input;
    std::error_code ec;
    if (std::filesystem::is_regular_file(args.scene.input, ec))
      options.sceneFile = args.scene.input;
  }
  const char* envDir = std::getenv("ZS_OUTPUT_DIR");
  options.outputDir = !args.outputDir.empty() ? args.outputDir : envDir && *envDir ? envDir : ".";
  options.dragScale = args.dragScale;
  options.log = args.log;
  if (args.kiosk) options.kiosk = args.kioskPolicy;
  std::string error;
  std::unique_ptr<Viewer> viewer = Viewer::open(options, error);
  if (!viewer) {
    std::cerr << "error: cannot open a window: " << error << "\n"
              << "hint: without a display, use `zeroset render` (or run under xvfb-run)\n";
    return 1;
  }
  viewer->run();
  return 0;
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("view", "Open the interactive viewer (see docs/viewer.md)");
  auto args = std::make_shared<ViewArgs>();
  addSceneOptions(*cmd, args->scene, false);
  cmd->add_option("--output-dir", args->outputDir,
                  "folder for screenshots and saved scenes (default: $ZS_OUTPUT_DIR or .)");
  cmd->add_option("--drag-scale", args->dragScale,
                  "resolution divisor while dragging (default: adaptive, ~30 fps)")
      ->check(CLI::Range(1, 8));
  cmd->add_flag("--log", args->log, "print events (ready, builds, key actions) on stdout");
  std::string codes;
  for (const i18n::Language& l : i18n::languages())
    codes += (codes.empty() ? "" : ", ") + std::string(l.code);
  cmd->add_option("--language", args->language,
                  "language of the viewer's texts: " + codes +
                      " (default: from LANGUAGE, LC_ALL, LC_MESSAGES or LANG, else en)")
      ->check([](const std::string& code) {
        return i18n::knownLanguage(code).empty() ? "no translation for '" + code + "'" : "";
      });
  auto* kiosk = cmd->add_flag("--kiosk", args->kiosk,
                              "exhibit mode: fullscreen, gallery start screen, no quit key, "
                              "no files written, formula keyboard (docs/viewer.md)");
  cmd->add_option("--kiosk-idle", args->kioskPolicy.idleSeconds,
                  "kiosk: seconds without input before the start screen returns (default 210)")
      ->check(CLI::Range(1.0, 86400.0))
      ->needs(kiosk);
  cmd->add_option("--kiosk-max-degree", args->kioskPolicy.maxDegree,
                  "kiosk: highest degree of a typed polynomial (default 10)")
      ->check(CLI::Range(1, 64))
      ->needs(kiosk);
  cmd->callback([args] { std::exit(runView(*args)); });
}

}  // namespace zs::app
