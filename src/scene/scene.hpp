#pragma once
// A scene: what one .surf file holds. Plain data; scene_io.hpp reads and writes it.
#include <string>
#include <utility>
#include <vector>

#include "interval/octree_settings.hpp"
#include "render/settings.hpp"

namespace zs {

struct Scene {
  std::string formula = "x^2 + y^2 + z^2 - 1";
  std::vector<std::pair<std::string, double>> params;  // in file order
  double level = 0;  // surface.level: the surface drawn is F = level (parseSceneFormula)
  Domain domain;
  OctreeSettings octree;
  RenderSettings render;
  int width = 800;
  int height = 600;

  bool operator==(const Scene&) const = default;
};

}  // namespace zs
