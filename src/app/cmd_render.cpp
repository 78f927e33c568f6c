// `zeroset render SCENE|FORMULA -o out.png [--size WxH] [--depth out.pfm]
// [--backend egl|osmesa] [--set KEY=VALUE]...`: one picture, headless. With
// `--animate KEY=FROM:TO [--frames N] [--video out.mp4] [--shard K/N]`, -o is a folder of
// numbered frames (animate/render_frames.hpp).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

#include "app/animate/render_frames.hpp"
#include "app/commands.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "app/scene_args.hpp"
#include "render/gl_context.hpp"
#include "render/ray_tracer.hpp"

namespace zs::app {

namespace {

struct RenderArgs {
  SceneArgs scene;
  std::string output;
  std::string size;
  std::string depth;
  std::string backend = "egl";
  AnimateOptions animate;  // used when animate.spec is set
  std::string shard;       // --shard K/N
};

bool parseSize(const std::string& text, int& w, int& h) {
  char x = 0;
  char rest = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) == 3 && (x == 'x' || x == 'X') &&
         w > 0 && h > 0 && w <= 16384 && h <= 16384;
}

int runRender(const RenderArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  if (!args.size.empty() && !parseSize(args.size, scene->width, scene->height)) {
    std::cerr << "error: --size '" << args.size << "' is not WIDTHxHEIGHT\n"
              << "hint: e.g. --size 800x600 (1 to 16384 pixels each way)\n";
    return 1;
  }
  Backend backend;
  if (!parseBackend(args.backend, backend)) {
    std::cerr << "error: unknown backend '" << args.backend << "'\nhint: egl or osmesa\n";
    return 1;
  }
  if (!args.animate.spec.empty()) {
    AnimateOptions animate = args.animate;
    animate.outDir = args.output;
    if (!args.shard.empty()) {
      std::string error;
      if (!parseShard(args.shard, animate.shard, animate.shards, error)) {
        std::cerr << error;
        return 1;
      }
    }
    return renderAnimation(*scene, animate, backend);
  }
  // Everything that can fail on the user's input fails here, before any GL context exists.
  auto prepared = prepareSurface(*scene);
  if (auto* err = std::get_if<std::string>(&prepared)) {
    std::cerr << *err;
    return 1;
  }
  const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
  std::cerr << surface.constantNote << surface.methodWarning << surface.singularNote;

  // One frame: on llvmpipe the JIT compile of the shader costs more than the frame unless
  // the image is large. Without LLVM's optimization passes the JIT takes about half as long
  // and the frame a fifth longer, so below some 8 megapixels of rays the picture is ready
  // sooner that way (docs/renderer.md has the measurement).
  // Mesa reads this once, when the driver starts; a value the user set is kept. Other
  // drivers ignore it.
  const double rays = double(scene->width) * scene->height * scene->render.samples *
                      scene->render.samples;
  if (rays <= 8e6) setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0);
  HeadlessTracer gl = openHeadlessTracer(backend, surface);
  if (!gl.tracer) return 1;
  RayTracer& tracer = *gl.tracer;

  const bool showProgress = isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  Frame frame = tracer.render(scene->render, scene->domain, scene->width, scene->height,
                              [showProgress](int done, int total) {
                                if (showProgress) {
                                  std::fprintf(stderr, "\rrendering: tile %d of %d", done, total);
                                }
                                return true;
                              });
  if (showProgress) std::fprintf(stderr, "\r\033[K");
  if (!frame.error.empty()) {
    std::cerr << "error: " << frame.error << "\n";
    return 1;
  }
  const double renderMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (std::string err = writePng(args.output, frame.color); !err.empty()) {
    std::cerr << "error: " << err << "\n";
    return 1;
  }
  if (!args.depth.empty()) {
    if (std::string err = writePfm(args.depth, frame.depth); !err.empty()) {
      std::cerr << "error: " << err << "\n";
      return 1;
    }
  }
  std::printf("wrote %s (%dx%d) in %.0f ms: %zu octree leaves, %s\n", args.output.c_str(),
              scene->width, scene->height, renderMs, surface.octree.leaves.size(),
              gl.context->backendName().c_str());
  // The picture's color map has no legend: say what its ends stand for.
  if (frame.curvatureRange > 0)
    std::printf("curvature color map: blue -%.4g, white 0, red +%.4g\n", frame.curvatureRange,
                frame.curvatureRange);
  return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a surface to a PNG, without a window");
  auto args = std::make_shared<RenderArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option("-o,--output", args->output,
                  "the PNG to write (with --animate: the folder of the frames)")
      ->required();
  cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT (default: the scene's)");
  auto* depth = cmd->add_option(
      "--depth", args->depth, "also write a PFM with the distance from the eye to the first hit");
  cmd->add_option("--backend", args->backend, "egl (default) or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}));
  auto* animate = cmd->add_option(
      "--animate", args->animate.spec,
      "sweep KEY from FROM to TO over the frames and write numbered PNGs into the folder -o "
      "names: params.NAME=FROM:TO, or camera.orbit=FROM:TO in degrees");
  animate->excludes(depth);
  cmd->add_option("--frames", args->animate.frames, "number of frames for --animate (default 60)")
      ->check(CLI::Range(1, 100000))
      ->needs(animate);
  cmd->add_option("--video", args->animate.video,
                  "also join the frames into this video with ffmpeg (which must be installed)")
      ->needs(animate);
  cmd->add_option("--fps", args->animate.fps, "frames per second of --video (default 30)")
      ->check(CLI::Range(1, 240))
      ->needs(animate);
  cmd->add_option("--shard", args->shard,
                  "K/N: render only frames K, K+N, K+2N, ... of --animate (0 <= K < N), under "
                  "their numbers in the whole animation, so N jobs fill one folder (docs/batch.md)")
      ->needs(animate);
  cmd->callback([args] { std::exit(runRender(*args)); });
}

}  // namespace zs::app
