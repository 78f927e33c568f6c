#include "surfscript/surf_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "surfscript/surf_scene.hpp"

namespace zs::surfscript {

namespace {

std::string lineOf(std::string_view text, int line) {
  int at = 1;
  std::size_t start = 0;
  while (at < line) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) return {};
    start = nl + 1;
    ++at;
  }
  const std::size_t end = text.find('\n', start);
  std::string out(
      text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
  if (!out.empty() && out.back() == '\r') out.pop_back();
  return out;
}

SceneError placed(std::string_view text, std::string_view fileName, const Place& p,
                  std::string message, std::string hint = {}) {
  SceneError e;
  e.file = std::string(fileName);
  e.line = p.line;
  e.column = p.column;
  e.width = std::max(1, p.width);
  e.message = std::move(message);
  e.hint = std::move(hint);
  e.sourceLine = lineOf(text, p.line);
  return e;
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
  // The mapped scene must be one a .surf file may hold; a failure here is zeroset's bug.
  const SceneResult check = parseScene(saveScene(scene), fileName);
  if (const auto* err = std::get_if<SceneError>(&check))
    return placed(
        text, fileName, d.place,
        "the imported scene is not valid (a bug in zeroset's surf import): " + err->message);
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
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    SceneError e;
    e.file = path.string();
    e.message = "cannot open the surf script";
    return e;
  }
  return importSurfScript(text.str(), path.string());
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
