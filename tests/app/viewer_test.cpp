// The viewer in a real window (ctest runs this binary under xvfb-run): each test drives
// `zeroset view` with xdotool and checks what the screenshots and saved scenes show.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <variant>

#include "app/viewer/fonts.hpp"
#include "app/viewer/formula_keyboard.hpp"
#include "interact/formula_keyboard.hpp"
#include "scene/scene_io.hpp"
#include "viewer_session.hpp"

namespace zs::test {
namespace {

// Fraction of pixels that moved by more than a little: "the picture changed".
double changed(const Image& a, const Image& b) {
  return compareImages(a, b, 24).fractionOver;
}

Scene loadSaved(const std::filesystem::path& path) {
  SceneResult loaded = loadScene(path);
  if (auto* err = std::get_if<SceneError>(&loaded)) {
    ADD_FAILURE() << formatSceneError(*err);
    return {};
  }
  return std::get<Scene>(loaded);
}

double distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The window's size, from the log's "ready WxH" line.
void windowSize(ViewerSession& v, int& width, int& height) {
  const std::string log = v.log();
  const std::size_t ready = log.find("ready ");
  ASSERT_NE(ready, std::string::npos) << log;
  ASSERT_EQ(std::sscanf(log.c_str() + ready, "ready %dx%d", &width, &height), 2) << log;
}

#define START(session) ASSERT_TRUE(session.ok()) << session.error()

TEST(Viewer, DragRotatesTheCameraAroundTheTarget) {
  ViewerSession v("drag", {"x^4 + y^4 + z^4 - 1", "--set", "octree.level=2"});
  START(v);
  const Image before = v.screenshot();
  ASSERT_GT(before.width, 0);
  v.drag(1, 560, 300, 700, 380);
  const Image after = v.screenshot();
  EXPECT_GT(changed(before, after), 0.05) << "a drag must turn the surface";
  const Scene saved = loadSaved(v.save());
  EXPECT_GT(distance(saved.render.camera.eye, {0, 0, 4}), 0.5) << "the eye moved";
  EXPECT_NEAR(distance(saved.render.camera.eye, saved.render.camera.target), 4.0, 1e-9)
      << "an arcball orbit keeps the distance to the target";
  // A right drag turns the key light (the thesis' first light, directional) and not the
  // camera: the picture is lit from elsewhere.
  const Light sun = saved.render.lights.sources.front();
  v.drag(3, 560, 300, 640, 260);
  const Scene relit = loadSaved(v.save());
  EXPECT_EQ(relit.render.camera.eye, saved.render.camera.eye);
  const Vec3 d0 = sun.direction, d1 = relit.render.lights.sources.front().direction;
  EXPECT_GT(distance(d0, d1), 0.1) << "the directional light turned";
  EXPECT_NEAR(distance(d1, {0, 0, 0}), distance(d0, {0, 0, 0}), 1e-9) << "a turn, not a stretch";
  EXPECT_GT(changed(after, v.screenshot()), 0.02);
}

TEST(Viewer, HoverShowsTheCurvaturesUnderThePointer) {
  ViewerSession v("hover", {"x^2 + y^2 + z^2 - 1"});
  START(v);
  int width = 0, height = 0;
  ASSERT_NO_FATAL_FAILURE(windowSize(v, width, height));
  v.move(width / 2 + 7, height / 2 - 5);  // over the unit sphere, right of the panel
  const std::string line = v.waitLog("probe: ", 20);
  double k = 0, h = 0, k1 = 0, k2 = 0;
  ASSERT_EQ(std::sscanf(line.c_str(), "probe: K %lf H %lf k1 %lf k2 %lf", &k, &h, &k1, &k2), 4)
      << line;
  EXPECT_NEAR(k, 1, 1e-4);
  EXPECT_NEAR(h, 1, 1e-4);
  EXPECT_NEAR(k1, 1, 1e-4);
  EXPECT_NEAR(k2, 1, 1e-4);
}

TEST(Viewer, SilhouetteKeyRemovesTheDarkOutline) {
  ViewerSession v("silhouette", {"x^4 + y^4 + z^4 - 1"});
  START(v);
  // The outline is a dark neutral gray (its color (0.05, 0.05, 0.05) blended with the
  // shading at the rim); the orange surface and the white background have none of it.
  const int outlined = countPixels(v.screenshot(), 30, 150, 8);
  v.key("s");
  ASSERT_FALSE(v.waitLog("silhouette off").empty());
  const int plain = countPixels(v.screenshot(), 30, 150, 8);
  EXPECT_GT(outlined, 300);
  EXPECT_LT(plain, outlined / 10);
}

TEST(Viewer, BorderKeyTogglesTheDomainBorderHighlight) {
  // A hyperboloid leaves the domain box, so its cut edges carry the (0.9, 0.9, 0.9) border.
  ViewerSession v("border", {"x^2 + y^2 - z^2 - 0.3", "--set", "camera.eye=[2.5,2,3]"});
  START(v);
  const int highlighted = countPixels(v.screenshot(), 215, 240);
  v.key("b");
  ASSERT_FALSE(v.waitLog("border highlight off").empty());
  const int plain = countPixels(v.screenshot(), 215, 240);
  EXPECT_GT(highlighted, 200);
  EXPECT_LT(plain, highlighted / 3);
}

// Two surfaces: a small ball in front of the unit sphere, on the view's axis. Hovering names
// the surface under the pointer with its own curvatures; the mesh key writes one file each.
TEST(Viewer, SeveralSurfacesAreProbedAndMeshedEachOnItsOwn) {
  ViewerSession v("surfaces", {"x^2 + y^2 + z^2 - 1", "--surface",
                               "x^2 + y^2 + (z - 1.25)^2 - 0.04", "--set", "camera.eye=[0,0,4]"});
  START(v);
  int width = 0, height = 0;
  ASSERT_NO_FATAL_FAILURE(windowSize(v, width, height));
  v.move(width / 2 + 1, height / 2 + 1);  // the picture's centre: the small ball
  const std::string line = v.waitLog("probe: surface 2 of 2 ", 20);
  double k = 0, h = 0;
  ASSERT_EQ(std::sscanf(line.c_str(), "probe: surface 2 of 2 K %lf H %lf", &k, &h), 2) << v.log();
  EXPECT_NEAR(k, 25, 1e-3);
  EXPECT_NEAR(h, 5, 1e-4);
  v.key("m");
  ASSERT_FALSE(v.waitLog("zeroset-level7-0001-2.stl: ").empty()) << v.log();
  EXPECT_TRUE(std::filesystem::exists(v.dir() / "zeroset-level7-0001-1.stl")) << v.log();
  EXPECT_TRUE(std::filesystem::exists(v.dir() / "zeroset-level7-0001-2.stl")) << v.log();
}

// A click that takes the focus from the formula box and a key pressed after it, both
// arriving during one long frame (the viewer stopped meanwhile): the key is the viewer's,
// as it would be had the frame been quick, not lost to the box the click left.
TEST(Viewer, AKeyAfterAClickInOneLongFrameIsTakenAfterTheClick) {
  ViewerSession v("click_then_key", {"x^2 + y^2 - z^2 - 0.3"});
  START(v);
  v.key("f");  // the formula box takes the keys
  v.freeze();
  v.click(600, 300);  // on the picture: the box lets the keys go
  v.key("b");
  v.thaw();
  ASSERT_FALSE(v.waitLog("border highlight off", 20).empty()) << v.log();
  EXPECT_EQ(loadSaved(v.save()).formula, "x^2 + y^2 - z^2 - 0.3") << "no key reached the box";
}

// F puts the cursor in the formula box and types its own character, which the box must not
// get; a formula typed at once after it, which one long frame holds with the F, must.
TEST(Viewer, AFormulaTypedInTheSameLongFrameAsFIsKept) {
  ViewerSession v("f_then_formula", {"x^2 + y^2 + z^2 - 1", "--log"});
  START(v);
  v.freeze();
  v.key("f");
  v.key("ctrl+a");
  v.type("x^2 + y^2 - z");
  v.thaw();
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 - z", 30).empty()) << v.log();
  EXPECT_EQ(v.log().find("built fx"), std::string::npos) << v.log();
}

TEST(Viewer, MeshAndPrintKeysWriteTheirFiles) {
  // A typed formula has no file: the mesh goes to the output folder, at the panel's level.
  ViewerSession v("mesh", {"x^2 + y^2 + z^2 - 1"});
  START(v);
  v.key("m");
  const std::string wrote = v.waitLog("consistently oriented; Euler characteristic 2, 1 piece");
  ASSERT_FALSE(wrote.empty()) << v.log();
  const auto file = v.dir() / "zeroset-level7-0001.stl";
  ASSERT_TRUE(std::filesystem::exists(file)) << v.log();
  EXPECT_GT(std::filesystem::file_size(file), 84u + 50u * 1000u);
  // The printed page (docs/print.md), from its own thread and GL context.
  v.key("ctrl+p");
  ASSERT_FALSE(v.waitLog("printed: ").empty()) << v.log();
  const auto page = v.dir() / "zeroset-page-0001.pdf";
  ASSERT_TRUE(std::filesystem::exists(page)) << v.log();
  EXPECT_EQ(readText(page).substr(0, 5), "%PDF-");
}

TEST(Viewer, LevelKeysRebuildTheOctreeAndKeepThePicture) {
  ViewerSession v("level", {"x^2*y^2 + y^2*z^2 + z^2*x^2 - 1"});
  START(v);
  const Image before = v.screenshot();
  v.key("o o");
  ASSERT_FALSE(v.waitLog("octree level 3").empty());
  ASSERT_FALSE(v.waitLog("built ").empty()) << "the level change rebuilds on the worker";
  const Image deeper = v.screenshot();
  // Tighter boxes bound the same surface: the picture must not change.
  EXPECT_LT(changed(before, deeper), 0.01);
  EXPECT_EQ(loadSaved(v.save()).octree.level, 3);
  v.key("shift+o");
  ASSERT_FALSE(v.waitLog("octree level 2").empty());
}

TEST(Viewer, FormulaTypedInThePanelReplacesTheSurface) {
  ViewerSession v("formula", {"x^2 + y^2 + z^2 - 1"});
  START(v);
  const Image sphere = v.screenshot();
  v.key("f");
  v.key("ctrl+a");
  v.type("x^2 + y^2 - z^2 - 0.3");
  v.key("Return");
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 - z^2 - 0.3").empty()) << v.log();
  const Image hyperboloid = v.screenshot();
  EXPECT_GT(changed(sphere, hyperboloid), 0.05);

  // A typo: the caret message shows in red in the panel, the last good surface stays.
  // (Enter left the box, so F first.)
  v.key("f");
  v.key("ctrl+a");
  v.type("* x^2 + y");  // no prefix of it parses, so no pause in typing can build it
  // Clicking the panel's title bar leaves the box with the text kept, so keys reach the
  // viewer again (while the box has focus, C is just a letter).
  v.click(200, 16);
  const Image panel = v.windowShot();
  ASSERT_GT(panel.width, 0);
  int red = 0;
  for (int y = 0; y < panel.height; ++y) {
    for (int x = 0; x < std::min(panel.width, 380); ++x) {
      const auto* p = panel.pixel(x, y);
      red += p[0] > 200 && p[1] > 80 && p[1] < 150 && p[2] > 70 && p[2] < 140;
    }
  }
  EXPECT_GT(red, 30) << "the parse error is shown under the formula";
  EXPECT_LT(changed(hyperboloid, v.screenshot()), 0.001);
  EXPECT_EQ(loadSaved(v.save()).formula, "x^2 + y^2 - z^2 - 0.3") << v.log();
}

TEST(Viewer, TypedFormulaShowsAFirstPictureBeforeItsOwnShader) {
  ViewerSession v("first_picture", {"x^2 + y^2 + z^2 - 1", "--log"});
  START(v);
  const Image sphere = v.screenshot();
  // The formula box's focus has the surface worker compile the tape interpreters; typing
  // before they are ready only waits for the build.
  v.key("f");
  ASSERT_FALSE(v.waitLog("first pictures ready").empty()) << v.log();
  v.key("ctrl+a");
  v.type("x^2 + y^2 - z^2 - 0.3");
  // Each prefix that parses is drawn by the interpreter; the last one's own shader follows.
  ASSERT_FALSE(v.waitLog("first picture x^2 + y^2 - z^2 - 0.3").empty()) << v.log();
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 - z^2 - 0.3").empty()) << v.log();
  v.click(200, 16);  // out of the formula box, so C takes a screenshot
  const Image hyperboloid = v.screenshot();
  EXPECT_GT(changed(sphere, hyperboloid), 0.05);
}

TEST(Viewer, SavedViewRendersLikeTheWindow) {
  ViewerSession v("save", {"x^3*y + y^3*z + z^3*x", "--set", "octree.level=2"});
  START(v);
  v.drag(1, 600, 300, 520, 200);
  v.wheel(2);
  v.drag(3, 600, 300, 700, 300);  // the point light
  v.key("d d shift+l");
  ASSERT_FALSE(v.waitLog("point light").empty());
  const Image shown = v.screenshot();
  const std::filesystem::path saved = v.save();
  ASSERT_FALSE(saved.empty());
  const Scene scene = loadSaved(saved);
  EXPECT_NEAR(scene.render.lights.sources[0].intensity, 1.0, 1e-9);
  EXPECT_NEAR(scene.render.lights.sources[1].intensity, 0.5, 1e-9);
  EXPECT_LT(distance(scene.render.camera.eye, scene.render.camera.target), 4.0) << "zoomed in";

  const auto rendered = v.dir() / "rendered.png";
  ASSERT_EQ(shell(std::string(ZS_ZEROSET_EXE) + " render " + saved.string() + " -o " +
                  rendered.string() + " > /dev/null"),
            0);
  const ImageDiff diff = compareImages(shown, loadPng(rendered));
  EXPECT_TRUE(withinTolerance(diff)) << "fraction " << diff.fractionOver << " rmse " << diff.rmse;
}

TEST(Viewer, ExampleKeysCycleThroughTheThesisSurfaces) {
  // An examples folder with no files: the seven built-in surfaces of thesis Table 5.1.
  const auto empty = freshDir("no-examples");
  std::filesystem::create_directories(empty / "examples");
  ViewerSession v("examples", {"x^2 + y^2 + z^2 - 1"}, {{"ZS_SOURCE_DIR", empty.string()}});
  START(v);
  const Image sphere = v.screenshot();
  v.key("n");
  ASSERT_FALSE(v.waitLog("example 1 of 7: 1 cross channel").empty()) << v.log();
  ASSERT_FALSE(v.waitLog("built x^2 + z^2 - y").empty());
  EXPECT_GT(changed(sphere, v.screenshot()), 0.05);
  v.key("p p");
  ASSERT_FALSE(v.waitLog("example 6 of 7").empty());
  const Scene saved = loadSaved(v.save());
  EXPECT_EQ(saved.formula, "x^4 - z^4 - y");
  EXPECT_EQ(saved.render.tracing.intervals, 10);
  EXPECT_DOUBLE_EQ(saved.render.tracing.epsilon, 0.01);
}

TEST(Viewer, GalleryKeySearchesTheExamplesAndOpensOne) {
  // Three examples of our own: one without a description, to show it is listed anyway.
  const auto root = freshDir("gallery-examples");
  const auto examples = root / "examples";
  std::filesystem::create_directories(examples);
  auto write = [&](const char* name, const char* text) { std::ofstream(examples / name) << text; };
  write("a-sphere.surf", "# The unit sphere, degree 2.\nformula = \"x^2 + y^2 + z^2 - 1\"\n");
  write("b-cubic.surf",
        "# The Cayley cubic with its four nodes.\nformula = \"4*(x^2 + y^2 + z^2) + 16*x*y*z - "
        "1\"\n");
  write("c-bare.surf", "formula = \"x^4 + y^4 + z^4 - 1\"\n");
  ViewerSession v("gallery", {"x^2 + y^2 - z^2 - 0.2"}, {{"ZS_SOURCE_DIR", root.string()}});
  START(v);
  v.key("g");
  ASSERT_FALSE(v.waitLog("gallery: 3 examples").empty()) << v.log();
  // The search box has the keyboard: typing filters, Enter opens the first match.
  v.type("cayley");
  v.key("Return");
  ASSERT_FALSE(v.waitLog("example 2 of 3: b-cubic").empty()) << v.log();
  ASSERT_FALSE(v.waitLog("built ").empty());
  EXPECT_EQ(loadSaved(v.save()).formula, "4*(x^2 + y^2 + z^2) + 16*x*y*z - 1");
  // The pick gives the keyboard back: N and P go on from it.
  v.key("n");
  ASSERT_FALSE(v.waitLog("example 3 of 3: c-bare").empty()) << v.log();
  v.key("p p");
  ASSERT_FALSE(v.waitLog("example 1 of 3: a-sphere").empty()) << v.log();
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 + z^2 - 1").empty()) << v.log();
}

}  // namespace
}  // namespace zs::test

