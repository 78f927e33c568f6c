// Every render setting, the octree and the domain as panel widgets, in the order of
// docs/surf-format.md. Bounds mirror the .surf ranges; the viewer still re-checks each
// edit, so a value typed with Ctrl+click beyond them is refused rather than saved.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "app/viewer/panel.hpp"

namespace zs::app {
namespace {

bool dragDouble(const char* label, double& v, double speed, double lo, double hi,
                const char* format = "%.3g") {
  return ImGui::DragScalar(label, ImGuiDataType_Double, &v, float(speed), &lo, &hi, format,
                           ImGuiSliderFlags_AlwaysClamp);
}

bool dragInt(const char* label, int& v, int lo, int hi) {
  return ImGui::DragInt(label, &v, 0.1f, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
}

bool dragVec(const char* label, Vec3& v, double speed) {
  return ImGui::DragScalarN(label, ImGuiDataType_Double, v.data(), 3, float(speed), nullptr,
                            nullptr, "%.3g");
}

bool color(const char* label, Vec3& c) {
  std::array<float, 3> f{float(c[0]), float(c[1]), float(c[2])};
  if (!ImGui::ColorEdit3(label, f.data(), ImGuiColorEditFlags_Float)) return false;
  c = {f[0], f[1], f[2]};
  return true;
}

void highlight(const char* name, Highlight& h) {
  ImGui::PushID(name);
  ImGui::Checkbox(name, &h.enabled);
  dragDouble("threshold", h.threshold, 0.005, 0.0, 1.0);
  color("color", h.color);
  ImGui::PopID();
}

void material(const char* name, Material& m) {
  ImGui::PushID(name);
  ImGui::TextUnformatted(name);
  color("color", m.color);
  dragDouble("ambient", m.ambient, 0.01, 0.0, 1.0);
  dragDouble("diffuse", m.diffuse, 0.01, 0.0, 1.0);
  dragDouble("specular", m.specular, 0.01, 0.0, 1.0);
  dragDouble("shininess", m.shininess, 0.5, 0.0, 1000.0);
  ImGui::PopID();
}

void camera(Camera& c) {
  int projection = c.projection == Projection::Orthographic;
  if (ImGui::Combo("projection", &projection, "perspective\0orthographic\0"))
    c.projection = projection ? Projection::Orthographic : Projection::Perspective;
  dragVec("eye", c.eye, 0.02);
  dragVec("target", c.target, 0.02);
  dragVec("up", c.up, 0.02);
  dragDouble("fov y", c.fovY, 0.2, 1.0, 179.0, "%.1f");
  dragDouble("height", c.height, 0.02, 0.001, 1e4);
}

// One light's widgets; returns false when its remove button was pressed.
bool light(Light& l, int number) {
  ImGui::PushID(number);
  const std::string name = "light " + std::to_string(number);
  ImGui::Checkbox(name.c_str(), &l.enabled);
  ImGui::SameLine();
  int kind = l.kind == LightKind::Point;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7);
  if (ImGui::Combo("##kind", &kind, "directional\0point\0"))
    l.kind = kind ? LightKind::Point : LightKind::Directional;
  ImGui::SameLine();
  const bool keep = !ImGui::SmallButton("remove");
  if (l.kind == LightKind::Directional)
    dragVec("direction", l.direction, 0.02);
  else
    dragVec("position", l.position, 0.05);
  dragDouble("intensity", l.intensity, 0.01, 0.0, 10.0);
  color("color", l.color);
  ImGui::PopID();
  return keep;
}

void lights(Lights& l) {
  dragDouble("ambient", l.ambient, 0.01, 0.0, 1.0);
  ImGui::TextDisabled("right drag moves the first point light");
  for (std::size_t i = 0; i < l.sources.size(); ++i) {
    if (!light(l.sources[i], int(i) + 1)) {
      l.sources.erase(l.sources.begin() + std::ptrdiff_t(i));
      break;  // the rest are drawn next frame
    }
  }
  if (l.sources.size() < std::size_t(kMaxLights) && ImGui::Button("add light"))
    l.sources.push_back(Light{});
}

void shading(Shading& s) {
  int mode = static_cast<int>(s.color);  // curvature modes rebuild the shader (viewer_build.cpp)
  if (ImGui::Combo("color", &mode, "material\0gauss curvature\0mean curvature\0normal\0"))
    s.color = static_cast<ColorMode>(mode);
  ImGui::Checkbox("shadows", &s.shadows);  // a new shader variant (shading_defines.cpp)
  // Contour lines: the switch and the function rebuild the shader (viewer_build.cpp), the
  // spacing, width and color are frame parameters. The function is applied on Enter.
  ImGui::PushID("contours");
  ImGui::Checkbox("contour lines", &s.contours.enabled);
  if (s.contours.enabled) {
    // The text being typed, kept until Enter (one panel per process), and the scene's
    // function it started from: a scene loaded meanwhile replaces it.
    static std::string typed;
    static std::string shown;
    if (shown != s.contours.function) typed = shown = s.contours.function;
    if (ImGui::InputText("of (x, y, z)", &typed, ImGuiInputTextFlags_EnterReturnsTrue))
      s.contours.function = typed;
    dragDouble("spacing", s.contours.spacing, 0.005, 1e-6, 1e6);
    dragDouble("width", s.contours.width, 0.001, 0.0, 1e3);
    color("line color", s.contours.color);
  }
  ImGui::PopID();
  if (!needsCurvature(s.color)) return;
  bool automatic = s.curvatureRange == 0;
  if (ImGui::Checkbox("automatic range", &automatic)) s.curvatureRange = automatic ? 0 : 1;
  if (!automatic) dragDouble("range", s.curvatureRange, 0.01, 1e-6, 1e6);
}

void tracing(Scene& scene) {
  Tracing& t = scene.render.tracing;
  int method = static_cast<int>(t.method);  // rebuilds the shader (viewer_build.cpp)
  if (ImGui::Combo("method", &method, "auto\0bernstein (exact, polynomials)\0sampling (thesis)\0interval (robust, any formula)\0"))
    t.method = static_cast<TracingMethod>(method);
  dragInt("intervals", t.intervals, 1, 1000);
  dragDouble("epsilon", t.epsilon, 0.0001, 1e-9, 1.0, "%.2g");
  dragInt("max bisections", t.maxBisections, 1, 200);
  dragInt("hits", t.hits, 1, 16);
  dragInt("samples (NxN)", scene.render.samples, 1, 8);
  dragDouble("opacity", scene.render.opacity, 0.01, 0.0, 1.0);
  ImGui::Checkbox("reflection", &scene.render.reflection.enabled);
  dragDouble("primary weight", scene.render.reflection.primaryWeight, 0.01, 0.0, 1.0);
  color("background", scene.render.background);
}

void octreeAndDomain(Scene& scene) {
  // Each of these rebuilds the octree and the box hierarchy on the worker thread.
  dragInt("octree level", scene.octree.level, 0, 12);
  int criteria = scene.octree.criteria == Criteria::Uniform;
  if (ImGui::Combo("criterion", &criteria, "thesis\0uniform\0"))
    scene.octree.criteria = criteria ? Criteria::Uniform : Criteria::Thesis;
  int shape = scene.domain.shape == DomainShape::Sphere;
  if (ImGui::Combo("domain shape", &shape, "box\0sphere\0"))
    scene.domain.shape = shape ? DomainShape::Sphere : DomainShape::Box;
  if (scene.domain.shape == DomainShape::Box) {
    dragVec("domain min", scene.domain.min, 0.02);
    dragVec("domain max", scene.domain.max, 0.02);
  } else {
    dragVec("sphere center", scene.domain.center, 0.02);
    dragDouble("sphere radius", scene.domain.radius, 0.01, 1e-3, 1e6);
  }
}

// Cross-sections: up to kMaxClipPlanes planes, each cutting away normal . p > offset; the
// offset slider spans the domain's bounding box along the plane's normal.
void clipPlanes(Scene& scene) {
  std::vector<ClipPlane>& planes = scene.render.clipPlanes;
  const Domain box = boundingBox(scene.domain);
  std::size_t removed = planes.size();
  for (std::size_t i = 0; i < planes.size(); ++i) {
    ClipPlane& plane = planes[i];
    ImGui::PushID(int(i));
    ImGui::Checkbox(("plane " + std::to_string(i + 1)).c_str(), &plane.enabled);
    ImGui::SameLine();
    for (int a = 0; a < 3; ++a) {  // the axis presets keep the plane's place
      const char* axis[] = {"x", "y", "z"};
      if (a) ImGui::SameLine();
      if (ImGui::SmallButton(axis[a])) plane.normal = {a == 0 ? 1.0 : 0.0, a == 1 ? 1.0 : 0.0, a == 2 ? 1.0 : 0.0};
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("flip")) {
      plane.normal = {-plane.normal[0], -plane.normal[1], -plane.normal[2]};
      plane.offset = -plane.offset;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) removed = i;
    Vec3 normal = plane.normal;
    if (dragVec("normal", normal, 0.01) && (normal[0] != 0 || normal[1] != 0 || normal[2] != 0))
      plane.normal = normal;
    // |normal| * the farthest corner's distance bounds the offsets that cut anything.
    double reach = 0;
    for (int a = 0; a < 3; ++a)
      reach += std::abs(plane.normal[a]) * std::max(std::abs(box.min[a]), std::abs(box.max[a]));
    const double hi = std::max(reach, 1e-6), lo = -hi;
    ImGui::SliderScalar("offset", ImGuiDataType_Double, &plane.offset, &lo, &hi, "%.3f");
    ImGui::PopID();
  }
  if (removed < planes.size()) planes.erase(planes.begin() + std::ptrdiff_t(removed));
  if (int(planes.size()) < kMaxClipPlanes && ImGui::Button("add plane")) planes.push_back(ClipPlane{});
  highlight("cut curve", scene.render.cut);
}

// render.mode and the volume's transfer function (a new program variant for the mode;
// the transfer function's numbers are frame parameters).
void volume(RenderSettings& r) {
  int mode = static_cast<int>(r.mode);
  if (ImGui::Combo("show", &mode, "the surface F = level\0F's field as a volume\0"))
    r.mode = static_cast<RenderMode>(mode);
  if (r.mode != RenderMode::Volume) return;
  dragDouble("density", r.volume.density, 0.1, 0.0, 1e4);
  dragDouble("falloff", r.volume.falloff, 0.002, 1e-6, 1e6);
  dragDouble("color range", r.volume.range, 0.01, 1e-6, 1e6);
  dragInt("steps", r.volume.steps, 1, 4096);
}

}  // namespace

void drawSettings(Scene& scene) {
  if (ImGui::CollapsingHeader("tracing")) tracing(scene);
  if (ImGui::CollapsingHeader("octree and domain"))
    octreeAndDomain(scene);
  if (ImGui::CollapsingHeader("highlights")) {
    highlight("silhouette", scene.render.silhouette);
    highlight("border", scene.render.border);
    highlight("singular points", scene.render.singular);
  }
  if (ImGui::CollapsingHeader("cross-sections")) clipPlanes(scene);
  if (ImGui::CollapsingHeader("volume")) volume(scene.render);
  if (ImGui::CollapsingHeader("lights")) lights(scene.render.lights);
  if (ImGui::CollapsingHeader("shading")) shading(scene.render.shading);
  if (ImGui::CollapsingHeader("materials")) {
    material("front", scene.render.materials.front);
    material("back", scene.render.materials.back);
  }
  if (ImGui::CollapsingHeader("camera")) camera(scene.render.camera);
}

}  // namespace zs::app
