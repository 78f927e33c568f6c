#include "app/animate/render_frames.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>
#include <variant>

#include "app/animate/animation.hpp"
#include "app/animate/video.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/ray_tracer.hpp"
#include "scene/scene_io.hpp"
#include "session/session.hpp"

namespace zs::app {

namespace {

int digitsFor(int frames) {
  int digits = 4;
  for (int n = 10000; n < frames; n *= 10) ++digits;
  return digits;
}

}  // namespace

bool parseShard(const std::string& text, int& shard, int& shards, std::string& error) {
  int k = 0, n = 0;
  char slash = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &rest) != 3 || slash != '/' || n < 1 ||
      k < 0 || k >= n) {
    error = "error: --shard '" + text +
            "' is not K/N with 0 <= K < N\n"
            "hint: --shard 0/4 renders frames 0, 4, 8, ...; --shard 3/4 frames 3, 7, 11, ...\n";
    return false;
  }
  shard = k;
  shards = n;
  return true;
}

std::string frameFileName(int i, int frames) {
  char name[64];
  std::snprintf(name, sizeof name, "frame-%0*d.png", digitsFor(frames), i);
  return name;
}

std::string frameFilePattern(int frames) {
  return "frame-%0" + std::to_string(digitsFor(frames)) + "d.png";
}

int renderAnimation(const Scene& base, const AnimateOptions& opt, Backend backend) {
  std::string error;
  const std::optional<Animation> anim = parseAnimation(opt.spec, opt.frames, error);
  if (!anim) {
    std::cerr << error;
    return 1;
  }
  const std::filesystem::path dir(opt.outDir);
  if (dir.extension() == ".png") {
    // Almost surely meant as one picture: a folder named like a file would surprise.
    std::cerr << "error: with --animate, -o names the folder of the frames, not a PNG ('"
              << opt.outDir << "')\nhint: e.g. -o frames/ writes frames/frame-0000.png, ...\n";
    return 1;
  }
  if (opt.shards > 1 && !opt.video.empty()) {
    std::cerr << "error: --video needs every frame, and --shard renders only some\n"
              << "hint: once every shard is done, join the frames with ffmpeg -framerate "
              << opt.fps << " -i " << (dir / frameFilePattern(anim->frames)).string()
              << " OUT.mp4 (docs/batch.md)\n";
    return 1;
  }
  const int first = opt.shard;  // this shard's frames: first, first + shards, ...
  if (first >= anim->frames) {
    std::printf("shard %d/%d has no frames: the animation has %d\n", opt.shard, opt.shards,
                anim->frames);
    return 0;
  }
  std::optional<std::string> ffmpeg;
  if (!opt.video.empty() && !(ffmpeg = findFfmpeg())) {
    std::cerr << missingFfmpegMessage(opt.outDir);
    return 1;
  }
  Scene scene;
  if (std::string err = frameScene(*anim, base, first, scene); !err.empty()) {
    std::cerr << err;
    return 1;
  }
  const bool perFrameOctree = rebuildsEachFrame(*anim, base);
  if (anim->kind == Animation::Kind::Param && !perFrameOctree) {
    std::cerr << "note: the formula does not use the parameter '" << anim->param
              << "': every frame shows the same surface\n";
  }
  // One session holds the animation's scene: each frame is an edit of it, and the session
  // rebuilds what the schema says that edit invalidates (scene/invalidation.hpp).
  session::Session session;
  session.loadScene(scene);
  if (std::string err = session.prepare(); !err.empty()) {
    std::cerr << err;
    return 1;
  }
  std::cerr << session.notes();

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    std::cerr << "error: cannot make the folder '" << opt.outDir << "' for the frames"
              << (ec ? ": " + ec.message() : std::string(": a file of that name exists"))
              << "\nhint: with --animate, -o names a folder, e.g. -o frames/\n";
    return 1;
  }
  HeadlessTracer gl = openHeadlessTracer(backend, *session.surface(), session.scene().render);
  if (!gl.tracer) return 1;
  RayTracer& tracer = *gl.tracer;

  int loaded = session.generation();
  const auto start = std::chrono::steady_clock::now();
  int written = 0;
  for (int i = first; i < anim->frames; i += opt.shards) {
    const auto frameStart = std::chrono::steady_clock::now();
    if (i > first) {
      if (std::string err = frameScene(*anim, base, i, scene); !err.empty()) {
        std::cerr << err;
        return 1;
      }
      error = session.edit(scene);
      if (error.empty()) error = session.prepare();
      if (error.empty() && session.generation() != loaded) {
        error = loadSurface(tracer, *session.surface(), session.scene().render);
        loaded = session.generation();
      }
      if (!error.empty()) {
        std::cerr << "frame " << i << ": " << error;
        return 1;
      }
    }
    const Scene& shown = session.scene();
    Frame frame = tracer.render(shown.render, shown.domain, shown.width, shown.height);
    if (!frame.error.empty()) {
      std::cerr << "error: frame " << i << ": " << frame.error << "\n";
      return 1;
    }
    const std::string path = (dir / frameFileName(i, anim->frames)).string();
    if (std::string err = writePng(path, frame.color); !err.empty()) {
      std::cerr << "error: " << err << "\n";
      return 1;
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart)
            .count();
    std::printf("wrote %s: %s = %.6g, %zu octree leaves%s, %.0f ms\n", path.c_str(),
                anim->key().c_str(), anim->valueAt(i), session.surface()->octree.leaves.size(),
                perFrameOctree && i > first ? " (rebuilt)" : "", ms);
    std::fflush(stdout);
    ++written;
  }
  const double totalMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const std::string shard = opt.shards > 1 ? " of " + std::to_string(anim->frames) + " (shard " +
                                                 std::to_string(opt.shard) + "/" +
                                                 std::to_string(opt.shards) + ")"
                                           : std::string();
  std::printf("wrote %d frame%s%s (%dx%d) to %s in %.0f ms, %s; %s\n", written,
              written == 1 ? "" : "s", shard.c_str(), scene.width, scene.height, opt.outDir.c_str(),
              totalMs,
              !perFrameOctree                        ? "octree built once (F does not change)"
              : anim->kind == Animation::Kind::Level ? "octree rebuilt per frame (the level moves)"
              : anim->kind == Animation::Kind::Setting
                  ? "surface rebuilt per frame (the setting changes its shader or octree)"
                  : "octree rebuilt per frame (the parameter is in F)",
              gl.context->backendName().c_str());
  if (ffmpeg) {
    const std::string pattern = (dir / frameFilePattern(anim->frames)).string();
    if (std::string err = encodeVideo(*ffmpeg, pattern, opt.video, opt.fps); !err.empty()) {
      std::cerr << "error: " << err << "\n";
      return 1;
    }
    std::printf("wrote %s (%d frames at %d fps)\n", opt.video.c_str(), anim->frames, opt.fps);
  }
  return 0;
}

}  // namespace zs::app
