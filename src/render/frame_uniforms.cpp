#include "render/frame_uniforms.hpp"

#include <algorithm>
#include <cmath>

#include "render/camera.hpp"

namespace zs {
namespace {

class UniformList {
 public:
  explicit UniformList(std::vector<UniformValue>& out) : out_(out) {}
  void integer(const char* name, int v) { out_.push_back({name, UniformValue::Kind::Int, {}, v}); }
  void real(const char* name, double v) {
    out_.push_back({name, UniformValue::Kind::Float, {float(v)}, 0});
  }
  void vec2(const char* name, double a, double b) {
    out_.push_back({name, UniformValue::Kind::Vec2, {float(a), float(b)}, 0});
  }
  void vec3(const char* name, const Vec3& v) {
    out_.push_back({name, UniformValue::Kind::Vec3, {float(v[0]), float(v[1]), float(v[2])}, 0});
  }
  void vec3(const char* name, const std::array<float, 3>& v) {
    out_.push_back({name, UniformValue::Kind::Vec3, {v[0], v[1], v[2]}, 0});
  }
  void vec4(const char* name, double a, double b, double c, double d) {
    out_.push_back({name, UniformValue::Kind::Vec4, {float(a), float(b), float(c), float(d)}, 0});
  }
  void array(const char* name, std::span<const float> v) {
    out_.push_back({name, UniformValue::Kind::FloatArray, {v.begin(), v.end()}, 0});
  }
  void mat4(const char* name, const std::array<float, 16>& m) {
    out_.push_back({name, UniformValue::Kind::Mat4, {m.begin(), m.end()}, 0});
  }

