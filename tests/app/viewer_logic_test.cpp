// The viewer's pure pieces, no window: arcball math, the key table and its scene edits,
// prompt line parsing, scene checks, example discovery.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <set>
#include <variant>

#include "app/gallery.hpp"
#include "app/repl/command.hpp"
#include "app/repl/scene_edit.hpp"
#include "app/viewer/examples.hpp"
#include "app/viewer/fonts.hpp"
#include "app/viewer/formula_keyboard.hpp"
#include "i18n/translate.hpp"
#include "interact/arcball.hpp"
#include "interact/formula_keyboard.hpp"
#include "interact/key_bindings.hpp"
#include "interact/kiosk.hpp"
#include "interact/trace_budget.hpp"
#include "process.hpp"
#include "render/camera.hpp"

namespace zs::app {
// The camera motions and key actions are the interact stage's, shared with the web page.
using namespace zs::interact;
namespace {

double length(const Vec3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

TEST(Arcball, HorizontalDragOrbitsAboutTheUpAxisAndKeepsTheDistance) {
  const Camera start;  // eye (0, 0, 4) looking at the origin
  const Camera turned = orbitCamera(start, {400, 300, 500, 300, 800, 600});
  EXPECT_NEAR(length(turned.eye), 4.0, 1e-12);
  EXPECT_NEAR(turned.eye[1], 0.0, 1e-12) << "a horizontal drag keeps the eye's height";
  EXPECT_LT(turned.eye[0], -0.5) << "dragging right turns the surface right: the eye goes left";
  const CameraBasis b = cameraBasis(turned);
  EXPECT_NEAR(b.up[1], 1.0, 1e-12);
}

TEST(Arcball, DragBackReturnsAndDegenerateInputIsANoOp) {
  const Camera start;
  const Camera there = orbitCamera(start, {400, 300, 470, 200, 800, 600});
  const Camera back = orbitCamera(start, {400, 300, 400, 300, 800, 600});
  EXPECT_EQ(back, start);
  EXPECT_NE(there, start);
  EXPECT_EQ(orbitCamera(start, {1, 2, 3, 4, 0, 0}), start);
}

TEST(Arcball, LightFollowsTheDragAndZoomMovesTowardsTheTarget) {
  const Camera view;
  const Vec3 light = orbitPoint(view, {3, 0, 0}, {400, 300, 300, 300, 800, 600});
  EXPECT_NEAR(length(light), 3.0, 1e-12);
  EXPECT_GT(light[2], 0.5) << "dragging left swings a light on the right towards the viewer";
  // A directional light's direction turns the same way (about the origin, not the target).
  Camera offCentre;
  offCentre.target = {1, 2, 0};
  offCentre.eye = {1, 2, 4};
  const Vec3 turned = orbitDirection(offCentre, {3, 0, 0}, {400, 300, 300, 300, 800, 600});
  const Vec3 moved = orbitPoint(offCentre, {4, 2, 0}, {400, 300, 300, 300, 800, 600});
  EXPECT_NEAR(length(turned), 3.0, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned[k], moved[k] - offCentre.target[k], 1e-12);
  const Camera closer = zoomCamera(view, 1);
  EXPECT_NEAR(length(closer.eye), 4 * 0.85, 1e-12);
  EXPECT_NEAR(length(zoomCamera(view, -1000).eye), 1e4, 1e-6) << "clamped";
}

TEST(KeyBindings, EveryKeyIsBoundOnceAndDescribed) {
  std::set<std::pair<int, int>> seen;
  for (const KeyBinding& b : keyBindings()) {
    EXPECT_TRUE(seen.insert({b.key, b.mods}).second) << b.keyName;
    EXPECT_NE(std::string(b.description), "");
    EXPECT_EQ(findBinding(b.key, b.mods | GLFW_MOD_CAPS_LOCK), &b) << "Caps Lock is ignored";
  }
  EXPECT_EQ(findBinding(GLFW_KEY_S, GLFW_MOD_CONTROL)->action, Action::SaveScene);
  EXPECT_EQ(findBinding(GLFW_KEY_Z, 0), nullptr);
}

TEST(KeyBindings, EditsStayInsideTheSceneRanges) {
  Scene s;
  std::string message;
  s.render.lights.sources[1].intensity = 0.05;
  EXPECT_TRUE(applyAction(Action::PointLightDown, s, message));
  EXPECT_EQ(s.render.lights.sources[1].intensity, 0.0);
  s.render.tracing.epsilon = 0.5;
  applyAction(Action::EpsilonUp, s, message);
  EXPECT_EQ(s.render.tracing.epsilon, 1.0);
  EXPECT_EQ(message, "epsilon 1");
  s.render.tracing.intervals = 1;
  applyAction(Action::IntervalsDown, s, message);
  EXPECT_EQ(s.render.tracing.intervals, 1);
  s.octree.level = 0;
  EXPECT_FALSE(applyAction(Action::LevelDown, s, message));
  EXPECT_TRUE(applyAction(Action::LevelUp, s, message));
  s.octree.level = kMaxKeyLevel;
  EXPECT_FALSE(applyAction(Action::LevelUp, s, message));
  const bool on = s.render.silhouette.enabled;
  applyAction(Action::ToggleSilhouette, s, message);
  EXPECT_NE(s.render.silhouette.enabled, on);
  session::Session session;
  EXPECT_EQ(session.edit(s), "") << "a key's edit saves and loads back";
}

TEST(PromptCommands, LinesParseToCommandsOrUsageErrors) {
  using K = PromptCommand::Kind;
  struct Case {
    const char* line;
    K kind;
    const char* arg;
  };
  for (const Case& c :
       {Case{"  x^2 - y ", K::Formula, "x^2 - y"}, Case{":load a b.surf", K::Load, "a b.surf"},
        Case{":save  s.surf", K::Save, "s.surf"},
        Case{":set tracing.hits=2", K::Set, "tracing.hits=2"}, Case{":png o.png", K::Png, "o.png"},
        Case{":help", K::Help, ""}, Case{":quit", K::Quit, ""}, Case{"   ", K::Empty, ""},
        // Bare command words a new user types are commands, not h*e*l*p.
        Case{"help", K::Help, ""}, Case{" quit", K::Quit, ""}, Case{"exit", K::Quit, ""},
        Case{":exit", K::Quit, ""}, Case{"helpx", K::Formula, "helpx"}}) {
    auto parsed = parsePromptLine(c.line);
    ASSERT_TRUE(std::holds_alternative<PromptCommand>(parsed)) << c.line;
    EXPECT_EQ(std::get<PromptCommand>(parsed).kind, c.kind) << c.line;
    EXPECT_EQ(std::get<PromptCommand>(parsed).arg, c.arg) << c.line;
  }
  for (const char* bad : {":load", ":quit now", ":frobnicate", ":", "load a.surf", "png o.png"}) {
    auto parsed = parsePromptLine(bad);
    ASSERT_TRUE(std::holds_alternative<std::string>(parsed)) << bad;
    EXPECT_EQ(std::get<std::string>(parsed).rfind("error: ", 0), 0u) << bad;
  }
}

TEST(SceneEdit, BadEditsLeaveTheSceneAlone) {
  session::Session session;
  const Scene before = session.scene();
  EXPECT_NE(applyPromptEdit({PromptCommand::Kind::Formula, "x^^2"}, session), "");
  EXPECT_NE(applyPromptEdit({PromptCommand::Kind::Set, "tracing.hits=99"}, session), "");
  EXPECT_NE(applyPromptEdit({PromptCommand::Kind::Load, "/nonexistent/a.surf"}, session), "");
  EXPECT_EQ(session.scene(), before);
  Scene bad = before;
  bad.render.tracing.epsilon = -1;  // what a bad panel edit would do
  EXPECT_NE(session.edit(bad), "");
  EXPECT_EQ(session.scene(), before);
  const auto dir = test::freshDir("next-free");
  EXPECT_EQ(nextFreePath(dir, "zeroset", ".png").filename(), "zeroset-0001.png");
  test::shell("touch " + (dir / "zeroset-0001.png").string());
  EXPECT_EQ(nextFreePath(dir, "zeroset", ".png").filename(), "zeroset-0002.png");
}

TEST(Examples, WithoutFilesTheThesisSurfacesAreBuiltIn) {
  const std::vector<Example> builtIn = listExamples({});
  ASSERT_EQ(builtIn.size(), 7u);
  for (const Example& e : builtIn) {
    auto scene = loadExample(e);
    ASSERT_TRUE(std::holds_alternative<Scene>(scene)) << e.name;
    EXPECT_EQ(std::get<Scene>(scene).render.tracing.intervals, 10);
    session::Session session;
    EXPECT_EQ(session.loadScene(std::get<Scene>(scene)), "") << e.name;
  }
  const auto dir = test::freshDir("examples");
  std::filesystem::create_directories(dir / "thesis");
  test::shell("echo 'formula = \"x^2 - y\"' > " + (dir / "thesis" / "b.surf").string());
  test::shell("echo 'formula = \"x - 1\"' > " + (dir / "a.surf").string());
  test::shell("echo 'formula = \"x^^\"' > " + (dir / "broken.surf").string());
  const std::vector<Example> files = listExamples(dir);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].name, "thesis/b") << "thesis surfaces first";
  EXPECT_EQ(files[1].name, "a");
  EXPECT_TRUE(std::holds_alternative<Scene>(loadExample(files[0])));
  auto broken = loadExample(files[2]);
  ASSERT_TRUE(std::holds_alternative<std::string>(broken));
  EXPECT_NE(std::get<std::string>(broken).find("broken.surf:1:"), std::string::npos);
}

TEST(ViewerFont, EveryGallerySymbolHasAGlyphAtTheScreensScale) {
  ASSERT_NE(findViewerFont(), "") << "fonts-dejavu-core is a dependency (install-deps.sh)";
  ImGui::CreateContext();
  ASSERT_EQ(loadViewerFont(2.0f), "");
  ImGuiIO& io = ImGui::GetIO();
  ASSERT_TRUE(io.Fonts->Build());
  const ImFont* font = io.FontDefault;
  ASSERT_NE(font, nullptr);
  EXPECT_FLOAT_EQ(font->FontSize, 2.0f * kViewerFontSize);  // a 2x (high-DPI) screen
  // "Cross channel (thesis surface 1) — degree 2", x², α, ≤, ∇: what the gallery writes.
  // And the letters of the translations: ñ, ¿, á, ß, ä, ü.
  for (ImWchar c : {0x2014, 0x00B2, 0x00B3, 0x03B1, 0x2264, 0x2207, 0x2080, 0x00F1, 0x00BF, 0x00E1,
                    0x00DF, 0x00E4, 0x00FC})
    EXPECT_NE(font->FindGlyphNoFallback(c), nullptr) << "U+" << std::hex << int(c);
  ImGui::DestroyContext();
}

// What the viewer shows from tables rather than code (docs/languages.md): every gallery
// line and every key's description has a translation in every language; the extraction
// test (i18n.catalogs_complete) covers the texts written in code.
TEST(Languages, TheGalleryAndTheKeysAreTranslated) {
  const std::vector<GalleryEntry> gallery = describeExamples(listExamples(findExamplesDir()));
  ASSERT_GT(gallery.size(), 30u);
  struct LanguageRestored {
    ~LanguageRestored() { i18n::setLanguage("en"); }
  } restore;
  for (const i18n::Language& l : i18n::languages()) {
    if (l.code == "en") continue;
    ASSERT_TRUE(i18n::setLanguage(l.code));
    for (const GalleryEntry& e : gallery)
      EXPECT_NE(i18n::tr(e.summary), e.summary) << l.code << ": " << e.name;
    for (const interact::KeyBinding& b : interact::keyBindings())
      EXPECT_STRNE(i18n::tr(b.description), b.description) << l.code;
  }
}

}  // namespace
}  // namespace zs::app