namespace zs::test {
namespace {

// Where the play button of the first parameter is, in window pixels (panel at (8, 8)).
constexpr int kPlayX = 26, kPlayY = 104;

TEST(Viewer, PlayButtonSweepsTheParameterUntilStopped) {
  ViewerSession v("play", {"x^2 + y^2 + z^2 - r", "--set", "params.r=0.5"});
  START(v);
  v.click(kPlayX, kPlayY);
  // Each step of the sweep is a new value: the worker builds again and again.
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 + z^2 - r").empty()) << v.log();
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 + z^2 - r").empty()) << v.log();
  v.click(kPlayX, kPlayY);  // stop
  // The button acts on release, a frame after the press, and a save can come between:
  // the first save may hold the value of the frame before the sweep stopped.
  loadSaved(v.save());
  const Scene first = loadSaved(v.save());
  ASSERT_EQ(first.params.size(), 1u);
  const double r = first.params[0].second;
  EXPECT_NE(r, 0.5) << "the sweep moved r";
  EXPECT_GE(r, -0.5) << "within the slider's range 0.5 +- 1";
  EXPECT_LE(r, 1.5);
  // Stopped: the value stays.
  const Scene second = loadSaved(v.save());
  EXPECT_EQ(second.params, first.params);
}

}  // namespace
}  // namespace zs::test

