// Today's zeroset scene has an ambient term, one point light and one directional light,
// and materials with a colour, a specular weight and a shininess (src/render/settings.hpp).
// SURFER's first light that is on becomes the point light, its second the directional one
// (a light far away shines from one direction); a diffuse weight other than 1 is folded
// into the light intensities.
#include "jsurf/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace zs::jsurf {
namespace {

Vec3 normalizedOr(const Vec3& v, const Vec3& fallback) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return l > 0 ? Vec3{v[0] / l, v[1] / l, v[2] / l} : fallback;
}

Material toMaterial(const SurferMaterial& m) {
  return {m.color, std::clamp(m.specular, 0.0, 1.0), std::clamp(m.shininess, 0.0, 10000.0)};
}

// Directional lights go this many clipping radii away, where a point light's direction
// hardly changes across the sphere.
constexpr double kFarAway = 1000.0;

}  // namespace

void lightingToScene(const SurferScene& s, const Mat4& cameraToWorld, RenderSettings& out,
                     std::vector<std::string>& notes) {
  out.materials.front = toMaterial(s.front);
  out.materials.back = toMaterial(s.back);
  for (const SurferMaterial* m : {&s.front, &s.back}) {
    if (m->specular > 1) notes.push_back("a specular intensity above 1 is taken as 1");
    if (m->shininess > 10000) notes.push_back("a shininess above 10000 is taken as 10000");
  }
  // SURFER lights back faces with the front material's ambient weight as well.
  out.lights.ambient = std::clamp(s.front.ambient, 0.0, 1.0);
  const double diffuse = s.front.diffuse;
  if (s.back.diffuse != s.front.diffuse)
    notes.push_back("zeroset has one diffuse weight for both sides; the front one is used");
  out.lights.point.intensity = 0;
  out.lights.directional.intensity = 0;
  int used = 0;
  for (int i = 0; i < kSurferLights; ++i) {
    const SurferLight& l = s.lights[static_cast<std::size_t>(i)];
    if (!l.on) continue;
    const Vec3 world = transformPoint(cameraToWorld, l.position);
    if (used == 0) {
      out.lights.point = {world, l.intensity * diffuse, l.color};
    } else if (used == 1) {
      out.lights.directional = {normalizedOr({-world[0], -world[1], -world[2]}, {0, 0, -1}),
                                l.intensity * diffuse, l.color};
    } else {
      notes.push_back("light " + std::to_string(i) +
                      " is left out: zeroset's scene holds one point and one directional light");
    }
    ++used;
  }
}

void lightingToSurfer(const RenderSettings& r, const Mat4& worldToCamera, double radius,
                      SurferScene& out, std::vector<std::string>& notes) {
  for (SurferMaterial* m : {&out.front, &out.back}) {
    const Material& z = m == &out.front ? r.materials.front : r.materials.back;
    *m = {z.color, r.lights.ambient, 1.0, z.specular, z.shininess};
  }
  const PointLight& p = r.lights.point;
  out.lights[0] = {p.intensity > 0, transformPoint(worldToCamera, p.position), p.color, p.intensity};
  const DirectionalLight& d = r.lights.directional;
  const Vec3 dir = normalizedOr(d.direction, {0, 0, -1});
  const Vec3 far{-dir[0] * kFarAway * radius, -dir[1] * kFarAway * radius, -dir[2] * kFarAway * radius};
  out.lights[1] = {d.intensity > 0, transformPoint(worldToCamera, far), d.color, d.intensity};
  if (d.intensity > 0)
    notes.push_back("the directional light becomes SURFER light 1, a point light far away");
  for (int i = 2; i < kSurferLights; ++i) out.lights[static_cast<std::size_t>(i)] = {};
}

}  // namespace zs::jsurf
