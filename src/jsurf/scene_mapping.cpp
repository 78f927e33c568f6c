#include "jsurf/scene_mapping.hpp"

#include <cmath>

#include "jsurf/lighting.hpp"

namespace zs::jsurf {

Scene toScene(const SurferScene& s, std::vector<std::string>& notes) {
  Scene scene;
  scene.formula = s.formula;
  scene.params = s.params;
  const ZerosetFrame frame = toZeroset(s.view);
  scene.domain = frame.domain;
  scene.render.camera = frame.camera;
  scene.width = 600;
  scene.height = 600;
  scene.render.silhouette.enabled = false;
  scene.render.border.enabled = false;
  scene.render.reflection.enabled = false;
  scene.render.samples = 2;
  scene.render.background = s.background;
  lightingToScene(s, cameraToWorld(s.view), scene.render, notes);
  return scene;
}

SurferScene toSurferScene(const Scene& scene, std::vector<std::string>& notes) {
  SurferScene s;
  s.formula = scene.formula;
  s.params = scene.params;
  double radius = scene.domain.radius;
  Vec3 center = scene.domain.center;
  if (scene.domain.shape == DomainShape::Box) {
    double sum = 0;
    for (int a = 0; a < 3; ++a) {
      const double half = (scene.domain.max[a] - scene.domain.min[a]) / 2;
      center[a] = (scene.domain.max[a] + scene.domain.min[a]) / 2;
      sum += half * half;
    }
    radius = std::sqrt(sum);
    notes.push_back(
        "SURFER clips to a sphere: the domain box becomes the ball through its corners, radius " +
        std::to_string(radius));
  }
  if (center[0] != 0 || center[1] != 0 || center[2] != 0)
    notes.push_back(
        "SURFER's clipping sphere is centred at the origin; the domain's centre is not kept");
  const Camera& cam = scene.render.camera;
  s.view = toSurfer(cam, radius);
  Mat4 worldToCamera = identity4();
  invertAffine(cameraToWorld(s.view), worldToCamera);
  lightingToSurfer(scene.render, worldToCamera, radius, s, notes);
  s.background = scene.render.background;
  return s;
}

}  // namespace zs::jsurf
