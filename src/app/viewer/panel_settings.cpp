// Every render setting, the octree and the domain as panel widgets, in the order of
// docs/surf-format.md. Bounds mirror the .surf ranges; the viewer still re-checks each
// edit, so a value typed with Ctrl+click beyond them is refused rather than saved.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "app/viewer/panel.hpp"
#include "i18n/translate.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {
namespace {

// A combo box whose items are shown translated; `items` are English, marked N_ at the call.
bool combo(const char* english, int* current, std::initializer_list<const char*> items) {
  std::string list;
  for (const char* item : items) (list += i18n::tr(item)) += '\0';
  const bool hidden = english[0] == '#';  // "##id": no label shown
  return ImGui::Combo(hidden ? english : i18n::label(english), current, list.c_str());
}

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
  ImGui::Checkbox(i18n::label(name), &h.enabled);
  dragDouble(i18n::label("threshold"), h.threshold, 0.005, 0.0, 1.0);
  color(i18n::label("color"), h.color);
  ImGui::PopID();
}

void material(const char* name, Material& m) {
  ImGui::PushID(name);
  ImGui::TextUnformatted(i18n::tr(name));
  color(i18n::label("color"), m.color);
  dragDouble(i18n::label("ambient"), m.ambient, 0.01, 0.0, 1.0);
  dragDouble(i18n::label("diffuse"), m.diffuse, 0.01, 0.0, 1.0);
  dragDouble(i18n::label("specular"), m.specular, 0.01, 0.0, 1.0);
  dragDouble(i18n::label("shininess"), m.shininess, 0.5, 0.0, 1000.0);
  ImGui::PopID();
}

void camera(Camera& c) {
  int projection = c.projection == Projection::Orthographic;
  if (combo(N_("projection"), &projection, {N_("perspective"), N_("orthographic")}))
    c.projection = projection ? Projection::Orthographic : Projection::Perspective;
  dragVec(i18n::label("eye"), c.eye, 0.02);
  dragVec(i18n::label("target"), c.target, 0.02);
  dragVec(i18n::label("up"), c.up, 0.02);
  dragDouble(i18n::label("fov y"), c.fovY, 0.2, 1.0, 179.0, "%.1f");
  dragDouble(i18n::label("height"), c.height, 0.02, 0.001, 1e4);
}

// One light's widgets; returns false when its remove button was pressed.
bool light(Light& l, int number) {
  ImGui::PushID(number);
  const std::string name = i18n::format(i18n::tr("light %d"), number) + "###light";
  ImGui::Checkbox(name.c_str(), &l.enabled);
  ImGui::SameLine();
  int kind = l.kind == LightKind::Point;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7);
  if (combo("##kind", &kind, {N_("directional"), N_("point")}))
    l.kind = kind ? LightKind::Point : LightKind::Directional;
  ImGui::SameLine();
  const bool keep = !ImGui::SmallButton(i18n::label("remove"));
  if (l.kind == LightKind::Directional)
    dragVec(i18n::label("direction"), l.direction, 0.02);
  else
    dragVec(i18n::label("position"), l.position, 0.05);
  dragDouble(i18n::label("intensity"), l.intensity, 0.01, 0.0, 10.0);
  color(i18n::label("color"), l.color);
  ImGui::PopID();
  return keep;
}

void lights(Lights& l) {
  dragDouble(i18n::label("ambient"), l.ambient, 0.01, 0.0, 1.0);
  ImGui::TextDisabled("%s", i18n::tr("right drag moves the first point light"));
  for (std::size_t i = 0; i < l.sources.size(); ++i) {
    if (!light(l.sources[i], int(i) + 1)) {
      l.sources.erase(l.sources.begin() + std::ptrdiff_t(i));
      break;  // the rest are drawn next frame
    }
  }
  if (l.sources.size() < std::size_t(kMaxLights) && ImGui::Button(i18n::label("add light")))
    l.sources.push_back(Light{});
}