namespace zs::app {
namespace {

TEST(Kiosk, RefusesQuitAndEverythingThatWritesAFile) {
  for (const interact::KeyBinding& b : interact::keyBindings()) {
    const bool writesOrQuits =
        b.action == interact::Action::Quit || b.action == interact::Action::Screenshot ||
        b.action == interact::Action::WindowShot || b.action == interact::Action::SaveScene ||
        b.action == interact::Action::ExportMesh || b.action == interact::Action::PrintPage;
    EXPECT_EQ(interact::kioskAllows(b.action), !writesOrQuits) << b.keyName;
  }
}

TEST(Kiosk, RefusesPolynomialsAboveTheDegreeLimitOnly) {
  interact::KioskPolicy policy;
  policy.maxDegree = 4;
  EXPECT_EQ(interact::kioskRefusal("x^4 + y^4 + z^4 - 1", policy), "");
  EXPECT_EQ(interact::kioskRefusal("(x^2 + y^2 + z^2 - 1)^2 - x", policy), "");
  EXPECT_NE(interact::kioskRefusal("x^5 + y - 1", policy).find("degree 5"), std::string::npos);
  // Not a polynomial: no degree to limit. Not a formula: the parser reports it.
  EXPECT_EQ(interact::kioskRefusal("sin(x) + y^9", policy), "");
  EXPECT_EQ(interact::kioskRefusal("x^^2", policy), "");
  // Cancelled terms count as the user wrote them cancelled: degree 1.
  EXPECT_EQ(interact::kioskRefusal("x^6 - x^6 + y", policy), "");
}

TEST(FormulaKeyboard, KeysAppendAndBackspaceRemovesACharacterOrAFunction) {
  using interact::pressFormulaKey;
  EXPECT_EQ(pressFormulaKey("x", "^2"), "x^2");
  EXPECT_EQ(pressFormulaKey("x+", "sin"), "x+sin(");
  EXPECT_EQ(pressFormulaKey("x+sin(", "<-"), "x+");
  EXPECT_EQ(pressFormulaKey("x+y", "<-"), "x+");
  EXPECT_EQ(pressFormulaKey("x²", "<-"), "x");  // a character, not a byte
  EXPECT_EQ(pressFormulaKey("", "<-"), "");
  EXPECT_EQ(pressFormulaKey("x^2+y", "clear"), "");
  EXPECT_EQ(pressFormulaKey("x", "draw"), "x");    // the front end submits
  EXPECT_EQ(pressFormulaKey("x", "rm -rf"), "x");  // not a key
  // Every key a visitor can press has a place.
  for (const char* label : {"x", "y", "z", "^2", "sin", "<-", "clear", "draw", "pi"})
    EXPECT_GE(interact::findFormulaKey(label).first, 0) << label;
  EXPECT_LT(interact::findFormulaKey("").first, 0);
  // Names do not run together: a then x is a product, not the parameter "ax".
  EXPECT_EQ(pressFormulaKey("a", "x"), "a x");
  EXPECT_EQ(pressFormulaKey("x", "2"), "x 2");
  EXPECT_EQ(pressFormulaKey("x", "pi"), "x pi");
  EXPECT_EQ(pressFormulaKey("x^2", "y"), "x^2y");
  EXPECT_EQ(pressFormulaKey("2", "x"), "2x");
  EXPECT_EQ(pressFormulaKey("x", "sin"), "x sin(");
  const FormulaKeyboardLayout l = formulaKeyboardLayout(1024, 768, kViewerFontSize);
  EXPECT_GE(l.key, 44.0f);  // a fingertip
  const auto [x, y] = l.centre(l.rows - 1, l.columns - 1);
  EXPECT_LT(x, 1024.0f);
  EXPECT_LT(y, 768.0f);
}

}  // namespace
// A first picture while typing (interact/trace_budget.hpp): sized from the pictures before
// it, so that it keeps to its budget also where the cost jumps.
TEST(FirstPictureCost, UnmeasuredIsTheSmallestSizeThenTheBudgetDecides) {
  interact::FirstPictureCost cost;
  EXPECT_EQ(cost.scale(800, 600, 10, true), interact::kFirstPictureMaxScale);
  // Within the budget at 400 x 300: the same formula is drawn at half size.
  cost.measured(39, 400.0 * 300, 10, true);
  EXPECT_EQ(cost.scale(800, 600, 10, true), 2);
  // Four times that cost per pixel: a quarter of the pixels.
  cost.measured(4 * 39, 400.0 * 300, 10, true);
  EXPECT_EQ(cost.scale(800, 600, 10, true), 4);
  // However costly, never below an eighth each way.
  cost.measured(100000, 100.0 * 75, 10, true);
  EXPECT_EQ(cost.scale(800, 600, 10, true), interact::kFirstPictureMaxScale);
}

TEST(FirstPictureCost, ALongerTapeIsSizedByTheMostATapeInstructionCost) {
  interact::FirstPictureCost cost;
  // A 5-instruction tape at the budget, then a picture of nothing that cost almost nothing.
  cost.measured(40, 400.0 * 300, 5, true);
  cost.measured(1, 400.0 * 300, 6, true);
  // The last picture alone would say half size; a tape of 9 instructions is sized as if
  // each instruction cost what the 5-instruction tape's did (faded once).
  EXPECT_EQ(
      interact::scaleForBudget(1.0 / (400 * 300), 800, 600, interact::kFirstPictureBudgetMs,
                               interact::kFirstPictureMinScale, interact::kFirstPictureMaxScale),
      2);
  const double perPixel = 0.75 * 40.0 / (400 * 300) / 5 * 9;
  EXPECT_EQ(
      cost.scale(800, 600, 9, true),
      interact::scaleForBudget(perPixel, 800, 600, interact::kFirstPictureBudgetMs,
                               interact::kFirstPictureMinScale, interact::kFirstPictureMaxScale));
  EXPECT_GE(cost.scale(800, 600, 9, true), 3);
  // The dispatch with every operation learns apart: nothing measured there yet.
  EXPECT_EQ(cost.scale(800, 600, 9, false), interact::kFirstPictureMaxScale);
}

TEST(FirstPictureCost, AFarLongerTapeThanAnyMeasuredIsDrawnSmallest) {
  interact::FirstPictureCost cost;
  cost.measured(10, 400.0 * 300, 48, true);  // a quarter of the budget
  // Up to kStretch times the longest tape measured, the estimate decides...
  EXPECT_EQ(cost.scale(800, 600, 72, true), 2);
  // ... beyond, the smallest size: the estimate would be stretched too far.
  EXPECT_EQ(cost.scale(800, 600, 73, true), interact::kFirstPictureMaxScale);
  // Once measured, the longer tape is sized by its own cost.
  cost.measured(10, 100.0 * 75, 83, true);
  EXPECT_LT(cost.scale(800, 600, 83, true), interact::kFirstPictureMaxScale);
}

TEST(FirstPictureCost, OneCostlyFormulaFadesAway) {
  interact::FirstPictureCost cost;
  cost.measured(400, 400.0 * 300, 10, true);  // ten times the budget
  EXPECT_GE(cost.scale(800, 600, 10, true), 4);
  // Cheap pictures after it: the costly one's weight fades by kForget each time.
  for (int i = 0; i < 12; ++i) cost.measured(4, 400.0 * 300, 10, true);
  EXPECT_EQ(cost.scale(800, 600, 10, true), 2);
}

}  // namespace zs::app
