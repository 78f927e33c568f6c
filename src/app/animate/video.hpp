#pragma once
// `--video out.mp4`: encodes a numbered PNG sequence with ffmpeg, which zeroset does not
// depend on: it is looked up on the PATH when a video is asked for, and its absence is an
// error that says how to get it, never a crash or a silent skip.
#include <optional>
#include <string>
#include <vector>

namespace zs::app {

// The full path of ffmpeg on the PATH, or nothing.
std::optional<std::string> findFfmpeg();

// The ffmpeg argument vector that turns `pattern` (e.g. "frames/frame-%04d.png", printf
// style) into `video` at `fps` frames per second. Odd picture sizes are padded by one pixel
// (H.264 needs even ones); .gif keeps ffmpeg's own palette handling.
std::vector<std::string> ffmpegArgs(const std::string& ffmpeg, const std::string& pattern,
                                    const std::string& video, int fps);

// Runs ffmpeg (no shell, so no quoting issues); "" on success, else why it failed.
std::string encodeVideo(const std::string& ffmpeg, const std::string& pattern,
                        const std::string& video, int fps);

// What to tell the user when ffmpeg is missing.
std::string missingFfmpegMessage(const std::string& framesDir);

}  // namespace zs::app
