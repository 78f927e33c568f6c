#pragma once
// A scene: what one .surf file holds. Plain data; scene_io.hpp reads and writes it.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "interval/octree_settings.hpp"
#include "render/settings.hpp"

namespace zs {

// A scene draws up to this many surfaces ([[surface]] entries).
inline constexpr int kMaxSurfaces = 4;

// A surface after the first: what Scene::formula, Scene::level and render.materials are for
// the first one. Every surface shares the scene's parameters.
struct SurfaceEntry {
  std::string formula = "x^2 + y^2 + z^2 - 1";
  double level = 0;
  Materials materials;

  bool operator==(const SurfaceEntry&) const = default;
};

struct Scene {
  std::string formula = "x^2 + y^2 + z^2 - 1";
  std::vector<std::pair<std::string, double>> params;  // in file order
  double level = 0;  // surface.level: the surface drawn is F = level (parseSceneFormula)
  // The second surface onwards ([[surface]] entries 2, 3, ...); the first is the fields above.
  std::vector<SurfaceEntry> moreSurfaces;
  Domain domain;
  OctreeSettings octree;
  RenderSettings render;
  int width = 800;
  int height = 600;

  bool operator==(const Scene&) const = default;
};

}  // namespace zs
