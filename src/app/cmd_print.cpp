// `zeroset print SCENE|FORMULA -o poster.pdf|poster.svg [--paper A4|A3|letter] [--dpi N]
// [--title TEXT] [--description TEXT] [--set KEY=VALUE]...`: one page with the picture at
// print resolution, the formula typeset, the parameter values, the surface's name and
// description (docs/print.md).
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "app/print_job.hpp"
#include "app/scene_args.hpp"

namespace zs::app {
namespace {

struct PrintArgs {
  SceneArgs scene;
  std::string output, paper = "A4", title, description, backend = "egl";
  double dpi = 300;
  bool titleGiven = false, descriptionGiven = false;  // "" is a choice too
};

int runPrint(const PrintArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  PrintJob job;
  job.scene = *scene;
  job.output = args.output;
  job.dpi = args.dpi;
  if (!printing::parsePaper(args.paper, job.paper)) {
    std::cerr << "error: --paper '" << args.paper << "' is not a paper size\n"
              << "hint: A4, A3 or letter\n";
    return 1;
  }
  if (!parseBackend(args.backend, job.backend)) {
    std::cerr << "error: unknown backend '" << args.backend << "'\nhint: egl or osmesa\n";
    return 1;
  }
  describeForPrint(args.scene.input, job.title, job.description);
  if (args.titleGiven) job.title = args.title;
  if (args.descriptionGiven) job.description = args.description;
  if (std::string err = runPrintJob(job); !err.empty()) {
    std::cerr << (err.rfind("error", 0) == 0 ? "" : "error: ") << err;
    return 1;
  }
  std::printf("wrote %s (%s, picture at %g dpi)\n", args.output.c_str(), args.paper.c_str(),
              args.dpi);
  return 0;
}

}  // namespace

void addPrintCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "print", "Write a printable page: the picture, the formula typeset, the parameters");
  auto args = std::make_shared<PrintArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option("-o,--output", args->output, "the page to write: a .pdf or an .svg")->required();
  cmd->add_option("--paper", args->paper, "A4 (default), A3 or letter");
  cmd->add_option("--dpi", args->dpi, "resolution of the picture on the page (default 300)")
      ->check(CLI::Range(30.0, 1200.0));
  cmd->add_option("--title", args->title,
                  "the heading (default: the name in the file's description line)")
      ->each([args](const std::string&) { args->titleGiven = true; });
  cmd->add_option("--description", args->description,
                  "the line under the heading (default: the file's description line)")
      ->each([args](const std::string&) { args->descriptionGiven = true; });
  cmd->add_option("--backend", args->backend, "egl (default) or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}));
  cmd->callback([args] { std::exit(runPrint(*args)); });
}

}  // namespace zs::app
