#include "surfscript/surf_import.hpp"

#include <algorithm>
#include <cctype>
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
        curves ? "this script draws plane curves only (draw_curve), which zeroset does not draw yet"
               : "this script draws no surface",
        curves ? "" : "end it with surface = ...; draw_surface;");
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
    const Drawing* d = lastSurfaces(saved.screen);
    if (!d) {
      const bool curves =
          std::any_of(saved.screen.begin(), saved.screen.end(),
                      [](const Drawing& x) { return x.kind == Drawing::Kind::Curve; });
      return placed(text, fileName, saved.place,
                    curves ? "zeroset does not draw plane curves (draw_curve) yet: nothing to save"
                           : "nothing is drawn yet: save_color_image would save an empty picture",
                    curves ? "" : "draw_surface; before save_color_image;");
    }
    if (std::count_if(saved.screen.begin(), saved.screen.end(),
                      [](const Drawing& x) { return x.kind == Drawing::Kind::Surfaces; }) > 1)
      out.warnings.push_back(
          placed(text, fileName, saved.place,
                 "several draw_surface without clear_screen: the picture shows the last"));
    if (std::any_of(saved.screen.begin(), saved.screen.end(),
                    [](const Drawing& x) { return x.kind == Drawing::Kind::Curve; }))
      out.warnings.push_back(placed(text, fileName, saved.place,
                                    "the plane curves drawn with draw_curve are not in the "
                                    "picture: zeroset does not draw them yet"));
    auto scene = sceneOf(text, fileName, *d, out.warnings);
    if (auto* e = std::get_if<SceneError>(&scene)) return *e;
    picture.scene = std::get<Scene>(std::move(scene));
    picture.scene.width = saved.width;
    picture.scene.height = saved.height;
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
