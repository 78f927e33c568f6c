#include "app/animate/video.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace zs::app {

std::optional<std::string> findFfmpeg() {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / "ffmpeg";
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return std::nullopt;
}

std::vector<std::string> ffmpegArgs(const std::string& ffmpeg, const std::string& pattern,
                                    const std::string& video, int fps) {
  std::vector<std::string> args{
      ffmpeg, "-y", "-loglevel", "error", "-framerate", std::to_string(fps), "-i", pattern};
  const std::string ext = std::filesystem::path(video).extension().string();
  if (ext != ".gif") {
    // yuv420p is what players expect; it needs even sizes.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"});
  }
  args.push_back(video);
  return args;
}

std::string encodeVideo(const std::string& ffmpeg, const std::string& pattern,
                        const std::string& video, int fps) {
  const std::vector<std::string> args = ffmpegArgs(ffmpeg, pattern, video, fps);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return "cannot start ffmpeg (fork failed)";
  if (pid == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return "lost track of ffmpeg";
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  std::string command;
  for (const std::string& a : args) command += (command.empty() ? "" : " ") + a;
  return "ffmpeg failed (" +
         (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                            : std::string("killed by a signal")) +
         "); the command was: " + command;
}

std::string missingFfmpegMessage(const std::string& framesDir) {
  return "error: --video needs ffmpeg, and there is no ffmpeg on the PATH\n"
         "hint: install it (Debian: sudo apt install ffmpeg), or leave out --video: the "
         "frames are written to " +
         framesDir + (framesDir.ends_with('/') ? "" : "/") + " and any encoder can join them\n";
}

}  // namespace zs::app
