#pragma once
// Inspecting one point of the picture: takes a formula with its parameter values, the
// scene's domain and camera, and a pixel of a width x height picture (or any ray), puts out
// where that ray first meets F = 0 inside the domain, and there F, grad F, the unit normal,
// the Gaussian and mean curvature K and H and the principal curvatures k1 >= k2, from the
// symbolic Hessian in double (docs/curvature.md for the formulas and the orientation). The
// first root is isolated with interval arithmetic on the CPU (src/interval), with the
// tangent tolerance of the tracer (docs/renderer.md), so no GPU is needed: the command line
// (`zeroset probe`), the viewer and the web page share it.
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "parser/parser.hpp"
#include "render/camera.hpp"
#include "scene/scene.hpp"

namespace zs {

struct ProbeResult {
  bool hit = false;
  double t = 0;  // along the unit ray, from its origin
  Vec3 point{};
  double value = 0;  // F at the point (near 0: the root is located within 1e-12 of t)
  Vec3 gradient{};
  // grad F / |grad F| and the curvatures; NaN where grad F = 0 (a singular point).
  Vec3 normal{};
  double gaussian = 0, mean = 0, k1 = 0, k2 = 0;
  // In a scene of `surfaces` surfaces, the one hit (0-based; its F, gradient and curvature).
  int surface = 0;
  int surfaces = 1;
};

// One formula prepared for probing: its gradient and Hessian and the tapes that evaluate
// them, made once, so each pixel costs only the search (the hover readouts keep one per
// surface on screen). Not thread-safe: the evaluators reuse their buffers.
class SurfaceProbe {
 public:
  explicit SurfaceProbe(const Formula& formula);
  ~SurfaceProbe();
  SurfaceProbe(const SurfaceProbe&) = delete;
  SurfaceProbe& operator=(const SurfaceProbe&) = delete;

  // probeRay and probePixel below, for this formula.
  // `clip`: the scene's clip planes, which cut the ray as they cut the tracer's.
  std::variant<ProbeResult, std::string> ray(std::span<const double> params, const Domain& domain,
                                             const Ray& ray, std::span<const ClipPlane> clip = {});
  std::variant<ProbeResult, std::string> pixel(std::span<const double> params, const Scene& scene,
                                               int width, int height, int x, int y);

 private:
  struct Evaluators;
  std::unique_ptr<Evaluators> eval_;
};

// Every surface of a scene prepared for probing: a pixel's result is the nearest of their
// first hits, with that surface's own F, gradient and curvatures (a scene of several
// surfaces is traced as their product, whose gradient would mix them). Not thread-safe.
class SceneProbe {
 public:
  // Parses the scene's formulas; on an error (as parseSceneFormula's) error() says it.
  explicit SceneProbe(const Scene& scene);
  ~SceneProbe();
  const std::string& error() const { return error_; }
  // True when `scene` draws the same functions (formulas and levels) as the one probed.
  bool sameSurfaces(const Scene& scene) const;
  std::variant<ProbeResult, std::string> pixel(const Scene& scene, int width, int height, int x,
                                               int y);

 private:
  std::vector<std::pair<std::string, double>> functions_;  // formula and level of each
  std::vector<Formula> formulas_;
  std::vector<std::unique_ptr<SurfaceProbe>> probes_;
  std::string error_;
};

// The first root along `ray` inside the domain (box, or ball), or hit = false. An error
// only when the search runs out of its budget (a ray grazing a surface over its whole length).
std::variant<ProbeResult, std::string> probeRay(const Formula& formula,
                                                std::span<const double> params,
                                                const Domain& domain, const Ray& ray);

// The same for the centre of pixel (x, y) of the picture `zeroset render` draws at
// width x height (docs/camera.md), x from the left and y from the top, both from 0.
std::variant<ProbeResult, std::string> probePixel(const Formula& formula,
                                                  std::span<const double> params,
                                                  const Scene& scene, int width, int height, int x,
                                                  int y);

// "name: value" lines (point, F, gradient, normal, K, H, k1, k2), or a JSON object with the
// same keys; a miss says so ("hit: false").
std::string probeText(const ProbeResult& result);
std::string probeJson(const ProbeResult& result);

}  // namespace zs
