// The surfaces of a scene: surface 0 in the scene's own fields, the others in moreSurfaces;
// each parsed on its own, or all of them as the one function the tracer draws.
#include <string>
#include <utility>

#include "parser/parser.hpp"
#include "scene/scene_io.hpp"

namespace zs {

std::size_t surfaceCount(const Scene& scene) {
  return 1 + scene.moreSurfaces.size();
}

SurfaceEntry surfaceAt(const Scene& scene, std::size_t i) {
  if (i > 0) return scene.moreSurfaces[i - 1];
  return SurfaceEntry{scene.formula, scene.level, scene.render.materials};
}

Materials surfaceMaterials(std::size_t i) {
  // Front and back colors far apart in hue from every other surface's.
  static const Materials kPalette[kMaxSurfaces] = {
      Materials{},
      {{{0.25, 0.65, 0.45}, 0.5, 40.0}, {{0.8, 0.8, 0.35}, 0.5, 40.0}},
      {{{0.6, 0.4, 0.8}, 0.5, 40.0}, {{0.9, 0.6, 0.7}, 0.5, 40.0}},
      {{{0.8, 0.3, 0.3}, 0.5, 40.0}, {{0.95, 0.75, 0.55}, 0.5, 40.0}},
  };
  return kPalette[i % kMaxSurfaces];
}

std::string addSurface(Scene& scene, std::string_view formula) {
  if (surfaceCount(scene) >= static_cast<std::size_t>(kMaxSurfaces)) {
    return "error: at most " + std::to_string(kMaxSurfaces) +
           " surfaces in a scene\n"
           "hint: combine surfaces into one formula (a product F*G draws both)\n";
  }
  const ParseResult parsed = parseFormula(formula);
  if (const auto* err = std::get_if<ParseError>(&parsed)) return formatError(formula, *err);
  scene.moreSurfaces.push_back(
      SurfaceEntry{std::string(formula), 0, surfaceMaterials(surfaceCount(scene))});
  return {};
}

ParseResult parseSurfaceFormula(const Scene& scene, std::size_t i) {
  const SurfaceEntry surface = surfaceAt(scene, i);
  ParseResult parsed = parseFormula(surface.formula);
  if (surface.level == 0) return parsed;
  if (auto* f = std::get_if<Formula>(&parsed)) {
    f->root = f->graph.binary(Op::Sub, f->root, f->graph.constant(surface.level));
  }
  return parsed;
}

ParseResult parseSceneFormula(const Scene& scene, std::size_t* failedSurface,
                              std::vector<NodeId>* surfaceRoots) {
  ParseResult parsed = parseSurfaceFormula(scene, 0);
  if (failedSurface) *failedSurface = 0;
  auto* product = std::get_if<Formula>(&parsed);
  std::vector<NodeId> roots;
  if (product) roots.push_back(product->root);
  // The product's zero set is the union of the surfaces' only where every factor is defined:
  // a factor that may be undefined somewhere stands in it as "F where F is defined, else 1",
  // IfDefined(F, F - 1) + 1, so that another surface is still drawn there.
  auto standIn = [&](NodeId root) {
    return surfaceCount(scene) == 1 ? root : definedOrOne(product->graph, root);
  };
  if (product) product->root = standIn(product->root);
  for (std::size_t i = 1; product && i < surfaceCount(scene); ++i) {
    ParseResult factor = parseSurfaceFormula(scene, i);
    if (std::holds_alternative<ParseError>(factor)) {
      if (failedSurface) *failedSurface = i;
      return factor;
    }
    const Formula& f = std::get<Formula>(factor);
    roots.push_back(copyInto(product->graph, f.graph, f.root));
    product->root = product->graph.binary(Op::Mul, product->root, standIn(roots.back()));
  }
  if (product && surfaceRoots) *surfaceRoots = std::move(roots);
  return parsed;
}

Scene surfaceScene(const Scene& scene, std::size_t i) {
  const SurfaceEntry surface = surfaceAt(scene, i);
  Scene one = scene;
  one.moreSurfaces.clear();
  one.formula = surface.formula;
  one.level = surface.level;
  one.render.materials = surface.materials;
  return one;
}

std::string formatSceneFormulaError(const Scene& scene, std::size_t surface,
                                    const ParseError& error) {
  const std::string text = formatError(surfaceAt(scene, surface).formula, error);
  if (surfaceCount(scene) == 1) return text;
  return "surface " + std::to_string(surface + 1) + ":\n" + text;
}

}  // namespace zs
