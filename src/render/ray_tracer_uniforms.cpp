// RenderSettings -> shader uniforms. Out-of-range knobs are clamped here (documented in
// docs/renderer.md) so no setting can hang or break the shader.
#include <glad/gl.h>

#include <algorithm>
#include <cmath>

#include "render/camera.hpp"
#include "render/ray_tracer.hpp"

namespace zs {
namespace {

void vec3Uniform(int location, const Vec3& v, double scale = 1) {
  glUniform3f(location, float(v[0] * scale), float(v[1] * scale), float(v[2] * scale));
}

}  // namespace

int RayTracer::setUniforms(unsigned program, const RenderSettings& s, const Domain& clip,
                           int width, int height) {
  auto uniform = [&](const char* name) { return programs_.uniform(program, name); };
  // Rays are clipped to the domain's bounding box, then to its ball when it is a sphere.
  const Domain domain = boundingBox(clip);
  const bool ball = clip.shape == DomainShape::Sphere;
  glUniform4f(uniform("rtBall"), float(clip.center[0]), float(clip.center[1]),
              float(clip.center[2]), ball ? float(clip.radius) : 0.0f);
  glUniform1i(uniform("rtHierarchy"), 0);
  glUniform1i(uniform("rtBeam"), 1);    // its own unit: never aliases the hierarchy's
  glUniform1i(uniform("rtBeamOn"), 0);  // prepare() turns it on after a beam pass
  glUniform1i(uniform("rtNodeCount"), hierarchy_.count);
  glUniform1i(uniform("rtFirstNode"), hierarchy_.rootIsLeaf ? 0 : 1);
  glUniform3f(uniform("rtRootMin"), hierarchy_.rootMin[0], hierarchy_.rootMin[1],
              hierarchy_.rootMin[2]);
  glUniform3f(uniform("rtRootMax"), hierarchy_.rootMax[0], hierarchy_.rootMax[1],
              hierarchy_.rootMax[2]);
  glUniform3f(uniform("rtCell"), hierarchy_.cell[0], hierarchy_.cell[1], hierarchy_.cell[2]);
  glUniform1f(uniform("rtPad"), hierarchy_.pad);
  vec3Uniform(uniform("rtDomainMin"), domain.min);
  vec3Uniform(uniform("rtDomainMax"), domain.max);
  glUniform2f(uniform("rtResolution"), float(width), float(height));

  const CameraBasis basis = cameraBasis(s.camera);
  vec3Uniform(uniform("rtEye"), basis.eye);
  vec3Uniform(uniform("rtForward"), basis.forward);
  vec3Uniform(uniform("rtRight"), basis.right);
  vec3Uniform(uniform("rtUp"), basis.up);
  glUniform1f(uniform("rtPlaneHalf"), float(imagePlaneHalfHeight(s.camera)));
  glUniform1i(uniform("rtOrtho"), s.camera.projection == Projection::Orthographic);

  const Tracing& t = s.tracing;
  glUniform1i(uniform("rtIntervals"), std::clamp(t.intervals, 1, 4096));
  glUniform1i(uniform("rtMaxBisections"), std::clamp(t.maxBisections, 1, 200));
  const double epsilon = std::isfinite(t.epsilon) && t.epsilon > 0 ? t.epsilon : 1e-6;
  glUniform1f(uniform("rtEpsilon"), float(epsilon));
  glUniform1i(uniform("rtTangentRoots"), tangentRoots_);
  // Tangent roots are accepted within a distance far below epsilon: epsilon bounds how
  // precisely a crossing is located, not how near a ray may pass and still count as a hit.
  double diagonal = 0;
  for (int a = 0; a < 3; ++a) diagonal += (domain.max[a] - domain.min[a]) * (domain.max[a] - domain.min[a]);
  glUniform1f(uniform("rtTangentTolerance"), float(1e-5 * std::max(std::sqrt(diagonal), 1e-6)));

  // The lights themselves are shader constants (render/shading_defines.hpp).
  const Materials& m = s.materials;
  const double ambient = std::max(s.lights.ambient, 0.0);
  auto phong = [&](const char* name, const Material& material) {
    glUniform4f(uniform(name), float(material.ambient * ambient), float(material.diffuse),
                float(material.specular), float(std::max(material.shininess, 0.0)));
  };
  vec3Uniform(uniform("rtFrontColor"), m.front.color);
  vec3Uniform(uniform("rtBackColor"), m.back.color);
  phong("rtFrontPhong", m.front);
  phong("rtBackPhong", m.back);
  glUniform1f(uniform("rtCurvatureRange"), float(curvatureRange_ > 0 ? curvatureRange_ : 1.0));

  glUniform1i(uniform("rtSilhouetteOn"), s.silhouette.enabled);
  glUniform1f(uniform("rtSilhouetteThreshold"), float(s.silhouette.threshold));
  vec3Uniform(uniform("rtSilhouetteColor"), s.silhouette.color);
  glUniform1i(uniform("rtBorderOn"), s.border.enabled);
  glUniform1f(uniform("rtBorderThreshold"), float(s.border.threshold));
  vec3Uniform(uniform("rtBorderColor"), s.border.color);
  glUniform1f(uniform("rtPrimaryWeight"), float(std::clamp(s.reflection.primaryWeight, 0.0, 1.0)));
  glUniform1f(uniform("rtOpacity"), float(std::clamp(s.opacity, 0.0, 1.0)));
  vec3Uniform(uniform("rtBackground"), s.background);

  if (!params_.empty()) {
    const int location = uniform("zs_params");
    if (location >= 0) glUniform1fv(location, GLsizei(params_.size()), params_.data());
  }
  return setProxyUniforms(program, s.camera, domain, width, height);
}

int RayTracer::setProxyUniforms(unsigned program, const Camera& camera, const Domain& domain,
                                int width, int height) {
  auto uniform = [&](const char* name) { return programs_.uniform(program, name); };
  glUniform1i(uniform("rtProxy"), proxy_ == Proxy::Box ? 1 : 0);  // fullscreen.vert.glsl
  if (proxy_ == Proxy::FullScreen) return 6;
  if (hierarchy_.count == 0) return 0;
  // Hits lie in the domain and in the root box of the hierarchy.
  Vec3 lo{}, hi{};
  double diagonal = 0, farthest = 0;
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(domain.min[a], double(hierarchy_.rootMin[a]));
    hi[a] = std::min(domain.max[a], double(hierarchy_.rootMax[a]));
    if (!(lo[a] <= hi[a])) return 0;
    diagonal += (hi[a] - lo[a]) * (hi[a] - lo[a]);
    const double e = std::max(std::abs(lo[a] - camera.eye[a]), std::abs(hi[a] - camera.eye[a]));
    farthest += e * e;
  }
  farthest = std::sqrt(farthest);
  // Widen by two pixels' footprint at the far side (the box outline is rasterized at pixel
  // centers; supersampling rays reach half a pixel further) plus the shader's pad.
  const double plane = imagePlaneHalfHeight(camera) * 2 / height;
  const double margin = 2 * plane * (camera.projection == Projection::Orthographic ? 1 : farthest) +
                        1e-5 * std::sqrt(diagonal) + hierarchy_.pad;
  for (int a = 0; a < 3; ++a) {
    lo[a] -= margin;
    hi[a] += margin;
  }
  vec3Uniform(uniform("rtBoxMin"), lo);
  vec3Uniform(uniform("rtBoxMax"), hi);
  const double farDist = 2 * farthest + 1;
  const std::array<float, 16> m = viewProjection(camera, width, height, farDist * 1e-7, farDist);
  glUniformMatrix4fv(uniform("rtViewProj"), 1, GL_FALSE, m.data());
  return 36;
}

}  // namespace zs
