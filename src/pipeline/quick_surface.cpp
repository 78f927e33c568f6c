#include "pipeline/quick_surface.hpp"

#include <algorithm>
#include <chrono>

#include "expr/derivative.hpp"
#include "parser/parser.hpp"
#include "pipeline/pipeline.hpp"
#include "scene/scene_io.hpp"

namespace zs {

std::variant<QuickSurface, std::string> prepareQuickSurface(const Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  if (needsCurvature(scene.render.shading.color))
    return std::string("the tape interpreter has no second derivatives (shading.color)");
  if (scene.render.singular.enabled)
    return std::string("the tape interpreter draws no singular-point markers");
  if (surfaceCount(scene) > 1)
    return std::string("the tape interpreter draws one surface's materials");
  ParseResult parsed = parseSceneFormula(scene);
  if (auto* err = std::get_if<ParseError>(&parsed)) return formatError(scene.formula, *err);
  Formula formula = std::get<Formula>(std::move(parsed));
  const std::array<NodeId, 3> grad = gradient(formula.graph, formula.root);
  QuickSurface q;
  auto tape = encodeGpuTape(formula.graph, formula.root, grad);
  if (auto* err = std::get_if<std::string>(&tape)) return *err;
  q.tape = std::get<GpuTape>(std::move(tape));
  q.params = paramValues(scene, formula.graph);
  OctreeSettings shallow = scene.octree;
  shallow.level = std::min(shallow.level, kQuickOctreeLevel);
  OctreeResult tree =
      buildOctree(formula, q.params, toBox(scene.domain), shallow, toBall(scene.domain));
  if (auto* err = std::get_if<OctreeError>(&tree)) return "error: " + err->message + "\n";
  // A volume skips stretches by the affine form, which only the interval program has.
  q.sampling = scene.render.tracing.method == TracingMethod::Sampling &&
               scene.render.mode != RenderMode::Volume;
  q.hierarchy = tracingHierarchy(formula, q.params, std::get<Octree>(tree),
                                 q.sampling ? TracingMethod::Sampling : TracingMethod::Interval);
  q.prepareMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return q;
}

}  // namespace zs
