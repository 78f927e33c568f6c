#include "app/bench/bench_runner.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "app/bench/thesis_data.hpp"
#include "render/ray_tracer.hpp"

namespace zs::bench {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

Scene sceneFor(std::string_view formula, const BenchOptions& options) {
  Scene scene;  // documented defaults: camera, lights, domain [-1.5, 1.5]^3, level 1
  scene.formula = std::string(formula);
  scene.width = options.width;
  scene.height = options.height;
  return scene;
}

// One full-frame draw, waited for: glFinish is what makes the time the frame's and not
// the time to queue a command (llvmpipe renders on its own threads).
std::string timedDraw(RayTracer& tracer, const Scene& scene, double& ms) {
  const auto start = Clock::now();
  std::string error = tracer.drawOffscreen(scene.render, scene.domain, scene.width, scene.height);
  glFinish();
  ms = msSince(start);
  return error;
}

// Everything a user waits for after typing a formula, on a context and ray tracer that
// already exist (the viewer's situation). `prepared` keeps the CPU results for reuse.
FirstFrame measureFirstFrame(int number, const Scene& scene, RayTracer& tracer,
                             std::optional<PreparedSurface>& prepared) {
  FirstFrame ff;
  ff.surface = number;
  ff.method = scene.render.tracing.method;
  const auto start = Clock::now();
  auto result = prepareSurface(scene);
  if (auto* err = std::get_if<std::string>(&result)) {
    ff.error = *err;
    return ff;
  }
  prepared = std::get<PreparedSurface>(std::move(result));
  ff.method = prepared->method;
  ff.cpu = prepared->times;
  auto t = Clock::now();
  std::string log;
  if (!tracer.build(prepared->vertexShader, prepared->fragmentShader, scene.render, log)) {
    ff.error = log;
    return ff;
  }
  ff.glCompileMs = msSince(t);
  if (std::string err = tracer.setHierarchy(prepared->hierarchy.packed()); !err.empty()) {
    ff.error = err;
    return ff;
  }
  tracer.setParams(prepared->paramsAsFloats());
  ff.error = timedDraw(tracer, scene, ff.firstDrawMs);
  ff.totalMs = msSince(start);
  return ff;
}

// Builds the octree and box hierarchy of one level and hands them to the tracer.
std::string loadLevel(const PreparedSurface& surface, Scene& scene, int level, RayTracer& tracer,
                      ConfigResult& info) {
  scene.octree.level = level;
  const auto start = Clock::now();
  OctreeResult tree = buildOctree(surface.formula, surface.params, toBox(scene.domain),
                                  scene.octree, toBall(scene.domain));
  if (auto* err = std::get_if<OctreeError>(&tree)) return err->message;
  const Octree& octree = std::get<Octree>(tree);
  const BoxHierarchy hierarchy =
      tracingHierarchy(surface.formula, surface.params, octree, surface.method);
  info.octreeMs = msSince(start);
  info.leaves = octree.leaves.size();
  info.nodes = hierarchy.nodes.size();
  return tracer.setHierarchy(hierarchy.packed());
}

FrameStats timeFrames(RayTracer& tracer, const Scene& scene, const BenchOptions& options,
                      std::string& error) {
  FrameStats stats;
  std::vector<double> times;
  double ms = 0;
  for (int i = 0; i < options.warmup + options.frames && error.empty(); ++i) {
    error = timedDraw(tracer, scene, ms);
    if (i >= options.warmup) times.push_back(ms);
  }
  if (times.empty()) return stats;
  stats.frames = static_cast<int>(times.size());
  stats.minMs = *std::min_element(times.begin(), times.end());
  stats.maxMs = *std::max_element(times.begin(), times.end());
  stats.medianMs = median(std::move(times));
  return stats;
}

// Times every configuration of one surface, building each octree level once.
void benchSurface(const PreparedSurface& surface, Scene scene,
                  const std::vector<BenchConfig>& configs, const BenchOptions& options,
                  RayTracer& tracer, BenchResults& out, std::size_t& done, std::size_t total) {
  ConfigResult levelInfo;
  std::string levelError;
  int loadedLevel = -1;
  for (const BenchConfig& config : configs) {
    if (config.level != loadedLevel) {
      levelInfo = {};
      levelError = loadLevel(surface, scene, config.level, tracer, levelInfo);
      loadedLevel = config.level;
    }
    ConfigResult r = levelInfo;
    r.config = config;
    r.error = levelError;
    scene.render.tracing.intervals = config.intervals;
    scene.render.tracing.epsilon = config.epsilon;
    if (r.error.empty()) r.stats = timeFrames(tracer, scene, options, r.error);
    out.configs.push_back(r);
    ++done;
    if (r.error.empty()) {
      std::fprintf(stderr,
                   "[%zu/%zu] surface %d, %s, level %d, %d intervals, epsilon %s: %.2f ms "
                   "median (%.1f fps), %zu leaves\n",
                   done, total, config.surface, tracingMethodName(config.method), config.level,
                   config.intervals, formatEpsilon(config.epsilon).c_str(), r.stats.medianMs,
                   r.stats.fps(), r.leaves);
    } else {
      std::fprintf(stderr, "[%zu/%zu] surface %d, level %d: FAILED: %s\n", done, total,
                   config.surface, config.level, r.error.c_str());
    }
  }
}

// The measuring context: llvmpipe JIT-compiles at the first draw, and a warm Mesa disk cache
// would hide that cost from the time to first frame (an explicit setting in the environment
// is respected). Returns the context, or nothing with `error` set.
std::unique_ptr<GlContext> openBenchContext(const BenchOptions& options, std::string& shaderCache,
                                            std::string& device, double& contextMs,
                                            std::string& error) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
  shaderCache = std::getenv("MESA_SHADER_CACHE_DISABLE");
  const auto start = Clock::now();
  ContextResult ctx = createHeadlessContext(options.backend);
  if (!ctx.context) {
    error = ctx.error;
    return nullptr;
  }
  contextMs = msSince(start);
  device = GlContext::describeCurrent();
  return std::move(ctx.context);
}

