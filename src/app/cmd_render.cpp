// `zeroset render SCENE|FORMULA -o out.png [--size WxH] [--depth out.pfm]
// [--backend egl|osmesa] [--set KEY=VALUE]...`: one picture, headless. With
// `--animate KEY=FROM:TO [--frames N] [--video out.mp4] [--shard K/N]`, -o is a folder of
// numbered frames (animate/render_frames.hpp). With `--tile I/N`, band I of N of the picture
// (render/picture_bands.hpp), which `zeroset assemble` stacks.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "app/animate/render_frames.hpp"
#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/gl_context.hpp"
#include "render/picture_bands.hpp"
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
  std::string tile;        // --tile I/N
};

// "I/N" with 0 <= I < N.
bool parseFraction(const std::string& text, int& index, int& count) {
  char slash = 0, rest = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &index, &slash, &count, &rest) == 3 &&
         slash == '/' && count >= 1 && index >= 0 && index < count;
}

bool parseSize(const std::string& text, int& w, int& h, int maxHeight = 16384) {
  char x = 0;
  char rest = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) == 3 && (x == 'x' || x == 'X') &&
         w > 0 && h > 0 && w <= 16384 && h <= maxHeight;
}

int runRender(const RenderArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  // In bands a picture may be taller than a framebuffer: only each band must fit.
  const int maxHeight = args.tile.empty() ? 16384 : 1 << 20;
  if (!args.size.empty() && !parseSize(args.size, scene->width, scene->height, maxHeight)) {
    std::cerr << "error: --size '" << args.size << "' is not WIDTHxHEIGHT\n"
              << "hint: e.g. --size 800x600 (1 to 16384 pixels each way; with --tile up to "
              << (1 << 20) << " rows)\n";
    return 1;
  }
  std::optional<PictureBand> band;
  if (!args.tile.empty()) {
    int index = 0, count = 0;
    if (!parseFraction(args.tile, index, count)) {
      std::cerr
          << "error: --tile '" << args.tile << "' is not I/N with 0 <= I < N\n"
          << "hint: --tile 0/4 is the top quarter of the picture, --tile 3/4 the bottom one\n";
      return 1;
    }
    band = pictureBand(scene->height, index, count);
    if (!band) {
      std::cerr << "error: " << scene->height << " rows cannot be cut into " << count
                << " bands of whole " << kBeamTile << "-row tiles\n"
                << "hint: at most " << scene->height / kBeamTile << " bands for this height\n";
      return 1;
    }
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
  std::cerr << surface.formulaNote << surface.methodWarning << surface.singularNote;

  preferQuickShaderCompile(double(scene->width) * (band ? band->rows : scene->height) *
                           scene->render.samples * scene->render.samples);
  HeadlessTracer gl = openHeadlessTracer(backend, surface, scene->render);
  if (!gl.tracer) return 1;
  RayTracer& tracer = *gl.tracer;

  const bool showProgress = isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  const ProgressFn progress = [showProgress](int done, int total) {
    if (showProgress) std::fprintf(stderr, "\rrendering: tile %d of %d", done, total);
    return true;
  };
  Frame frame =
      band ? tracer.renderBand(scene->render, scene->domain, scene->width, scene->height, band->top,
                               band->rows, progress)
           : tracer.render(scene->render, scene->domain, scene->width, scene->height, progress);
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
  if (band) {
    std::printf("wrote %s (rows %d to %d of %dx%d, tile %s) in %.0f ms: %zu octree leaves, %s\n",
                args.output.c_str(), band->top, band->top + band->rows - 1, scene->width,
                scene->height, args.tile.c_str(), renderMs, surface.octree.leaves.size(),
                gl.context->backendName().c_str());
  } else {
    std::printf("wrote %s (%dx%d) in %.0f ms: %zu octree leaves, %s\n", args.output.c_str(),
                scene->width, scene->height, renderMs, surface.octree.leaves.size(),
                gl.context->backendName().c_str());
  }
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
  auto* depth = cmd->add_option("--depth", args->depth,
                                "also write a PFM with the distance from the eye to the first hit");
  cmd->add_option("--backend", args->backend, "egl (default) or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}));
  auto* animate = cmd->add_option(
      "--animate", args->animate.spec,
      "sweep KEY from FROM to TO over the frames and write numbered PNGs into the folder -o "
      "names: params.NAME=FROM:TO, or camera.orbit=FROM:TO in degrees");
  animate->excludes(depth);
  auto* tile = cmd->add_option(
      "--tile", args->tile,
      "I/N: render only band I of N (0 = top) of the picture, cut on whole tile rows, exactly "
      "as the whole picture has it; `zeroset assemble` stacks the bands (docs/batch.md)");
  tile->excludes(animate);
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