void shading(Shading& s) {
  int mode = static_cast<int>(s.color);  // curvature modes rebuild the shader (viewer_build.cpp)
  if (combo(N_("color"), &mode,
            {N_("material"), N_("gauss curvature"), N_("mean curvature"), N_("normal")}))
    s.color = static_cast<ColorMode>(mode);
  ImGui::Checkbox(i18n::label("shadows"), &s.shadows);  // a new shader variant (shading_defines.cpp)
  // Contour lines: the switch and the function rebuild the shader (viewer_build.cpp), the
  // spacing, width and color are frame parameters. The function is applied on Enter.
  ImGui::PushID("contours");
  ImGui::Checkbox(i18n::label("contour lines"), &s.contours.enabled);
  if (s.contours.enabled) {
    // The text being typed, kept until Enter (one panel per process), and the scene's
    // function it started from: a scene loaded meanwhile replaces it.
    static std::string typed;
    static std::string shown;
    if (shown != s.contours.function) typed = shown = s.contours.function;
    if (ImGui::InputText(i18n::label("of (x, y, z)"), &typed, ImGuiInputTextFlags_EnterReturnsTrue))
      s.contours.function = typed;
    dragDouble(i18n::label("spacing"), s.contours.spacing, 0.005, 1e-6, 1e6);
    dragDouble(i18n::label("width"), s.contours.width, 0.001, 0.0, 1e3);
    color(i18n::label("line color"), s.contours.color);
  }
  ImGui::PopID();
  if (!needsCurvature(s.color)) return;
  bool automatic = s.curvatureRange == 0;
  if (ImGui::Checkbox(i18n::label("automatic range"), &automatic)) s.curvatureRange = automatic ? 0 : 1;
  if (!automatic) dragDouble(i18n::label("range"), s.curvatureRange, 0.01, 1e-6, 1e6);
}

void tracing(Scene& scene) {
  Tracing& t = scene.render.tracing;
  int method = static_cast<int>(t.method);  // rebuilds the shader (viewer_build.cpp)
  if (combo(N_("method"), &method,
            {N_("auto"), N_("bernstein (exact, polynomials)"), N_("sampling (thesis)"),
             N_("interval (robust, any formula)")}))
    t.method = static_cast<TracingMethod>(method);
  dragInt(i18n::label("intervals"), t.intervals, 1, 1000);
  dragDouble(i18n::label("epsilon"), t.epsilon, 0.0001, 1e-9, 1.0, "%.2g");
  dragInt(i18n::label("max bisections"), t.maxBisections, 1, 200);
  dragInt(i18n::label("hits"), t.hits, 1, 16);
  dragInt(i18n::label("samples (NxN)"), scene.render.samples, 1, 8);
  dragDouble(i18n::label("opacity"), scene.render.opacity, 0.01, 0.0, 1.0);
  ImGui::Checkbox(i18n::label("reflection"), &scene.render.reflection.enabled);
  dragDouble(i18n::label("primary weight"), scene.render.reflection.primaryWeight, 0.01, 0.0, 1.0);
  color(i18n::label("background"), scene.render.background);
}

void octreeAndDomain(Scene& scene) {
  // Each of these rebuilds the octree and the box hierarchy on the worker thread.
  dragInt(i18n::label("octree level"), scene.octree.level, 0, 12);
  int criteria = scene.octree.criteria == Criteria::Uniform;
  if (combo(N_("criterion"), &criteria, {N_("thesis"), N_("uniform")}))
    scene.octree.criteria = criteria ? Criteria::Uniform : Criteria::Thesis;
  int shape = scene.domain.shape == DomainShape::Sphere;
  if (combo(N_("domain shape"), &shape, {N_("box"), N_("sphere")}))
    scene.domain.shape = shape ? DomainShape::Sphere : DomainShape::Box;
  if (scene.domain.shape == DomainShape::Box) {
    dragVec(i18n::label("domain min"), scene.domain.min, 0.02);
    dragVec(i18n::label("domain max"), scene.domain.max, 0.02);
  } else {
    dragVec(i18n::label("sphere center"), scene.domain.center, 0.02);
    dragDouble(i18n::label("sphere radius"), scene.domain.radius, 0.01, 1e-3, 1e6);
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
    ImGui::Checkbox((i18n::format(i18n::tr("plane %d"), int(i) + 1) + "###plane").c_str(),
                    &plane.enabled);
    ImGui::SameLine();
    for (int a = 0; a < 3; ++a) {  // the axis presets keep the plane's place
      const char* axis[] = {"x", "y", "z"};
      if (a) ImGui::SameLine();
      if (ImGui::SmallButton(axis[a])) plane.normal = {a == 0 ? 1.0 : 0.0, a == 1 ? 1.0 : 0.0, a == 2 ? 1.0 : 0.0};
    }
    ImGui::SameLine();
    if (ImGui::SmallButton(i18n::label("flip"))) {
      plane.normal = {-plane.normal[0], -plane.normal[1], -plane.normal[2]};
      plane.offset = -plane.offset;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton(i18n::label("remove"))) removed = i;
    Vec3 normal = plane.normal;
    if (dragVec(i18n::label("normal"), normal, 0.01) && (normal[0] != 0 || normal[1] != 0 || normal[2] != 0))
      plane.normal = normal;
    // |normal| * the farthest corner's distance bounds the offsets that cut anything.
    double reach = 0;
    for (int a = 0; a < 3; ++a)
      reach += std::abs(plane.normal[a]) * std::max(std::abs(box.min[a]), std::abs(box.max[a]));
    const double hi = std::max(reach, 1e-6), lo = -hi;
    ImGui::SliderScalar(i18n::label("offset"), ImGuiDataType_Double, &plane.offset, &lo, &hi, "%.3f");
    ImGui::PopID();
  }
  if (removed < planes.size()) planes.erase(planes.begin() + std::ptrdiff_t(removed));
  if (int(planes.size()) < kMaxClipPlanes && ImGui::Button(i18n::label("add plane"))) planes.push_back(ClipPlane{});
  highlight(N_("cut curve"), scene.render.cut);
}