// One-time driver start-up (LLVM initialisation, the vertex stage, the render target) is
// paid once per process, not per formula: pay it on a sphere nobody measures.
void payDriverStartUp(RayTracer& tracer, const BenchOptions& options) {
  std::optional<PreparedSurface> unused;
  measureFirstFrame(0, sceneFor("x^2 + y^2 + z^2 - 1", options), tracer, unused);
}

}  // namespace

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  if (values.size() % 2 == 1) return values[mid];
  const double upper = values[mid];
  const double lower = *std::max_element(values.begin(), values.begin() + mid);
  return (lower + upper) / 2;
}

BenchResults runBench(const BenchOptions& options, const std::vector<BenchConfig>& plan) {
  BenchResults results;
  results.options = options;
  results.cpuThreads = std::thread::hardware_concurrency();
  auto context = openBenchContext(options, results.shaderCache, results.device, results.contextMs,
                                  results.error);
  if (!context) return results;
  RayTracer tracer;
  payDriverStartUp(tracer, options);
  std::fprintf(stderr, "bench: %s, %dx%d, %d frames after %d warm-up, %zu configurations\n",
               results.device.c_str(), options.width, options.height, options.frames,
               options.warmup, plan.size());

  std::size_t done = 0;
  for (const ThesisSurface& surface : kThesisSurfaces) {
    for (TracingMethod method : {TracingMethod::Sampling, TracingMethod::Bernstein}) {
      std::vector<BenchConfig> configs;
      for (const BenchConfig& c : plan)
        if (c.surface == surface.number && c.method == method) configs.push_back(c);
      if (configs.empty()) continue;
      Scene scene = sceneFor(surface.formula, options);
      scene.render.tracing.method = method;
      std::optional<PreparedSurface> prepared;
      FirstFrame ff = measureFirstFrame(surface.number, scene, tracer, prepared);
      if (ff.error.empty() && ff.method != method) ff.error = prepared->methodWarning;
      results.firstFrames.push_back(ff);
      if (!ff.error.empty()) {
        std::fprintf(stderr, "surface %d (%s): FAILED before its first frame:\n%s\n",
                     surface.number, tracingMethodName(method), ff.error.c_str());
        for (const BenchConfig& c : configs) results.configs.push_back({c, {}, 0, 0, 0, ff.error});
        done += configs.size();
        continue;
      }
      std::fprintf(stderr,
                   "surface %d (%s), %s: first frame after %.0f ms (CPU %.1f, GL compile "
                   "%.1f, first draw %.1f)\n",
                   surface.number, std::string(surface.formula).c_str(), tracingMethodName(method),
                   ff.totalMs,
                   ff.cpu.parseMs + ff.cpu.octreeMs + ff.cpu.codegenMs + ff.cpu.validateMs,
                   ff.glCompileMs, ff.firstDrawMs);
      benchSurface(*prepared, scene, configs, options, tracer, results, done, plan.size());
    }
  }
  return results;
}

InputBenchResults runInputBench(const Scene& input, const BenchOptions& options) {
  InputBenchResults results;
  results.options = options;
  results.scene = input;
  results.cpuThreads = std::thread::hardware_concurrency();
  double contextMs = 0;
  auto context =
      openBenchContext(options, results.shaderCache, results.device, contextMs, results.error);
  if (!context) return results;
  RayTracer tracer;
  payDriverStartUp(tracer, options);
  // Every method that can trace the input, side by side (bernstein only for polynomials). A
  // volume is drawn by the one program the pipeline picks whatever the method: one row, named
  // after that program's method.
  const bool volume = input.render.mode == RenderMode::Volume;
  const std::vector<TracingMethod> methods =
      volume ? std::vector<TracingMethod>{TracingMethod::Auto}
             : std::vector<TracingMethod>{TracingMethod::Sampling, TracingMethod::Bernstein,
                                          TracingMethod::Interval};
  for (TracingMethod method : methods) {
    MethodResult r;
    r.method = method;
    Scene scene = input;
    scene.width = options.width;
    scene.height = options.height;
    scene.render.tracing.method = method;
    std::fprintf(stderr, "bench: %s, first frame...\n", tracingMethodName(method));
    std::optional<PreparedSurface> prepared;
    r.first = measureFirstFrame(0, scene, tracer, prepared);
    if (volume && prepared) r.method = prepared->method;
    if (!r.first.error.empty()) {
      r.error = r.first.error;
    } else if (prepared->method != r.method) {
      r.skipped = prepared->methodWarning;  // e.g. not a polynomial: no bernstein row
      while (!r.skipped.empty() && r.skipped.back() == '\n') r.skipped.pop_back();
    } else {
      r.leaves = prepared->octree.leaves.size();
      std::fprintf(stderr, "bench: %s, %d frames...\n", tracingMethodName(method),
                   options.warmup + options.frames);
      r.stats = timeFrames(tracer, scene, options, r.error);
    }
    results.methods.push_back(r);
  }
  return results;
}

}  // namespace zs::bench
