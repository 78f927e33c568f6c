#pragma once
// The viewer's readout under the mouse pointer: takes the scene on screen and the cursor,
// puts out a tooltip with the point the cursor's ray first meets, F's normal there and the
// curvatures K, H, k1, k2 (src/probe, the numbers `zeroset probe` prints). Probes again only
// when the cursor moves to another pixel or the scene changes.
#include <memory>
#include <optional>
#include <string>

#include "parser/parser.hpp"
#include "probe/probe.hpp"
#include "scene/scene.hpp"

namespace zs::app {

class HoverProbe {
 public:
  // Probes the pixel under (x, y) of a width x height window, in window points. True when
  // that found a new point to show.
  bool update(const Scene& scene, double x, double y, int width, int height);
  // "probe: K k H h k1 a k2 b at x, y, z" for the viewer's --log; "" when nothing is shown.
  std::string logLine() const;
  // Nothing to show (no surface yet, the cursor left the picture, a drag).
  void clear() { shown_.reset(); }
  // The tooltip, inside an ImGui frame.
  void draw() const;

 private:
  std::unique_ptr<SceneProbe> probe_;  // the scene's surfaces, made again when they change
  Scene lastScene_;
  int lastX_ = -1, lastY_ = -1, lastW_ = 0, lastH_ = 0;
  std::optional<ProbeResult> shown_;
};

}  // namespace zs::app
