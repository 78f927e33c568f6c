// The prompt loop and its two threading shapes. With a window, GLFW needs the main thread,
// so the prompt reads lines on a second thread and posts each command to the viewer,
// waiting for the reply before it prompts again. Without one, everything runs here.
#include "app/repl/prompt.hpp"

#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "app/repl/headless_target.hpp"
#include "app/repl/line_reader.hpp"
#include "app/viewer/viewer.hpp"

namespace zs::app {
namespace {

constexpr const char* kPrompt = "F(x,y,z) = ";

class WindowTarget final : public PromptTarget {
 public:
  explicit WindowTarget(Viewer& viewer) : viewer_(viewer) {}
  std::string run(const PromptCommand& command) override { return viewer_.post(command).get(); }

 private:
  Viewer& viewer_;
};

std::filesystem::path outputDir() {
  const char* dir = std::getenv("ZS_OUTPUT_DIR");
  return dir && *dir ? std::filesystem::path(dir) : std::filesystem::path(".");
}

// Reads and carries out lines until :quit or end of input.
void promptLoop(LineReader& reader, PromptTarget& target) {
  if (reader.interactive())
    std::printf("zeroset: type a formula F(x,y,z), or :help for the commands\n");
  for (;;) {
    std::fflush(stdout);
    std::optional<std::string> line = reader.read(reader.interactive() ? kPrompt : "");
    if (!line) break;
    auto parsed = parsePromptLine(*line);
    std::string reply;
    if (auto* err = std::get_if<std::string>(&parsed)) {
      reply = *err;
    } else {
      const PromptCommand& command = std::get<PromptCommand>(parsed);
      if (command.kind == PromptCommand::Kind::Quit) break;
      if (command.kind == PromptCommand::Kind::Help)
        reply = promptHelp();
      else if (command.kind != PromptCommand::Kind::Empty)
        reply = target.run(command);
    }
    std::fputs(reply.c_str(), stdout);
  }
  if (reader.interactive()) std::printf("\n");
  std::fflush(stdout);
}

bool haveDisplay() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

}  // namespace

int runPrompt() {
  std::unique_ptr<LineReader> reader = LineReader::forStdin();
  std::unique_ptr<Viewer> viewer;
  if (haveDisplay()) {
    ViewerOptions options;
    options.outputDir = outputDir();
    std::string error;
    viewer = Viewer::open(options, error);
    if (!viewer)
      std::fprintf(stderr, "note: no window (%s); rendering to PNG files\n", error.c_str());
  }
  if (!viewer) {
    HeadlessTarget target(outputDir());
    promptLoop(*reader, target);
    return 0;
  }

  // The terminal's modes, to restore if the window closes while libedit is mid-line.
  termios saved{};
  const bool tty = isatty(STDIN_FILENO) && tcgetattr(STDIN_FILENO, &saved) == 0;
  std::atomic<bool> promptDone{false};
  WindowTarget target(*viewer);
  std::thread promptThread([&] {
    promptLoop(*reader, target);
    promptDone = true;
    viewer->requestClose();
  });
  viewer->run();
  if (promptDone) {
    promptThread.join();
    viewer.reset();
    return 0;
  }
  // The window was closed while the prompt waits for a line: that read cannot be
  // interrupted portably, so leave without unwinding the blocked thread.
  if (tty) tcsetattr(STDIN_FILENO, TCSANOW, &saved);
  std::printf("\n");
  std::fflush(stdout);
  viewer.reset();
  std::_Exit(0);
}

}  // namespace zs::app
