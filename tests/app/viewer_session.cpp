#include "viewer_session.hpp"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace zs::test {
namespace {

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void pause(int ms) {
  std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

}  // namespace

ViewerSession::ViewerSession(const std::string& name, const std::vector<std::string>& args,
                             const std::vector<EnvChange>& env)
    : dir_(freshDir(name)), logFile_(dir_ / "viewer.log") {
  std::vector<std::string> argv{ZS_ZEROSET_EXE, "view"};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"--log", "--output-dir", dir_.string()});
  // English whatever the machine's locale, unless the test asks for a language.
  std::vector<EnvChange> environment{{"LANGUAGE", "en"}};
  environment.insert(environment.end(), env.begin(), env.end());
  child_ = std::make_unique<Child>(argv, environment, Stdio::File, logFile_);
  if (waitLog("ready ").empty()) {
    error_ = "the viewer never showed its first frame; log:\n" + log();
    return;
  }
  const std::string idFile = (dir_ / "window.id").string();
  // No window manager under xvfb: focus the window ourselves, and keep the pointer over
  // the picture (not the panel) so keys and the wheel reach the viewer.
  shell("xdotool search --sync --onlyvisible --pid " + std::to_string(child_->pid()) + " > " +
        idFile);
  window_ = readText(idFile);
  window_ = window_.substr(0, window_.find('\n'));
  if (window_.empty()) {
    error_ = "xdotool found no window of the viewer";
    return;
  }
  shell("xdotool windowfocus --sync " + window_ + " mousemove --window " + window_ + " 600 300");
}

void ViewerSession::key(const std::string& keys) {
  shell("xdotool key --delay 60 " + keys);
  pause(100);
}

void ViewerSession::type(const std::string& text) {
  shell("xdotool type --delay 40 " + quote(text));
  pause(100);
}

void ViewerSession::drag(int button, int x0, int y0, int x1, int y1, int steps) {
  const std::string w = " --window " + window_ + " ";
  shell("xdotool mousemove" + w + std::to_string(x0) + " " + std::to_string(y0) + " mousedown " +
        std::to_string(button));
  for (int i = 1; i <= steps; ++i) {
    const int x = x0 + (x1 - x0) * i / steps, y = y0 + (y1 - y0) * i / steps;
    shell("xdotool mousemove" + w + std::to_string(x) + " " + std::to_string(y));
    pause(40);
  }
  shell("xdotool mouseup " + std::to_string(button));
  pause(100);
}

void ViewerSession::move(int x, int y) {
  shell("xdotool mousemove --window " + window_ + " " + std::to_string(x) + " " +
        std::to_string(y));
  pause(100);
}

void ViewerSession::click(int x, int y) {
  shell("xdotool mousemove --window " + window_ + " " + std::to_string(x) + " " +
        std::to_string(y) + " click 1");
  pause(100);
}

void ViewerSession::freeze() {
  kill(child_->pid(), SIGSTOP);
}

void ViewerSession::thaw() {
  kill(child_->pid(), SIGCONT);
}

void ViewerSession::wheel(int clicks) {
  const int button = clicks > 0 ? 4 : 5;
  for (int i = 0; i < std::abs(clicks); ++i) shell("xdotool click " + std::to_string(button));
  pause(100);
}

std::string ViewerSession::log() const {
  return readText(logFile_);
}

std::string ViewerSession::waitLog(const std::string& marker, double seconds) {
  std::string rest;
  if (!waitForText(logFile_, marker, seconds, seen_, &rest)) return {};
  const std::string text = log();
  seen_ = text.find(marker, seen_) + marker.size() + rest.size();
  return marker + rest;
}

Image loadPng(const std::filesystem::path& path) {
  Image image;
  readPng(path.string(), image);
  return image;
}

Image ViewerSession::screenshot() {
  key("c");
  const std::string line = waitLog("screenshot: ");
  return line.empty() ? Image{} : loadPng(line.substr(12));
}

Image ViewerSession::windowShot() {
  key("shift+c");
  const std::string line = waitLog("window: ");
  return line.empty() ? Image{} : loadPng(line.substr(8));
}

std::filesystem::path ViewerSession::save() {
  key("ctrl+s");
  const std::string line = waitLog("saved: ");
  return line.empty() ? std::filesystem::path{} : std::filesystem::path(line.substr(7));
}

int countPixels(const Image& image, int lo, int hi, int spread) {
  int count = 0;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    const auto* p = &image.rgba[i];
    const int min = std::min({p[0], p[1], p[2]}), max = std::max({p[0], p[1], p[2]});
    count += min >= lo && max <= hi && max - min <= spread;
  }
  return count;
}

}  // namespace zs::test
