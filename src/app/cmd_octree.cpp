// `zeroset octree SCENE|FORMULA --level N [--criteria thesis|uniform] [--domain ...]
// [--dump FILE.csv]`: the CPU subdivision alone, with its statistics and the surface's
// bounds.
#include <fstream>
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "interval/report.hpp"
#include "interval/surface_bounds.hpp"
#include "parser/parser.hpp"
#include "pipeline/pipeline.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

namespace {

struct OctreeArgs {
  SceneArgs scene;
  std::optional<int> level;
  std::optional<std::string> criteria;
  std::vector<double> domain;
  std::string dump;
};

int runOctree(const OctreeArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  if (args.level) scene->octree.level = *args.level;
  if (args.criteria)
    scene->octree.criteria = *args.criteria == "uniform" ? Criteria::Uniform : Criteria::Thesis;
  if (!args.domain.empty()) {  // --domain is a box: it replaces a sphere domain too
    scene->domain.shape = DomainShape::Box;
    for (int axis = 0; axis < 3; ++axis) {
      scene->domain.min[axis] = args.domain[2 * axis];
      scene->domain.max[axis] = args.domain[2 * axis + 1];
    }
  }
  ParseResult parsed = parseSceneFormula(*scene);
  if (auto* err = std::get_if<ParseError>(&parsed)) {
    std::cerr << formatError(scene->formula, *err);
    return 1;
  }
  const Formula& formula = std::get<Formula>(parsed);
  const std::vector<double> params = paramValues(*scene, formula.graph);
  OctreeResult built =
      buildOctree(formula, params, toBox(scene->domain), scene->octree, toBall(scene->domain));
  if (auto* err = std::get_if<OctreeError>(&built)) {
    std::cerr << "error: " << err->message << "\n";
    return 1;
  }
  const Octree& tree = std::get<Octree>(built);
  std::cout << octreeReport(tree);
  // What the exact tracing methods clip rays to (docs/hierarchy.md): a hint for a tighter domain.
  const Box bounds = surfaceBounds(formula, params, tree.domain, tree.ball);
  if (isEmpty(bounds)) {
    std::cout << "surface bounds: empty (no cell of the level-6 grid can hold F = 0)\n";
  } else {
    std::cout << "surface bounds: ";
    for (std::size_t a = 0; a < 3; ++a)
      std::cout << (a ? "x[" : "[") << bounds.min[a] << "," << bounds.max[a] << "]";
    std::cout << " (level-6 cells where F = 0 may hold)\n";
  }
  if (!args.dump.empty()) {
    std::ofstream out(args.dump);
    writeLeafCsv(tree, out);
    if (!out) {
      std::cerr << "error: cannot write " << args.dump << "\n";
      return 1;
    }
    std::cout << "wrote " << tree.leaves.size() << " leaf boxes to " << args.dump << "\n";
  }
  return 0;
}

}  // namespace

void addOctreeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("octree",
                                 "Subdivide the domain with interval arithmetic and "
                                 "report the kept boxes");
  auto args = std::make_shared<OctreeArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option("--level", args->level, "maximum octree level")->check(CLI::Range(0, 20));
  cmd->add_option("--criteria", args->criteria, "subdivision criteria")
      ->check(CLI::IsMember({"thesis", "uniform"}));
  cmd->add_option("--domain", args->domain, "xmin,xmax,ymin,ymax,zmin,zmax")
      ->delimiter(',')
      ->expected(6);
  cmd->add_option("--dump", args->dump, "write the kept leaf boxes as CSV");
  cmd->callback([args] { std::exit(runOctree(*args)); });
}

}  // namespace zs::app
