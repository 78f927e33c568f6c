#include "jsurf/write_surfer.hpp"

#include <charconv>

#include "expr/number_text.hpp"
#include "jsurf/properties.hpp"

namespace zs::jsurf {
namespace {

std::string num(double v) {
  if (v == 0) return "0.0";  // no "-0": Java prints it, but it reads oddly
  std::string s = shortestText(v);
  // Java's Scanner and parseDouble read "1e-05" and "2" alike; ".0" only keeps the look
  // of SURFER's own files.
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string vec(const Vec3& v) {
  return num(v[0]) + " " + num(v[1]) + " " + num(v[2]);
}

std::string matrix(const Mat4& m) {
  std::string s;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s += (s.empty() ? "" : " ") + num(m[r][c]);
  return s;
}

void line(std::string& out, const std::string& key, const std::string& value) {
  out += escapeProperty(key, true) + "=" + escapeProperty(value) + "\n";
}

}  // namespace

std::string writeSurferScene(const SurferScene& s) {
  std::string out = "#jSurfer surface description\n#written by zeroset export\n";
  line(out, "surface_equation", s.formula);
  for (const auto& [name, value] : s.params) line(out, "surface_parameter_" + name, num(value));
  const SurferView& v = s.view;
  line(out, "scale_factor", num(v.scaleFactor));
  line(out, "rotation_matrix", matrix(v.rotation));
  line(out, "camera_type", v.orthographic ? "ORTHOGRAPHIC_CAMERA" : "PERSPECTIVE_CAMERA");
  line(out, "camera_fov_y", num(v.fovY));
  line(out, "camera_height", num(v.height));
  line(out, "camera_transform", matrix(v.cameraTransform));
  for (const auto* side : {"front", "back"}) {
    const SurferMaterial& m = std::string_view(side) == "front" ? s.front : s.back;
    const std::string p = std::string(side) + "_material_";
    line(out, p + "color", vec(m.color));
    line(out, p + "ambient_intensity", num(m.ambient));
    line(out, p + "diffuse_intensity", num(m.diffuse));
    line(out, p + "specular_intensity", num(m.specular));
    line(out, p + "shininess", num(m.shininess));
  }
  for (int i = 0; i < kSurferLights; ++i) {
    const SurferLight& l = s.lights[static_cast<std::size_t>(i)];
    const std::string n = "_" + std::to_string(i);
    line(out, "light_status" + n, l.on ? "ON" : "OFF");
    line(out, "light_position" + n, vec(l.position));
    line(out, "light_color" + n, vec(l.color));
    line(out, "light_intensity" + n, num(l.intensity));
  }
  line(out, "background_color", vec(s.background));
  return out;
}

}  // namespace zs::jsurf
