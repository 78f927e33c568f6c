#include "app/viewer/hover_probe.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <variant>

#include "i18n/translate.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

bool HoverProbe::update(const Scene& scene, double x, double y, int width, int height) {
  const int px = int(std::floor(x)), py = int(std::floor(y));
  if (px < 0 || py < 0 || px >= width || py >= height) {
    clear();
    return false;
  }
  if (px == lastX_ && py == lastY_ && width == lastW_ && height == lastH_ && scene == lastScene_)
    return false;
  lastX_ = px, lastY_ = py, lastW_ = width, lastH_ = height;
  lastScene_ = scene;
  if (!probe_ || !probe_->sameSurfaces(scene)) probe_ = std::make_unique<SceneProbe>(scene);
  if (!probe_->error().empty()) {
    clear();
    return false;
  }
  auto result = probe_->pixel(scene, width, height, px, py);
  if (auto* r = std::get_if<ProbeResult>(&result); r && r->hit) {
    shown_ = *r;
    return true;
  }
  clear();
  return false;
}

std::string HoverProbe::logLine() const {
  if (!shown_) return {};
  const ProbeResult& r = *shown_;
  char text[200];
  std::snprintf(text, sizeof text, "K %.6g H %.6g k1 %.6g k2 %.6g at %.6g, %.6g, %.6g", r.gaussian,
                r.mean, r.k1, r.k2, r.point[0], r.point[1], r.point[2]);
  if (r.surfaces == 1) return std::string("probe: ") + text;
  return "probe: surface " + std::to_string(r.surface + 1) + " of " + std::to_string(r.surfaces) +
         " " + text;
}

void HoverProbe::draw() const {
  if (!shown_) return;
  const ProbeResult& r = *shown_;
  ImGui::BeginTooltip();
  if (r.surfaces > 1) ImGui::Text(i18n::tr("surface %d of %d"), r.surface + 1, r.surfaces);
  ImGui::Text(i18n::tr("point  %.5g, %.5g, %.5g"), r.point[0], r.point[1], r.point[2]);
  ImGui::Text(i18n::tr("normal %.4f, %.4f, %.4f"), r.normal[0], r.normal[1], r.normal[2]);
  ImGui::Text("|grad F| %.5g", std::hypot(r.gradient[0], r.gradient[1], r.gradient[2]));
  ImGui::Text("K %.5g   H %.5g", r.gaussian, r.mean);
  ImGui::Text("k1 %.5g   k2 %.5g", r.k1, r.k2);
  ImGui::EndTooltip();
}

}  // namespace zs::app
