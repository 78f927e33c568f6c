#include "render/shading_defines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace zs {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", std::isfinite(v) ? v : 0.0);
  std::string s = text;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string vec3(const Vec3& v, double scale = 1) {
  return "vec3(" + number(v[0] * scale) + ", " + number(v[1] * scale) + ", " +
         number(v[2] * scale) + ")";
}

// The unit vector towards a directional light ((0, 0, 1) for a zero direction, which the
// scene reader refuses anyway).
Vec3 towards(const Light& l) {
  const double length = std::hypot(l.direction[0], l.direction[1], l.direction[2]);
  if (!(length > 0) || !std::isfinite(length)) return {0, 0, 1};
  return {-l.direction[0] / length, -l.direction[1] / length, -l.direction[2] / length};
}

}  // namespace

std::string shadingDefines(const RenderSettings& s) {
  // With shadows each light carries its index (its bit in rtShadowMask), and RT_SHADOW_RAYS
  // says where each one's shadow ray goes.
  const bool shadows = s.shading.shadows;
  // Lights fixed to the camera are moved into the world by the shader, from the frame's
  // camera (raytrace_main.frag.glsl), so turning the view compiles nothing.
  const bool camera = s.lights.space == LightSpace::Camera;
  auto direction = [&](const Light& l) {
    return camera ? "rtCameraVector(" + vec3(towards(l)) + ")" : vec3(towards(l));
  };
  auto position = [&](const Light& l) {
    return camera ? "rtCameraPoint(" + vec3(l.position) + ")" : vec3(l.position);
  };
  std::string lights, rays;
  const Light* key = nullptr;
  int count = 0;
  for (const Light& l : s.lights.sources) {
    if (!l.enabled || count == kMaxLights) continue;
    const std::string index = shadows ? std::to_string(count) + ", " : "";
    ++count;
    const double intensity = std::max(l.intensity, 0.0);
    const char* shadowed = shadows ? "_SHADOWED(" : "(";
    if (l.kind == LightKind::Directional) {
      if (!key) key = &l;
      lights += " RT_DIRECTIONAL" + std::string(shadowed) + index + direction(l) + ", " +
                vec3(l.color, intensity) + ")";
      rays += " RT_SHADOW_DIRECTIONAL(" + index + direction(l) + ")";
    } else {
      lights += " RT_POINT" + std::string(shadowed) + index + position(l) + ", " +
                vec3(l.color, intensity) + ")";
      rays += " RT_SHADOW_POINT(" + index + position(l) + ")";
    }
  }
  std::string out = "#define RT_LIGHTS" + lights + "\n";
  if (shadows && count > 0) {
    out += "#define RT_SHADOWS " + std::to_string(count) + "\n";
    out += "#define RT_SHADOW_RAYS" + rays + "\n";
  }
  if (key) out += "#define RT_KEY_LIGHT " + direction(*key) + "\n";
  out += "#define RT_COLOR " + std::to_string(static_cast<int>(s.shading.color)) + "\n";
  return out;
}

double curvatureRangeOf(std::vector<float> values, double floor) {
  std::erase_if(values, [](float v) { return !std::isfinite(v); });
  if (values.empty()) return 1;
  for (float& v : values) v = std::abs(v);
  const auto at = values.begin() + std::ptrdiff_t(0.95 * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return std::max(double(*at), floor);
}

}  // namespace zs
