#pragma once
// The frame loop of `zeroset render --animate`: takes the loaded scene and the animation
// options, writes one numbered PNG per frame (or per frame of its shard) into a folder, and
// optionally joins them into a video with ffmpeg (video.hpp). One GL context and one compiled
// shader serve every frame; the octree is rebuilt per frame only when the animated key changes F
// (animation.hpp says when). Returns the process exit status; messages go to stderr,
// one line per written frame to stdout.
#include <string>

#include "render/gl_context.hpp"
#include "scene/scene.hpp"

namespace zs::app {

struct AnimateOptions {
  std::string spec;    // --animate KEY=FROM:TO
  int frames = 60;     // --frames
  std::string outDir;  // -o: the folder the frames go to (made if missing)
  std::string video;   // --video: "" for none
  int fps = 30;        // --fps
  // --shard K/N: only frames K, K + N, K + 2N, ... (0 <= K < N), under their numbers in the
  // whole animation, so N machines (a job array, GNU parallel) fill one folder between them.
  int shard = 0, shards = 1;
};

// "K/N" with 0 <= K < N -> shard and shards; false (with `error` ready to print) otherwise.
bool parseShard(const std::string& text, int& shard, int& shards, std::string& error);

// The file name of frame i: frame-0000.png, with more digits when there are more frames.
std::string frameFileName(int i, int frames);
// printf pattern of those names, for ffmpeg: frame-%04d.png.
std::string frameFilePattern(int frames);

int renderAnimation(const Scene& scene, const AnimateOptions& options, Backend backend);

}  // namespace zs::app
