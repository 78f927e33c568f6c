#pragma once
// Plain data: what a .jsurf file says, in SURFER's own terms, before it is mapped onto a
// zeroset Scene (to_scene.cpp) or after a Scene is mapped onto it (from_scene.cpp). The
// defaults are jsurf's, i.e. what SURFER shows for a key the file leaves out.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "jsurf/surfer_frame.hpp"
#include "render/settings.hpp"

namespace zs::jsurf {

inline constexpr int kSurferLights = 8;  // AlgebraicSurfaceRenderer.MAX_LIGHTS

struct SurferLight {
  bool on = false;         // SURFER switches every light off before reading a file
  Vec3 position{0, 0, 0};  // camera space: the lights move with the camera
  Vec3 color{1, 1, 1};
  double intensity = 1.0;

  bool operator==(const SurferLight&) const = default;
};

struct SurferMaterial {
  Vec3 color{0.5, 0.5, 0.5};
  double ambient = 0.1;
  double diffuse = 0.23232;
  double specular = 0.9;
  double shininess = 1.0;

  bool operator==(const SurferMaterial&) const = default;
};

struct SurferScene {
  std::string formula;
  std::vector<std::pair<std::string, double>> params;  // sorted by name, as SURFER lists them
  SurferView view;
  SurferMaterial front;
  SurferMaterial back;
  std::array<SurferLight, kSurferLights> lights{};
  Vec3 background{1, 1, 1};
};

}  // namespace zs::jsurf
