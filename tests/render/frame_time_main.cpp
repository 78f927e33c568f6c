// zs_render_frame_time FORMULA [WxH] [octree level] [frames] [--osmesa] [--no-tangent]
//   [--no-reflection] [--samples N] [--intervals N] [--epsilon E] [--sampling] [--png out.png]:
// median glFinish-timed frame time of the real pipeline at the default (method: Bernstein for
// polynomials, --sampling for the thesis' method)
// settings (camera (0,0,4), domain [-1.5,1.5]^3), plus the time to the first frame
// (shader JIT). Not a test: the numbers in docs/renderer.md come from here.
#include <glad/gl.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "render_support.hpp"

using namespace zs;
using Clock = std::chrono::steady_clock;

// CPU time of the whole process (all llvmpipe threads): on a machine shared with other
// jobs wall time inflates, CPU time much less; CPU / threads estimates an idle machine.
static double cpuMs() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 +
         (u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e3;
}

static double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(
        stderr,
        "usage: %s FORMULA [WxH] [level] [frames] [--osmesa] [--no-tangent] [--png out.png]\n",
        argv[0]);
    return 2;
  }
  int w = 800, h = 600, level = 3, frames = 15;
  bool osmesa = false, tangent = true, reflection = true;
  int samples = 1, intervals = 10;
  double epsilon = 0.001;
  const char* png = nullptr;
  bool sampling = false;
  std::vector<const char*> positional;
  for (int i = 2; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--osmesa"))
      osmesa = true;
    else if (!std::strcmp(argv[i], "--no-tangent"))
      tangent = false;
    else if (!std::strcmp(argv[i], "--no-reflection"))
      reflection = false;
    else if (!std::strcmp(argv[i], "--samples") && i + 1 < argc)
      samples = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--intervals") && i + 1 < argc)
      intervals = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--epsilon") && i + 1 < argc)
      epsilon = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--png") && i + 1 < argc)
      png = argv[++i];
    else if (!std::strcmp(argv[i], "--sampling"))
      sampling = true;
    else
      positional.push_back(argv[i]);
  }
  if (positional.size() > 0) std::sscanf(positional[0], "%dx%d", &w, &h);
  if (positional.size() > 1) level = std::atoi(positional[1]);
  if (positional.size() > 2) frames = std::max(1, std::atoi(positional[2]));

  std::string error;
  if (!test::context(osmesa ? Backend::OsMesa : Backend::Egl, error)) {
    std::fprintf(stderr, "no GL context: %s\n", error.c_str());
    return 1;
  }
  test::SurfaceSpec spec{argv[1]};
  spec.octreeLevel = level;
  if (sampling) spec.method = TracingMethod::Sampling;
  const auto start = Clock::now();
  auto tracer = test::makeTracer(spec, error);
  if (!tracer) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  tracer->setTangentRoots(tangent);
  RenderSettings settings = test::testSettings({0, 0, 4});
  settings.reflection.enabled = reflection;
  settings.samples = samples;
  settings.tracing.intervals = intervals;
  settings.tracing.epsilon = epsilon;
  if (std::string e = tracer->drawOffscreen(settings, spec.domain, w, h); !e.empty()) {
    std::fprintf(stderr, "%s\n", e.c_str());
    return 1;
  }
  glFinish();
  const double first = msSince(start);
  std::vector<double> times;
  const double cpuStart = cpuMs();
  for (int f = 0; f < frames; ++f) {
    const auto t = Clock::now();
    tracer->drawOffscreen(settings, spec.domain, w, h);
    glFinish();
    times.push_back(msSince(t));
  }
  const double cpuPerFrame = (cpuMs() - cpuStart) / frames;
  std::sort(times.begin(), times.end());
  std::printf(
      "%s  %s  %dx%d level %d tangent %s reflection %s samples %d intervals %d epsilon %g: median "
      "%.1f ms (min %.1f, max %.1f), CPU %.1f ms/frame, first frame %.0f ms\n",
      argv[1], sampling ? "sampling" : "default method", w, h, level, tangent ? "on" : "off",
      reflection ? "on" : "off", samples, intervals, epsilon, times[times.size() / 2],
      times.front(), times.back(), cpuPerFrame, first);
  if (png) {
    Frame frame = tracer->render(settings, spec.domain, w, h);
    if (!frame.error.empty() || !writePng(png, frame.color).empty()) return 1;
  }
  return 0;
}
