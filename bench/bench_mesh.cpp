// `zeroset mesh` without the file: the Barth sextic and the Endraß octic at level 8 with 2
// threads (the goals of docs/mesh.md), and the sphere for scale. Counters: triangles, cells
// the zero set crosses, and the largest |F|/|grad F| at a vertex in cells.
#include <benchmark/benchmark.h>

#include <string>
#include <variant>

#include "mesh/mesh.hpp"
#include "parser/parser.hpp"
#include "scene/scene_io.hpp"

namespace {

void meshScene(benchmark::State& state, const std::string& input) {
  zs::SceneResult loaded = zs::loadSceneOrFormula(input);
  if (!std::holds_alternative<zs::Scene>(loaded)) {
    state.SkipWithError(("cannot load " + input).c_str());
    return;
  }
  const zs::Scene& scene = std::get<zs::Scene>(loaded);
  const zs::ParseResult parsed = zs::parseFormula(scene.formula);
  const zs::Formula& formula = std::get<zs::Formula>(parsed);
  const std::vector<double> params = zs::paramValues(scene, formula.graph);
  const zs::Box box{scene.domain.min, scene.domain.max};
  zs::MeshSettings settings;
  settings.level = int(state.range(0));
  settings.threads = 2;
  zs::MeshResult last;
  for (auto _ : state) {
    auto r = zs::buildMesh(formula, params, box, std::nullopt, settings);
    last = std::get<zs::MeshResult>(std::move(r));
    benchmark::DoNotOptimize(last.mesh.triangles.data());
  }
  state.counters["triangles"] = double(last.mesh.triangles.size());
  state.counters["cells"] = double(last.stats.cells);
  state.counters["residual_cells"] = last.stats.maxResidual / last.stats.cellSize;
}

const std::string kExamples = ZS_EXAMPLES_DIR;

}  // namespace

BENCHMARK_CAPTURE(meshScene, sphere, std::string("x^2 + y^2 + z^2 - 1"))
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(meshScene, barth_sextic, kExamples + "/barth-sextic.surf")
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(meshScene, endrass_octic, kExamples + "/endrass-octic.surf")
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