// The surfaces after the first (whose formula is the panel's formula box): each with its
// formula (applied on Enter; a formula that does not parse is refused like any bad value),
// level and colors. Every change rebuilds the shader (viewer_build.cpp).
void surfaces(Scene& scene) {
  std::vector<SurfaceEntry>& more = scene.moreSurfaces;
  // The texts being typed, kept until Enter, and the formulas they started from.
  static std::vector<std::string> typed, shown;
  typed.resize(more.size());
  shown.resize(more.size());
  std::size_t removed = more.size();
  ImGui::TextUnformatted(i18n::tr("surface 1: the formula above"));
  for (std::size_t i = 0; i < more.size(); ++i) {
    SurfaceEntry& e = more[i];
    ImGui::PushID(int(i));
    if (shown[i] != e.formula) typed[i] = shown[i] = e.formula;
    ImGui::TextUnformatted(i18n::format(i18n::tr("surface %d"), int(i) + 2).c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton(i18n::label("remove"))) removed = i;
    if (ImGui::InputText(i18n::label("formula"), &typed[i], ImGuiInputTextFlags_EnterReturnsTrue))
      e.formula = typed[i];
    dragDouble(i18n::label("level"), e.level, 0.01, -1e6, 1e6);
    color(i18n::label("front color"), e.materials.front.color);
    color(i18n::label("back color"), e.materials.back.color);
    ImGui::PopID();
  }
  if (removed < more.size()) {
    more.erase(more.begin() + std::ptrdiff_t(removed));
    typed.erase(typed.begin() + std::ptrdiff_t(removed));
    shown.erase(shown.begin() + std::ptrdiff_t(removed));
  }
  // A plane through the middle: visible at once, easy to edit.
  if (int(more.size()) + 1 < kMaxSurfaces && ImGui::Button(i18n::label("add surface")))
    addSurface(scene, "z");
  if (!more.empty()) highlight(N_("intersection curves"), scene.render.intersection);
}

// render.mode and the volume's transfer function (a new program variant for the mode;
// the transfer function's numbers are frame parameters).
void volume(RenderSettings& r) {
  int mode = static_cast<int>(r.mode);
  if (combo(N_("show"), &mode, {N_("the surface F = level"), N_("F's field as a volume")}))
    r.mode = static_cast<RenderMode>(mode);
  if (r.mode != RenderMode::Volume) return;
  dragDouble(i18n::label("density"), r.volume.density, 0.1, 0.0, 1e4);
  dragDouble(i18n::label("falloff"), r.volume.falloff, 0.002, 1e-6, 1e6);
  dragDouble(i18n::label("color range"), r.volume.range, 0.01, 1e-6, 1e6);
  dragInt(i18n::label("steps"), r.volume.steps, 1, 4096);
}

}  // namespace

void drawSettings(Scene& scene) {
  if (ImGui::CollapsingHeader(i18n::label("tracing"))) tracing(scene);
  if (ImGui::CollapsingHeader(i18n::label("octree and domain")))
    octreeAndDomain(scene);
  if (ImGui::CollapsingHeader(i18n::label("highlights"))) {
    highlight(N_("silhouette"), scene.render.silhouette);
    highlight(N_("border"), scene.render.border);
    highlight(N_("singular points"), scene.render.singular);
  }
  if (ImGui::CollapsingHeader(i18n::label("surfaces"))) surfaces(scene);
  if (ImGui::CollapsingHeader(i18n::label("cross-sections"))) clipPlanes(scene);
  if (ImGui::CollapsingHeader(i18n::label("volume"))) volume(scene.render);
  if (ImGui::CollapsingHeader(i18n::label("lights"))) lights(scene.render.lights);
  if (ImGui::CollapsingHeader(i18n::label("shading"))) shading(scene.render.shading);
  if (ImGui::CollapsingHeader(i18n::label("materials"))) {
    material(N_("front"), scene.render.materials.front);
    material(N_("back"), scene.render.materials.back);
  }
  if (ImGui::CollapsingHeader(i18n::label("camera"))) camera(scene.render.camera);
}

}  // namespace zs::app
