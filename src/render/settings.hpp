#pragma once
// Plain data: everything that decides how a surface is drawn. The scene loader fills it,
// the command line and the viewer edit it, the renderer reads it. Defaults here are the
// documented defaults of docs/surf-format.md.
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace zs {

using Vec3 = std::array<double, 3>;

enum class Projection { Perspective, Orthographic };

struct Camera {
  Vec3 eye{0, 0, 4};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 1, 0};
  Projection projection = Projection::Perspective;
  double fovY = 40.0;   // degrees, perspective
  double height = 3.0;  // world units covered vertically, orthographic

  bool operator==(const Camera&) const = default;
};

enum class DomainShape { Box, Sphere };

// Where the surface is shown: the box [min, max] (the thesis' domain), or the ball of the
// given center and radius (SURFER's clipping sphere), when min and max are not used.
struct Domain {
  Vec3 min{-1.5, -1.5, -1.5};
  Vec3 max{1.5, 1.5, 1.5};
  DomainShape shape = DomainShape::Box;
  Vec3 center{0, 0, 0};
  double radius = 1.5;

  bool operator==(const Domain&) const = default;
};

// The box the octree subdivides and rays are clipped to first: the box itself, or the
// ball's bounding box (shape Box either way).
inline Domain boundingBox(const Domain& d) {
  if (d.shape == DomainShape::Box) return d;
  Domain box;
  for (int a = 0; a < 3; ++a) {
    box.min[a] = d.center[a] - d.radius;
    box.max[a] = d.center[a] + d.radius;
  }
  return box;
}

enum class LightKind { Directional, Point };

// Where lights are given: fixed in the world, or to the camera (Lights::space).
enum class LightSpace { World, Camera };

// One light source. A directional light shines from infinitely far along `direction`; a
// point light from `position`, with no falloff (SURFER's lights have none either). Both keep
// their unused vector, so switching the kind back and forth loses nothing.
struct Light {
  LightKind kind = LightKind::Directional;
  bool enabled = true;
  Vec3 direction{-0.4, -0.6, -1.0};  // directional: the direction the light travels
  Vec3 position{3, 3, 4};            // point
  double intensity = 0.8;
  Vec3 color{1, 1, 1};

  bool operator==(const Light&) const = default;
};

// At most this many lights (SURFER shows up to 8 at once). Each light is a compile-time
// constant of the shader (docs/renderer.md), so the bound keeps the unrolled shading short.
inline constexpr int kMaxLights = 8;

// The thesis' two lights: a directional light from the upper left and a point light.
inline std::vector<Light> thesisLights() {
  Light point;
  point.kind = LightKind::Point;
  point.intensity = 0.6;
  return {Light{}, point};
}

struct Lights {
  double ambient = 0.15;  // ambient light, weighted by each material's ambient
  // Where the lights' directions and positions are given: fixed in the world, or fixed to
  // the camera and turning with it, as SURFER's (camera coordinates: from the eye, x right,
  // y up, z towards the viewer, in the world's units; render/camera.hpp).
  LightSpace space = LightSpace::World;
  std::vector<Light> sources = thesisLights();  // at most kMaxLights; may be empty

  bool operator==(const Lights&) const = default;
};

// The first light of `kind` that is on, or nullptr: what the viewer's keys move.
inline Light* firstLight(Lights& lights, LightKind kind) {
  for (Light& l : lights.sources) {
    if (l.kind == kind && l.enabled) return &l;
  }
  return nullptr;
}

// The key light: the first light that is on, of either kind, or nullptr. The viewer's
// right drag turns it.
inline Light* keyLight(Lights& lights) {
  for (Light& l : lights.sources) {
    if (l.enabled) return &l;
  }
  return nullptr;
}

// Phong material. The color is lit as color * (ambient * lights.ambient + diffuse * sum of
// the lights' n.l terms) + specular highlights (docs/renderer.md has the whole formula).
struct Material {
  Vec3 color{0.85, 0.55, 0.2};
  double specular = 0.5;    // weight of the specular highlights
  double shininess = 40.0;  // Phong exponent
  double ambient = 1.0;     // weight of lights.ambient
  double diffuse = 1.0;     // weight of the lights' diffuse terms

  bool operator==(const Material&) const = default;
};

// A material's Phong weights as the shader takes them: (ambient * the scene's ambient light,
// diffuse, specular, shininess), negative ambient light and shininess taken as 0.
inline std::array<double, 4> phongWeights(const Material& m, double ambientLight) {
  return {m.ambient * (ambientLight > 0 ? ambientLight : 0.0), m.diffuse, m.specular,
          m.shininess > 0 ? m.shininess : 0.0};
}

// front: where the gradient of F points towards the viewer; back: the other side (the
// inside of a closed surface, seen through a cut).
struct Materials {
  Material front{};
  Material back{{0.25, 0.55, 0.85}, 0.5, 40.0};

  bool operator==(const Materials&) const = default;
};

// What colors a hit: the materials, the Gaussian or mean curvature of the surface through a
// diverging color map, or the unit normal as RGB (docs/curvature.md).
enum class ColorMode { Material, Gauss, Mean, Normal };

inline bool needsCurvature(ColorMode m) {
  return m == ColorMode::Gauss || m == ColorMode::Mean;
}

// Contour lines on the surface: where a function g of x, y, z (a formula without parameters)
// is a multiple of `spacing`, in a band `width` wide measured along the surface.
struct Contours {
  bool enabled = false;
  std::string function = "z";
  double spacing = 0.1;
  double width = 0.01;
  Vec3 color{0.1, 0.1, 0.1};

