// `zeroset singular SCENE|FORMULA [--set KEY=VALUE]... [--depth N] [--budget N] [--csv FILE]
// [--json FILE]`: the certified singular points of F = 0 in the scene's domain (box or
// sphere), with the regions that could not be certified; src/singular does the work.
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "app/text_output.hpp"
#include "parser/parser.hpp"
#include "pipeline/pipeline.hpp"
#include "scene/scene_io.hpp"
#include "singular/report.hpp"

namespace zs::app {

namespace {

struct SingularArgs {
  SceneArgs scene;
  int depth = SingularSettings{}.maxDepth;
  std::size_t budget = SingularSettings{}.boxBudget;
  std::string csv, json;
};

// One surface's singular points: the table on stdout, the CSV and JSON files if asked.
bool reportSurface(const SingularArgs& args, const Scene& scene, std::size_t i, std::size_t count) {
  ParseResult parsed = parseSceneFormula(scene);
  if (auto* err = std::get_if<ParseError>(&parsed)) {
    std::cerr << formatError(scene.formula, *err);
    return false;
  }
  const Formula& formula = std::get<Formula>(parsed);
  SingularSettings settings;
  settings.maxDepth = args.depth;
  settings.boxBudget = args.budget;
  const Box box = toBox(scene.domain);
  auto found = findSingularPoints(formula, paramValues(scene, formula.graph), box,
                                  toBall(scene.domain), settings);
  if (auto* err = std::get_if<std::string>(&found)) {
    std::cerr << "error: " << *err << "\n";
    return false;
  }
  const SingularResult& result = std::get<SingularResult>(found);
  if (count > 1) std::cout << (i > 0 ? "\n" : "") << "surface " << i + 1 << " of " << count << ": ";
  std::cout << "singular points of " << scene.formula << " = 0 in ";
  if (scene.domain.shape == DomainShape::Sphere) {
    std::printf("the ball of center (%g, %g, %g), radius %g\n", scene.domain.center[0],
                scene.domain.center[1], scene.domain.center[2], scene.domain.radius);
  } else {
    std::printf("[%g, %g] x [%g, %g] x [%g, %g]\n", box.min[0], box.max[0], box.min[1], box.max[1],
                box.min[2], box.max[2]);
  }
  std::fflush(stdout);
  std::cout << singularTable(result);
  bool ok = true;
  if (!args.csv.empty())
    ok = writeTextFile(surfacePath(args.csv, i, count), singularCsv(result)) && ok;
  if (!args.json.empty())
    ok = writeTextFile(surfacePath(args.json, i, count), singularJson(result)) && ok;
  return ok;
}

// Each surface of a scene on its own: the points where two surfaces cross are not
// singular points of either.
int runSingular(const SingularArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  const std::size_t count = surfaceCount(*scene);
  bool ok = true;
  for (std::size_t i = 0; i < count; ++i)
    ok = reportSurface(args, surfaceScene(*scene, i), i, count) && ok;
  return ok ? 0 : 1;
}

}  // namespace

void addSingularCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "singular",
      "Find the singular points of F = 0 (F = 0 and grad F = 0) in the domain, each certified "
      "with interval arithmetic (Krawczyk), and report what could not be certified");
  auto args = std::make_shared<SingularArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option("--depth", args->depth,
                  "halvings of the domain per axis before a box is reported as not certified "
                  "(default 14)")
      ->check(CLI::Range(1, 30));
  cmd->add_option("--budget", args->budget,
                  "boxes to test before the search gives up with an error (default 4000000)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  cmd->add_option("--csv", args->csv, "also write the points and regions as CSV");
  cmd->add_option("--json", args->json, "also write the points and regions as JSON");
  cmd->callback([args] { std::exit(runSingular(*args)); });
}

}  // namespace zs::app
