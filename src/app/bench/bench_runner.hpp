#pragma once
// The measuring half of `zeroset bench`: takes the options and the plan (bench_plan.hpp),
// needs nothing current (it creates its own headless GL context), and puts out per
// surface the time to first frame split by stage, and per configuration the median frame
// time over `frames` glFinish-timed full-frame draws (after `warmup` untimed ones) with
// the octree build time and leaf count. Progress goes to stderr as it runs. Failures of a
// surface or a configuration are recorded in its result, never thrown.
#include <cstddef>
#include <string>
#include <vector>

#include "app/bench/bench_plan.hpp"
#include "pipeline/pipeline.hpp"
#include "scene/scene.hpp"

namespace zs::bench {

// From typed formula to first pixels, for the scene defaults (octree level 1, 10
// intervals, epsilon 0.001). GL compile is glCompileShader + glLinkProgram; llvmpipe
// JIT-compiles the fragment shader at the first draw, so firstDrawMs holds the JIT.
struct FirstFrame {
  int surface = 0;
  TracingMethod method = TracingMethod::Sampling;  // as resolved for the formula
  StageTimes cpu;  // parse (+ gradient), octree (+ box hierarchy), codegen, glslang
  double glCompileMs = 0;
  double firstDrawMs = 0;
  double totalMs = 0;  // wall time of all of the above, end to end
  std::string error;
};

struct FrameStats {
  int frames = 0;
  double medianMs = 0, minMs = 0, maxMs = 0;
  double fps() const { return medianMs > 0 ? 1000.0 / medianMs : 0; }
};

struct ConfigResult {
  BenchConfig config;
  FrameStats stats;
  double octreeMs = 0;  // octree + box hierarchy build, wall time
  std::size_t leaves = 0;
  std::size_t nodes = 0;  // of the box hierarchy the shader walks
  std::string error;
};

struct BenchResults {
  BenchOptions options;
  std::string device;       // GL_VERSION / GL_RENDERER
  std::string shaderCache;  // value of MESA_SHADER_CACHE_DISABLE during the run
  unsigned cpuThreads = 0;  // std::thread::hardware_concurrency()
  double contextMs = 0;     // headless context creation, not part of any first frame
  std::vector<FirstFrame> firstFrames;
  std::vector<ConfigResult> configs;
  std::string error;  // non-empty: no GL context, nothing was measured
};

// Median of the values (mean of the middle two for an even count); 0 when empty.
double median(std::vector<double> values);

BenchResults runBench(const BenchOptions& options, const std::vector<BenchConfig>& plan);

// `zeroset bench INPUT`: one scene (a formula or a .surf, with its own octree level and
// settings) timed with each tracing method at options' size.
struct MethodResult {
  TracingMethod method = TracingMethod::Sampling;
  std::string skipped;  // why this method was not timed (not a polynomial, ...); "" if it was
  FirstFrame first;     // cold shader cache: what a user waits for after typing the formula
  FrameStats stats;
  std::size_t leaves = 0;
  std::string error;
};

struct InputBenchResults {
  BenchOptions options;
  std::string device, shaderCache;
  unsigned cpuThreads = 0;
  Scene scene;
  std::vector<MethodResult> methods;  // sampling, bernstein, interval
  std::string error;                  // non-empty: no GL context, nothing was measured
};

InputBenchResults runInputBench(const Scene& scene, const BenchOptions& options);

}  // namespace zs::bench