 private:
  std::vector<UniformValue>& out_;
};

// The proxy's uniforms (fullscreen.vert.glsl); returns its vertex count.
// `wholeDomain`: the box is the domain's (the volume mode draws F's field wherever it is),
// not only the part that holds the hierarchy's leaves (where hits lie).
int proxyUniforms(UniformList& u, const Camera& camera, const Domain& domain,
                  const GpuHierarchy& hierarchy, const FrameInputs& in, bool wholeDomain) {
  u.integer("rtProxy", in.proxy == Proxy::Box ? 1 : 0);
  if (in.proxy == Proxy::FullScreen) return 6;
  if (hierarchy.count == 0 && !wholeDomain) return 0;
  // Hits lie in the domain and in the root box of the hierarchy.
  Vec3 lo{}, hi{};
  double diagonal = 0, farthest = 0;
  for (int a = 0; a < 3; ++a) {
    lo[a] = wholeDomain ? domain.min[a] : std::max(domain.min[a], double(hierarchy.rootMin[a]));
    hi[a] = wholeDomain ? domain.max[a] : std::min(domain.max[a], double(hierarchy.rootMax[a]));
    if (!(lo[a] <= hi[a])) return 0;
    diagonal += (hi[a] - lo[a]) * (hi[a] - lo[a]);
    const double e = std::max(std::abs(lo[a] - camera.eye[a]), std::abs(hi[a] - camera.eye[a]));
    farthest += e * e;
  }
  farthest = std::sqrt(farthest);
  // Widen by two pixels' footprint at the far side (the box outline is rasterized at pixel
  // centers; supersampling rays reach half a pixel further) plus the shader's pad.
  const double plane = imagePlaneHalfHeight(camera) * 2 / in.height;
  const double margin = 2 * plane * (camera.projection == Projection::Orthographic ? 1 : farthest) +
                        1e-5 * std::sqrt(diagonal) + hierarchy.pad;
  for (int a = 0; a < 3; ++a) {
    lo[a] -= margin;
    hi[a] += margin;
  }
  u.vec3("rtBoxMin", lo);
  u.vec3("rtBoxMax", hi);
  const double farDist = 2 * farthest + 1;
  std::array<float, 16> viewProj =
      viewProjection(camera, in.width, in.height, farDist * 1e-7, farDist);
  if (in.bandHeight > 0) {
    // The band's rows fill the target: clip y' = (y - c w) / k, column-major rows 1 and 3.
    const double k = double(in.bandHeight) / in.height;
    const double c = 1.0 - (2.0 * in.bandTop + in.bandHeight) / in.height;
    for (int col = 0; col < 4; ++col) {
      float& y = viewProj[std::size_t(col * 4 + 1)];
      y = float((y - c * viewProj[std::size_t(col * 4 + 3)]) / k);
    }
  }
  u.mat4("rtViewProj", viewProj);
  return 36;
}

}  // namespace

FrameUniforms frameUniforms(const RenderSettings& s, const Domain& clip, const FrameInputs& in) {
  FrameUniforms result;
  UniformList u(result.values);
  const GpuHierarchy& hierarchy = *in.hierarchy;
  // Rays are clipped to the domain's bounding box, then to its ball when it is a sphere.
  const Domain domain = boundingBox(clip);
  const bool ball = clip.shape == DomainShape::Sphere;
  u.vec4("rtBall", clip.center[0], clip.center[1], clip.center[2], ball ? clip.radius : 0.0);
  u.integer("rtHierarchy", 0);
  u.integer("rtBeam", 1);    // its own unit: never aliases the hierarchy's
  u.integer("rtBeamOn", 0);  // the tracer turns it on after a beam pass
  u.integer("zs_tape", 2);   // a tape interpreter's program (interpreter/gpu_tape.hpp)
  u.integer("rtNodeCount", hierarchy.count);
  u.integer("rtFirstNode", hierarchy.rootIsLeaf ? 0 : 1);
  u.vec3("rtRootMin", hierarchy.rootMin);
  u.vec3("rtRootMax", hierarchy.rootMax);
  u.vec3("rtCell", hierarchy.cell);
  u.real("rtPad", hierarchy.pad);
  u.vec3("rtDomainMin", domain.min);
  u.vec3("rtDomainMax", domain.max);
  u.vec2("rtResolution", in.width, in.height);
  u.vec2("rtPixelOrigin", 0, in.bandHeight > 0 ? in.height - in.bandTop - in.bandHeight : 0);

  const CameraBasis basis = cameraBasis(s.camera);
  u.vec3("rtEye", basis.eye);
  u.vec3("rtForward", basis.forward);
  u.vec3("rtRight", basis.right);
  u.vec3("rtUp", basis.up);
  u.real("rtPlaneHalf", imagePlaneHalfHeight(s.camera));
  u.integer("rtOrtho", s.camera.projection == Projection::Orthographic);

  const Tracing& t = s.tracing;
  u.integer("rtIntervals", std::clamp(t.intervals, 1, 4096));
  u.integer("rtMaxBisections", std::clamp(t.maxBisections, 1, 200));
  u.real("rtEpsilon", std::isfinite(t.epsilon) && t.epsilon > 0 ? t.epsilon : 1e-6);
  u.integer("rtTangentRoots", in.tangentRoots);
  // Tangent roots are accepted within a distance far below epsilon: epsilon bounds how
  // precisely a crossing is located, not how near a ray may pass and still count as a hit.
  double diagonal = 0;
  for (int a = 0; a < 3; ++a)
    diagonal += (domain.max[a] - domain.min[a]) * (domain.max[a] - domain.min[a]);
  u.real("rtTangentTolerance", 1e-5 * std::max(std::sqrt(diagonal), 1e-6));

  // The lights themselves are shader constants (render/shading_defines.hpp).
  const Materials& m = s.materials;
  auto phong = [&](const char* name, const Material& material) {
    const std::array<double, 4> w = phongWeights(material, s.lights.ambient);
    u.vec4(name, w[0], w[1], w[2], w[3]);
  };
  u.vec3("rtFrontColor", m.front.color);
  u.vec3("rtBackColor", m.back.color);
  phong("rtFrontPhong", m.front);
  phong("rtBackPhong", m.back);
  u.real("rtCurvatureRange", in.curvatureRange > 0 ? in.curvatureRange : 1.0);

  u.integer("rtSilhouetteOn", s.silhouette.enabled);
  u.real("rtSilhouetteThreshold", s.silhouette.threshold);
  u.vec3("rtSilhouetteColor", s.silhouette.color);
  u.integer("rtBorderOn", s.border.enabled);
  u.real("rtBorderThreshold", s.border.threshold);
  u.vec3("rtBorderColor", s.border.color);
  // The cutting planes in the first slots (RT_CLIP_PLANES of them, program_variant.cpp),
  // with unit normals; an unused slot keeps everything (normal 0, offset 1e30).
  const std::vector<ClipPlane> planes = cuttingPlanes(s.clipPlanes);
  for (int k = 0; k < kMaxClipPlanes; ++k) {
    double plane[4] = {0, 0, 0, 1e30};
    if (k < int(planes.size())) {
      const Vec3& n = planes[k].normal;
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      plane[0] = n[0] / length;
      plane[1] = n[1] / length;
      plane[2] = n[2] / length;
      plane[3] = planes[k].offset / length;
    }
    u.vec4(("rtClip" + std::to_string(k)).c_str(), plane[0], plane[1], plane[2], plane[3]);
  }
  u.integer("rtCutOn", s.cut.enabled && !planes.empty());
  u.real("rtCutThreshold", s.cut.threshold);
  u.vec3("rtCutColor", s.cut.color);
  const Contours& contours = s.shading.contours;
  u.real("rtContourSpacing",
         contours.spacing > 0 && std::isfinite(contours.spacing) ? contours.spacing : 1.0);
  u.real("rtContourWidth", std::max(contours.width, 0.0));
  u.vec3("rtContourColor", contours.color);
  const Volume& volume = s.volume;
  u.real("rtVolumeDensity", std::max(volume.density, 0.0));
  u.real("rtVolumeFalloff", volume.falloff > 0 ? volume.falloff : 1.0);
  u.real("rtVolumeRange", volume.range > 0 ? volume.range : 1.0);
  u.integer("rtVolumeSteps", std::clamp(volume.steps, 1, 4096));
  u.real("rtPrimaryWeight", std::clamp(s.reflection.primaryWeight, 0.0, 1.0));
  u.real("rtOpacity", std::clamp(s.opacity, 0.0, 1.0));
  u.vec3("rtBackground", s.background);

  if (!in.params.empty()) u.array("zs_params", in.params);
  result.vertices = proxyUniforms(u, s.camera, domain, hierarchy, in, s.mode == RenderMode::Volume);
  return result;
}

}  // namespace zs