  bool operator==(const Contours&) const = default;
};

struct Shading {
  ColorMode color = ColorMode::Material;
  // The curvature shown at the ends of the color map (the map is symmetric about 0); 0 picks
  // it from the picture: the 95th percentile of |curvature| over the visible surface.
  double curvatureRange = 0;
  // A shadow ray towards each light from the first hit, traced by the tracing method itself:
  // a light that something blocks adds no diffuse or specular there (docs/renderer.md).
  bool shadows = false;
  Contours contours;

  bool operator==(const Shading&) const = default;
};

// How rays find the surface (docs/renderer.md). Auto: Bernstein for polynomials up to
// kMaxBernsteinDegree, interval otherwise; sampling (the thesis' method) only when asked.
enum class TracingMethod { Auto, Bernstein, Sampling, Interval };

// As tracing.method spells it in a scene (the schema's table lists them in this order).
inline const char* tracingMethodName(TracingMethod m) {
  switch (m) {
    case TracingMethod::Auto:
      return "auto";
    case TracingMethod::Bernstein:
      return "bernstein";
    case TracingMethod::Sampling:
      return "sampling";
    case TracingMethod::Interval:
      return "interval";
  }
  return "auto";
}

// Highest degree the Bernstein method takes. Measured exact against a double reference up to
// degree 32 (tests/render/degree_limit_test.cpp; float below degree 9, double from there);
// the limit is compile time: the unrolled kernels grow as D^2 (degree 20: 0.67 s to the
// first frame on llvmpipe), and sampling takes over above it (docs/renderer.md).
inline constexpr int kMaxBernsteinDegree = 20;

struct Tracing {
  TracingMethod method = TracingMethod::Auto;
  int intervals = 10;      // sampling: sign samples per leaf segment (thesis: "intervalos")
  double epsilon = 0.001;  // root refinement stops when the bracket is below this
  int maxBisections = 40;  // safety bound on refinement steps (both methods)
  int hits = 4;            // n nearest hits kept per ray

  bool operator==(const Tracing&) const = default;
};

struct Highlight {
  bool enabled = true;
  // silhouette: |cos| below; border: distance to a face below; singular: marker radius
  double threshold = 0.15;
  Vec3 color{0.05, 0.05, 0.05};

  bool operator==(const Highlight&) const = default;
};

// Cross-sections: a plane cuts away the side where normal . p > offset (the domain keeps
// what no plane cuts). Normals need not be unit length; a zero normal is refused by the scene.
struct ClipPlane {
  bool enabled = true;
  Vec3 normal{0, 0, 1};
  double offset = 0;

  bool operator==(const ClipPlane&) const = default;
};

inline constexpr int kMaxClipPlanes = 4;

// The planes that cut: enabled, with a finite offset and a finite, non-zero normal (the
// scene refuses a zero normal; a plane built in code may still have one).
inline std::vector<ClipPlane> cuttingPlanes(const std::vector<ClipPlane>& planes) {
  std::vector<ClipPlane> out;
  for (const ClipPlane& p : planes) {
    const double n2 =
        p.normal[0] * p.normal[0] + p.normal[1] * p.normal[1] + p.normal[2] * p.normal[2];
    if (p.enabled && n2 > 0 && std::isfinite(n2) && std::isfinite(p.offset) &&
        int(out.size()) < kMaxClipPlanes)
      out.push_back(p);
  }
  return out;
}

struct Reflection {
  bool enabled = true;
  double primaryWeight = 0.7;  // color = primary*w + reflected*(1-w)

  bool operator==(const Reflection&) const = default;
};

// What a frame shows: the surface F = level, or F's scalar field as a volume (emission and
// absorption along each ray through a transfer function around the level).
enum class RenderMode { Surface, Volume };

// The volume's transfer function (docs/renderer.md, "Volume rendering"): at a sample where
// v = F - level, the color is the diverging map of v / range (blue below the level, white at
// it, red above) and the extinction density * exp(-(v / falloff)^2); `steps` samples along
// the ray's span in the domain, by the midpoint rule.
struct Volume {
  double density = 8;
  double falloff = 0.1;
  double range = 0.25;
  int steps = 256;

  bool operator==(const Volume&) const = default;
};

struct RenderSettings {
  Camera camera;
  Lights lights;
  Materials materials;
  Shading shading;
  Tracing tracing;
  Highlight silhouette{true, 0.15, {0.05, 0.05, 0.05}};
  Highlight border{true, 0.01, {0.9, 0.9, 0.9}};
  // Certified singular points (src/singular) drawn as small spheres of this radius.
  Highlight singular{false, 0.04, {0.9, 0.15, 0.55}};
  std::vector<ClipPlane> clipPlanes;  // at most kMaxClipPlanes
  // The curve where the surface meets a clip plane: hits closer to a plane than this.
  Highlight cut{true, 0.02, {0.85, 0.12, 0.1}};
  // The curves where two surfaces of the scene meet: hits whose distance to another
  // surface (|F| / |grad F|, to first order) is below this.
  Highlight intersection{true, 0.02, {0.1, 0.1, 0.1}};
  Reflection reflection;
  double opacity = 1.0;  // < 1 blends the kept hits front to back
  int samples = 1;       // N x N supersampling
  Vec3 background{1, 1, 1};
  RenderMode mode = RenderMode::Surface;
  Volume volume;

  bool operator==(const RenderSettings&) const = default;
};

}  // namespace zs
