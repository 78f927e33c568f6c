// zs_reference_compare: scenes as zeroset traces them against an independent reference in
// double precision (reference_comparison.hpp). Not a test: docs/renderer.md quotes it.
//
//   zs_reference_compare SCENE... [--size N] [--box] [--verbose] [--set KEY=VALUE]...
//
// SCENE is a .surf or .jsurf file or a formula, prepared and traced by the app's pipeline at
// N x N (default 96) with its own camera and settings; --box replaces a sphere domain by
// the box of the same half-width (SURFER's clipping radius as a box). One line per scene:
// the reference's hits, the ghost and missed pixels, and those left out; --verbose lists
// each ghost and missed pixel. Exits 3 when any scene has a ghost or missed pixel.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "app/scene_args.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "reference_comparison.hpp"

namespace zs {
namespace {

int run(int argc, char** argv) {
  int size = 96;
  bool box = false, verbose = false;
  std::vector<std::string> scenes, sets;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc)
      size = std::atoi(argv[++i]);
    else if (a == "--box")
      box = true;
    else if (a == "--verbose")
      verbose = true;
    else if (a == "--set" && i + 1 < argc)
      sets.push_back(argv[++i]);
    else
      scenes.push_back(a);
  }
  if (scenes.empty() || size < 1) {
    std::fprintf(stderr,
                 "usage: zs_reference_compare SCENE... [--size N] [--box] [--verbose] "
                 "[--set K=V]...\n");
    return 2;
  }
  int failures = 0;
  for (const std::string& path : scenes) {
    std::optional<Scene> loaded = app::loadSceneArgs({path, sets, {}});
    if (!loaded) return 1;
    Scene scene = std::move(*loaded);
    if (box) scene.domain = test::boxOfBall(scene.domain);
    scene.render.samples = 1;  // the depth of the pixel's centre ray
    auto prepared = prepareSurface(scene, kWithoutGlslang);
    if (auto* e = std::get_if<std::string>(&prepared)) {
      std::fprintf(stderr, "%s: %s", path.c_str(), e->c_str());
      return 1;
    }
    const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
    HeadlessTracer gl = openHeadlessTracer(Backend::Egl, surface, scene.render);
    if (!gl.tracer) return 1;
    const Frame frame = gl.tracer->render(scene.render, scene.domain, size, size);
    if (!frame.error.empty()) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), frame.error.c_str());
      return 1;
    }
    const test::ReferenceCounts c = test::compareWithReference(scene, surface, frame, size);
    if (verbose) std::fputs(c.details.c_str(), stdout);
    const char* method = surface.method == TracingMethod::Bernstein  ? "bernstein"
                         : surface.method == TracingMethod::Interval ? "interval"
                                                                     : "sampling";
    std::printf("%-36s %-9s hits %5d  ghost %4d (%.2f %%)  missed %4d (%.2f %%)  left out %4d\n",
                path.substr(path.find_last_of('/') + 1).c_str(), method, c.hits, c.ghost,
                100.0 * c.ghost / std::max(c.hits, 1), c.missed,
                100.0 * c.missed / std::max(c.hits, 1), c.leftOut);
    std::fflush(stdout);
    failures += c.ghost + c.missed > 0;
  }
  return failures > 0 ? 3 : 0;
}

}  // namespace
}  // namespace zs

int main(int argc, char** argv) {
  return zs::run(argc, argv);
}
