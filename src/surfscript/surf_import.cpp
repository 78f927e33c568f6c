#include "surfscript/surf_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "scene/source_text.hpp"
#include "surfscript/surf_scene.hpp"

namespace zs::surfscript {

namespace {

// A SceneError at `p` with its source line for the caret (scene/source_text.hpp): the
// script's columns count bytes, a SceneError's code points (a file name may hold an ä).
SceneError placed(std::string_view text, std::string_view fileName, const Place& p,
                  std::string message, std::string hint = {}) {
  const scene_detail::SourceText src(fileName, text);
  const std::size_t offset = src.offsetOf({p.line, 1}) + std::size_t(std::max(0, p.column - 1));
  return src.error(src.positionOf(offset), {}, std::move(message), std::move(hint),
                   std::max(1, p.width));
}

std::variant<ScriptRun, SceneError> run(std::string_view text, std::string_view fileName) {
  auto r = runScript(text);
  if (auto* e = std::get_if<ScriptError>(&r))
    return placed(text, fileName, e->place, e->message, e->hint);
  return std::get<ScriptRun>(std::move(r));
}

// The last surface drawing on `screen`, or null.
const Drawing* lastSurfaces(const std::vector<Drawing>& screen) {
  for (auto it = screen.rbegin(); it != screen.rend(); ++it)
    if (it->kind == Drawing::Kind::Surfaces) return &*it;
  return nullptr;
}

void addNotes(std::string_view text, std::string_view fileName, const std::vector<Note>& notes,
              std::vector<SceneError>& out) {
  for (const Note& n : notes) out.push_back(placed(text, fileName, n.place, n.message));
}

// The scene of a surface drawing, or the error that it draws no surface.
std::variant<Scene, SceneError> sceneOf(std::string_view text, std::string_view fileName,
                                        const Drawing& d, std::vector<SceneError>& warnings) {
  std::vector<Note> notes;
  Scene scene = surfaceScene(d, notes);
  addNotes(text, fileName, notes, warnings);
  if (scene.formula.empty())
    return placed(text, fileName, d.place, "draw_surface has no surface to draw",
                  "set surface = ...; to a polynomial in x, y, z of degree 1 or more before it");
  // A failure here is a bug in the mapping: said at the drawing it maps.
  if (auto err = checkImportedScene(scene, fileName, "surf"))
    return placed(text, fileName, d.place, err->message);
  return scene;
}

// surf's draw_curve: curve(x, y) = 0 in the surface's window, moved by origin and scaled by
// scale_* as surfaces are (not turned: a plane curve ignores rot_*), clipped to surf's
// sphere where clip is the sphere.
std::variant<ScriptCurve, SceneError> curveOf(std::string_view text, std::string_view fileName,
                                              const Drawing& d, int width, int height) {
  const Globals& g = d.globals;
  const Poly* p = g.poly("curve");
  if (!p || p->degree() < 1)
    return placed(text, fileName, d.place, "draw_curve has no curve to draw",
                  "set curve = ...; to a polynomial in x and y before it");
  ScriptCurve c;
  c.formula = p->applied().formula();
  if (c.formula.find('z') != std::string::npos)
    return placed(text, fileName, d.place, "the curve holds z: surf draws plane curves f(x, y) = 0",
                  "write the curve in x and y only");
  const double wf = width >= height ? 10.0 * width / height : 10;
  const double hf = width >= height ? 10 : 10.0 * height / width;
  c.u0 = -wf;
  c.du = 2 * wf / std::max(1, width - 1);
  c.v0 = hf;
  c.dv = -2 * hf / std::max(1, height - 1);
  const double sx = g.number("scale_x"), sy = g.number("scale_y");
  c.map = {sx * c.u0 - g.number("origin_x"), sx * c.du, sy * c.v0 - g.number("origin_y"),
           sy * c.dv};
  // surf's stroke of curve_width w is about 2w/3 pixels thick (measured: 1.5 gives one
  // pixel, 3 two): a square of side 0.6 w about each pixel's centre draws as thick.
  c.halfWidth = std::max(0.5, 0.3 * g.number("curve_width"));
  c.color = {g.number("curve_red") / 255, g.number("curve_green") / 255,
             g.number("curve_blue") / 255};
  if (g.integer("clip") == 0) {
    const double r = g.number("radius") > 0 ? g.number("radius") : 10, cz = g.number("center_z");
    c.clipped = true;
    c.discU = g.number("center_x");
    c.discV = g.number("center_y");
    c.discRadius = r * r > cz * cz ? std::sqrt(r * r - cz * cz) : 0;
  }
  return c;
}

}  // namespace

ImportResult importSurfScript(std::string_view text, std::string_view fileName) {
  auto r = run(text, fileName);
  if (auto* e = std::get_if<SceneError>(&r)) return *e;
  const ScriptRun& script = std::get<ScriptRun>(r);
  ImportedScene out;
  const Drawing* d = lastSurfaces(script.screen);
  for (auto it = script.saved.rbegin(); !d && it != script.saved.rend(); ++it)
    d = lastSurfaces(it->screen);
  if (!d) {
    const bool curves =
        std::any_of(script.screen.begin(), script.screen.end(),
                    [](const Drawing& x) { return x.kind == Drawing::Kind::Curve; });
    SceneError e = placed(
        text, fileName, {1, 1, 1},
        curves ? "this script draws plane curves only (draw_curve): a scene holds surfaces"
               : "this script draws no surface",
        curves ? "run it with `zeroset surf`, which draws its curves into the pictures it saves"
               : "end it with surface = ...; draw_surface;");
    e.line = 0;
    return e;
  }
  addNotes(text, fileName, script.notes, out.warnings);
  auto scene = sceneOf(text, fileName, *d, out.warnings);
  if (auto* e = std::get_if<SceneError>(&scene)) return *e;
  out.scene = std::get<Scene>(std::move(scene));
  return out;
}

ImportResult loadSurfScript(const std::filesystem::path& path) {
  auto text = readSceneFile(path, "surf script");
  if (auto* err = std::get_if<SceneError>(&text)) return *err;
  return importSurfScript(std::get<std::string>(text), path.string());
}

std::variant<ScriptPictures, SceneError> runSurfScript(std::string_view text,
                                                       std::string_view fileName) {
  auto r = run(text, fileName);
  if (auto* e = std::get_if<SceneError>(&r)) return *e;
  const ScriptRun& script = std::get<ScriptRun>(r);
  ScriptPictures out;
  addNotes(text, fileName, script.notes, out.warnings);
  for (const SavedImage& saved : script.saved) {
    ScriptPicture picture;
    picture.fileName = saved.fileName;
    picture.format = saved.format;
    picture.place = placed(text, fileName, saved.place, "");
    if (saved.screen.empty())
      return placed(text, fileName, saved.place,
                    "nothing is drawn yet: save_color_image would save an empty picture",
                    "draw_surface; or draw_curve; before save_color_image;");
    // Each drawing starts from a cleared picture (surf 1.0.6, measured: a draw_curve after a
    // draw_surface leaves the curve alone on black), so the picture is the last drawing.
    const Drawing& last = saved.screen.back();
    if (last.kind == Drawing::Kind::Surfaces) {
      auto scene = sceneOf(text, fileName, last, out.warnings);
      if (auto* e = std::get_if<SceneError>(&scene)) return *e;
      picture.scene = std::get<Scene>(std::move(scene));
    } else {
      picture.scene.formula.clear();
      auto c = curveOf(text, fileName, last, saved.width, saved.height);
      if (auto* e = std::get_if<SceneError>(&c)) return *e;
      picture.curves.push_back(std::get<ScriptCurve>(std::move(c)));
    }
    picture.scene.width = saved.width;
    picture.scene.height = saved.height;
    if (saved.screen.size() > 1)
      out.warnings.push_back(
          placed(text, fileName, last.place,
                 "each drawing clears the picture, as in surf: the one saved shows this "
                 "drawing alone"));
    out.pictures.push_back(std::move(picture));
  }
  return out;
}

bool isSurfScriptPath(std::string_view path) {
  constexpr std::string_view ext = ".pic";
  if (path.size() < ext.size()) return false;
  return std::equal(
      ext.begin(), ext.end(), path.end() - static_cast<std::ptrdiff_t>(ext.size()),
      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

}  // namespace zs::surfscript
