// zeroset's scene holds up to 8 lights, directional or point, each on or off, and Phong
// materials with ambient, diffuse and specular weights per side (src/render/settings.hpp):
// SURFER's model fits in it one to one. SURFER's ambient term is the material's ambient
// weight alone, so lights.ambient is 1 on import. Its lights are points in camera space,
// and stay there (lights.space = "camera"): they turn with the view, as in SURFER.
#include "jsurf/lighting.hpp"

#include <algorithm>
#include <cmath>

#include "render/camera.hpp"

namespace zs::jsurf {
namespace {

// A SURFER light nobody touched (all eight are listed in every file SURFER writes): it is
// left out on import and written back on export as padding.
bool isUnusedSlot(const SurferLight& l) {
  return l == SurferLight{};
}

double unit(double v, const char* what, std::vector<std::string>& notes) {
  if (v > 1) notes.push_back(std::string(what) + " above 1 is taken as 1");
  return std::clamp(v, 0.0, 1.0);
}

Material toMaterial(const SurferMaterial& m, std::vector<std::string>& notes) {
  Material out;
  out.color = m.color;
  out.ambient = unit(m.ambient, "an ambient intensity", notes);
  out.diffuse = unit(m.diffuse, "a diffuse intensity", notes);
  out.specular = unit(m.specular, "a specular intensity", notes);
  if (m.shininess > 10000) notes.push_back("a shininess above 10000 is taken as 10000");
  out.shininess = std::min(m.shininess, 10000.0);
  return out;
}

// Directional lights go this many clipping radii away, where a point light's direction
// hardly changes across the sphere.
constexpr double kFarAway = 1000.0;

}  // namespace

void lightingToScene(const SurferScene& s, const Mat4& cameraToWorld, RenderSettings& out,
                     std::vector<std::string>& notes) {
  out.materials.front = toMaterial(s.front, notes);
  out.materials.back = toMaterial(s.back, notes);
  if (s.back.ambient != s.front.ambient)
    notes.push_back(
        "SURFER lights back faces with the front material's ambient intensity; "
        "zeroset uses the back material's own");
  out.lights.ambient = 1.0;
  out.lights.space = LightSpace::Camera;
  out.lights.sources.clear();
  for (const SurferLight& l : s.lights) {
    if (isUnusedSlot(l)) continue;
    Light light;
    light.kind = LightKind::Point;
    light.enabled = l.on;
    light.position = worldPointToCamera(out.camera, transformPoint(cameraToWorld, l.position));
    light.intensity = l.intensity;
    light.color = l.color;
    out.lights.sources.push_back(light);
  }
}

void lightingToSurfer(const RenderSettings& r, const Mat4& worldToCamera, double radius,
                      SurferScene& out, std::vector<std::string>& notes) {
  for (SurferMaterial* m : {&out.front, &out.back}) {
    const Material& z = m == &out.front ? r.materials.front : r.materials.back;
    // zeroset scales every material's ambient weight by lights.ambient; SURFER has no such
    // factor, so it goes into the weights.
    *m = {z.color, z.ambient * r.lights.ambient, z.diffuse, z.specular, z.shininess};
  }
  std::size_t slot = 0;
  for (const Light& l : r.lights.sources) {
    if (slot == out.lights.size()) break;  // the scene holds at most as many as SURFER
    const bool fixedToCamera = r.lights.space == LightSpace::Camera;
    Vec3 world = fixedToCamera ? cameraPointToWorld(r.camera, l.position) : l.position;
    if (l.kind == LightKind::Directional) {
      const Vec3 dir = fixedToCamera ? cameraVectorToWorld(r.camera, l.direction) : l.direction;
      const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
      const Vec3 d = n > 0 ? Vec3{dir[0] / n, dir[1] / n, dir[2] / n} : Vec3{0, 0, -1};
      for (int a = 0; a < 3; ++a) world[a] = -d[a] * kFarAway * radius;
      notes.push_back("directional light " + std::to_string(slot + 1) +
                      " becomes a SURFER point light far away in the same direction");
    }
    out.lights[slot++] = {l.enabled, transformPoint(worldToCamera, world), l.color, l.intensity};
  }
  for (; slot < out.lights.size(); ++slot) out.lights[slot] = {};
}

}  // namespace zs::jsurf
