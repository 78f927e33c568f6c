#pragma once
// One real `zeroset view` in a window on the X display of xvfb-run, driven with xdotool
// (XTEST events, the same path as a person's keyboard and mouse): takes the viewer's
// arguments, puts out screenshots (the C key) and saved scenes (Ctrl+S) read back from
// disk, and waits on the viewer's --log lines so no step depends on a fixed sleep.
#include <filesystem>
#include <string>
#include <vector>

#include "process.hpp"
#include "render/image.hpp"
#include "scene/scene.hpp"

namespace zs::test {

class ViewerSession {
 public:
  // Starts the viewer and waits for its first full-resolution frame; `ok()` says whether
  // that worked, `error()` why not.
  ViewerSession(const std::string& name, const std::vector<std::string>& args,
                const std::vector<EnvChange>& env = {});
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  const std::filesystem::path& dir() const { return dir_; }

  void key(const std::string& keys);  // xdotool key names: "s", "shift+o", "ctrl+s"
  void type(const std::string& text);
  // Left or right button drag through `steps` intermediate points, in window pixels.
  void drag(int button, int x0, int y0, int x1, int y1, int steps = 8);
  void wheel(int clicks);    // positive: towards the user (zoom in)
  void click(int x, int y);  // left click at window pixels
  void move(int x, int y);   // the pointer to window pixels, no button
  // Stops the viewer's process and lets it go on: what is sent meanwhile reaches it at once,
  // as in a frame that took long.
  void freeze();
  void thaw();

  // Waits until the log holds `marker` after everything seen so far by waits; "" if not.
  std::string waitLog(const std::string& marker, double seconds = 60);
  Image screenshot();            // C; empty image on failure
  Image windowShot();            // Shift+C: panel included
  std::filesystem::path save();  // Ctrl+S; empty path on failure
  std::string log() const;

 private:
  std::filesystem::path dir_, logFile_;
  std::unique_ptr<Child> child_;
  std::string window_;
  std::size_t seen_ = 0;  // log bytes consumed by waits
  std::string error_;
};

Image loadPng(const std::filesystem::path& path);

// Pixels whose channels all lie within [lo, hi] and differ from each other by at most
// `spread` (spread 0..255; small = a neutral gray).
int countPixels(const Image& image, int lo, int hi, int spread = 255);

}  // namespace zs::test
