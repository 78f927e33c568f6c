#include "pipeline/load_surface.hpp"

#include <cstdlib>
#include <iostream>

#include "interpreter/interpreter_glsl.hpp"

namespace zs {

std::string loadSurface(RayTracer& tracer, const PreparedSurface& surface,
                        const RenderSettings& drawnWith) {
  std::string log;
  if (!tracer.build(surface.vertexShader, surface.fragmentShader, drawnWith, log)) return log;
  if (std::string err = tracer.setHierarchy(surface.hierarchy.packed()); !err.empty()) {
    return "error: " + err + "\n";
  }
  tracer.setParams(surface.paramsAsFloats());
  return {};
}

std::string buildInterpreter(RayTracer& tracer, bool sampling, bool polynomialOnly) {
  std::string log;
  if (!tracer.build(vertexShaderSource(ShaderDialect::Gl330),
                    interpreterFragmentShader(sampling, polynomialOnly), RenderSettings{}, log))
    return log;
  return {};
}

std::string loadQuickSurface(RayTracer& tracer, const QuickSurface& surface) {
  if (std::string err = tracer.setTape(surface.tape.texels); !err.empty())
    return "error: " + err + "\n";
  if (std::string err = tracer.setHierarchy(surface.hierarchy.packed()); !err.empty())
    return "error: " + err + "\n";
  tracer.setParams(std::vector<float>(surface.params.begin(), surface.params.end()));
  return {};
}

namespace {

// The warm-up's scene for `formula`: the interpreter's method, no curvature or markers.
Scene warmUpScene(const Scene& base, const char* formula, bool sampling) {
  Scene scene = base;
  scene.formula = formula;
  scene.render.tracing.method = sampling ? TracingMethod::Sampling : TracingMethod::Interval;
  if (needsCurvature(scene.render.shading.color)) scene.render.shading.color = ColorMode::Material;
  scene.render.singular.enabled = false;
  return scene;
}

// A sphere (polynomial) and a sphere with a sine in it (every operation).
constexpr const char* kWarmSpheres[] = {"x^2+y^2+z^2-1", "x^2+y^2+z^2-1+sin(x)/9"};

}  // namespace

std::string TapeInterpreters::warm(bool sampling, const Scene& base, const Draw& draw) {
  // The spheres, and "x^2" seen edge-on (a view with nothing in it).
  for (const char* formula : {kWarmSpheres[0], "x^2", kWarmSpheres[1]}) {
    const Scene scene = warmUpScene(base, formula, sampling);
    auto quick = prepareQuickSurface(scene);
    if (auto* err = std::get_if<std::string>(&quick)) return *err;
    const QuickSurface& q = std::get<QuickSurface>(quick);
    auto& tracer = tracers_[sampling][q.tape.polynomialOnly];
    if (!tracer) tracer = std::make_unique<RayTracer>();
    if (std::string err = buildInterpreter(*tracer, sampling, q.tape.polynomialOnly); !err.empty())
      return err;
    if (std::string err = loadQuickSurface(*tracer, q); !err.empty()) return err;
    draw(*tracer, scene);
  }
  warmed_[sampling] = true;
  return {};
}

std::string TapeInterpreters::warmFilledPictures(bool sampling, const Scene& base,
                                                 const Draw& draw) {
  if (!warmed_[sampling]) return "the interpreters are not warmed up";
  for (const char* formula : kWarmSpheres) {
    Scene scene = warmUpScene(base, formula, sampling);
    auto quick = prepareQuickSurface(scene);
    if (auto* err = std::get_if<std::string>(&quick)) return *err;
    const QuickSurface& q = std::get<QuickSurface>(quick);
    RayTracer* tracer = tracers_[sampling][q.tape.polynomialOnly].get();
    if (!tracer) return "the interpreters are not warmed up";
    if (std::string err = loadQuickSurface(*tracer, q); !err.empty()) return err;
    // From the domain's centre every tile sees the sphere.
    const Domain box = boundingBox(scene.domain);
    const Camera camera = scene.render.camera;
    for (int i = 0; i < 3; ++i) {
      const double centre = 0.5 * (box.min[i] + box.max[i]);
      scene.render.camera.eye[i] = centre;
      scene.render.camera.target[i] = centre + (camera.target[i] - camera.eye[i]);
    }
    draw(*tracer, scene);
  }
  return {};
}

RayTracer* TapeInterpreters::load(const QuickSurface& surface, std::string& error) {
  RayTracer* tracer = tracers_[surface.sampling][surface.tape.polynomialOnly].get();
  if (!warmed_[surface.sampling] || !tracer) {
    error = "the tape interpreter is not ready yet";
    return nullptr;
  }
  error = loadQuickSurface(*tracer, surface);
  return error.empty() ? tracer : nullptr;
}

void preferQuickShaderCompile(double rays) {
  if (rays <= 8e6) setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0);
}

HeadlessTracer openHeadlessTracer(Backend backend, const PreparedSurface& surface,
                                  const RenderSettings& drawnWith) {
  ContextResult ctx = createHeadlessContext(backend);
  if (!ctx.context) {
    std::cerr << "error: " << ctx.error << "\n"
              << (backend == Backend::Egl ? "hint: try --backend osmesa\n" : "");
    return {};
  }
  HeadlessTracer out{std::move(ctx.context), std::make_unique<RayTracer>()};  // needs the context
  if (std::string err = loadSurface(*out.tracer, surface, drawnWith); !err.empty()) {
    std::cerr << err;
    return {};
  }
  return out;
}

}  // namespace zs