namespace zs::test {
namespace {

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Kiosk mode (docs/viewer.md): fullscreen with the gallery as the start screen; the keys
// that quit or write files refused; a typed polynomial above the degree limit refused; the
// formula keyboard by touch (a tap is a left click); back to the start screen once idle.
TEST(Viewer, KioskKeepsTheExhibitRunningAndReturnsToTheStartWhenIdle) {
  ViewerSession v(
      "kiosk", {"x^2 + y^2 + z^2 - 1", "--kiosk", "--kiosk-idle", "6", "--kiosk-max-degree", "4"});
  START(v);
  EXPECT_NE(v.log().find("ready 1024x768"), std::string::npos) << "fullscreen\n" << v.log();
  EXPECT_NE(v.log().find("gallery: "), std::string::npos) << "the start screen\n" << v.log();
  v.click(500, 300);  // on the picture: the gallery's search box lets the keys go
  v.key("ctrl+q c shift+c ctrl+s m");
  v.key("b");
  ASSERT_FALSE(v.waitLog("border highlight off").empty()) << "still running\n" << v.log();
  EXPECT_EQ(occurrences(v.log(), "not available in this exhibit"), 5) << v.log();
  for (const auto& entry : std::filesystem::directory_iterator(v.dir())) {
    const std::string ext = entry.path().extension().string();
    EXPECT_TRUE(ext != ".png" && ext != ".surf" && ext != ".stl") << entry.path();
  }

  v.key("f");
  v.key("ctrl+a");
  v.type("x^6 + y - 1");
  ASSERT_FALSE(v.waitLog("refused: degree 6 is more than this exhibit draws (at most 4)").empty())
      << v.log();
  v.key("Return");

  const app::FormulaKeyboardLayout keyboard =
      app::formulaKeyboardLayout(1024, 768, app::kViewerFontSize);
  for (const char* label : {"clear", "x", "^2", "+", "y", "^2", "-", "1", "draw"}) {
    const auto [row, column] = interact::findFormulaKey(label);
    ASSERT_GE(row, 0) << label;
    const auto [x, y] = keyboard.centre(row, column);
    v.click(int(x), int(y));
  }
  ASSERT_FALSE(v.waitLog("built x^2+y^2-1").empty()) << v.log();
  EXPECT_EQ(v.log().find("built x^6"), std::string::npos) << v.log();

  ASSERT_FALSE(v.waitLog("idle: back to the start screen", 30).empty()) << v.log();
  ASSERT_FALSE(v.waitLog("built x^2 + y^2 + z^2 - 1").empty()) << v.log();
}

// The viewer in the language the environment asks for (docs/languages.md): the kiosk's
// refusal and a key's effect are the core's messages, translated by the same catalogs.
TEST(Viewer, SpeaksTheLanguageTheEnvironmentAsksFor) {
  ViewerSession v("german", {"x^2 + y^2 + z^2 - 1", "--kiosk", "--kiosk-max-degree", "4"},
                  {{"LANGUAGE", ""}, {"LC_ALL", ""}, {"LC_MESSAGES", ""}, {"LANG", "de_DE.UTF-8"}});
  START(v);
  // A kiosk warms the first pictures' interpreters from the start, which on a loaded machine
  // slows the frames that would take the keys typed meanwhile; the message is all this test
  // is about, so it types once they are warm.
  ASSERT_FALSE(v.waitLog("first pictures ready", 90).empty()) << v.log();
  v.click(500, 300);
  v.key("f");
  v.key("ctrl+a");
  v.type("x^6 + y - 1");
  ASSERT_FALSE(v.waitLog("refused: Grad 6").empty()) << v.log();
}

}  // namespace
}  // namespace zs::test
