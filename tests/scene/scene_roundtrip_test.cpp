// saveScene -> parseScene gives back the same Scene, for every key of the schema.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "expr/tape.hpp"
#include "parser/parser.hpp"
#include "scene/scene_io.hpp"
#include "scene/schema.hpp"

namespace zs {
namespace {

// A scene in which every key differs from its default, with doubles chosen to break any
// printing that is not round-trip exact.
Scene everyKeyChanged() {
  Scene s;
  s.formula = "a*x^2 + b*y^2 +\tz^2 - 1";
  s.params = {{"b", 1.0 / 3.0}, {"a", 0.1 + 0.2}, {"unused", -7.25}};
  s.level = -0.1 - 0.2;
  s.domain = {{-2.5, -1e-300, -3},
              {2.5, 5e-324, 1.7976931348623157e308},
              DomainShape::Sphere,
              {0.5, -1e-300, 2},
              0.75};
  s.octree = {7, Criteria::Uniform, 123'456};
  RenderSettings& r = s.render;
  r.camera = {{0.1, 4.4, -9e10}, {1, 2, 3}, {0.3, 1, 0}, Projection::Orthographic, 33.3, 2.2};
  r.lights.ambient = 0.05;
  r.lights.space = LightSpace::Camera;
  // Every light key differs from Light{} in some light (see the test below).
  r.lights.sources = {
      {LightKind::Point, false, {1, -1, 0.5}, {-3, 2, 1e-5}, 1.25, {0.9, 0.8, 0.7}},
      {LightKind::Directional, true, {0.25, 0.5, -1}, {7, 8, 9}, 0.45, {0.1, 0.2, 0.3}},
      {LightKind::Directional, true, {0, 0, 1}, {3, 3, 4}, 0.0, {1, 1, 1}},
  };
  r.materials.front = {{0.2, 0.3, 0.4}, 0.11, 12.5, 0.4, 0.8};
  r.materials.back = {{0.6, 0.7, 0.8}, 0.22, 99, 0.35, 0.65};
  r.shading = {ColorMode::Mean, 2.5, true};
  r.shading.contours = {true, "x*y - 0.5*z", 0.25, 0.03, {0.2, 0.4, 0.6}};
  r.tracing = {TracingMethod::Sampling, 17, 1e-7 / 3, 77, 9};
  r.silhouette = {false, 0.33, {0.5, 0.25, 0.125}};
  r.border = {false, 0.0625, {0.2, 0.1, 0.05}};
  r.singular = {true, 0.125, {0.3, 0.6, 0.9}};
  r.cut = {false, 0.03125, {0.1, 0.9, 0.2}};
  r.intersection = {false, 0.015625, {0.7, 0.6, 0.5}};
  // Every clip plane key differs from ClipPlane{} in some plane.
  r.clipPlanes = {{false, {1, 0, 0}, -0.25}, {true, {0.5, -2, 1e-7}, 1.0 / 3.0}};
  r.reflection = {false, 0.55};
  r.opacity = 0.4;
  r.samples = 3;
  r.background = {0.01, 0.02, 0.03};
  r.mode = RenderMode::Volume;
  r.volume = {3.5, 0.25, 2.5, 100};
  s.width = 321;
  s.height = 123;
  return s;
}

const Scene& expectScene(const SceneResult& r) {
  if (const auto* e = std::get_if<SceneError>(&r)) ADD_FAILURE() << formatSceneError(*e);
  static const Scene kEmpty;
  const Scene* s = std::get_if<Scene>(&r);
  return s ? *s : kEmpty;
}

// Whether key `spec` has the same value in scenes a and b.
bool sameValue(const scene_detail::KeySpec& spec, Scene& a, Scene& b) {
  return std::visit(
      [&](const auto& ref) {
        if constexpr (std::is_same_v<std::decay_t<decltype(ref)>, scene_detail::EnumRef>) {
          return ref.get(a) == ref.get(b);
        } else {
          return ref(a) == ref(b);
        }
      },
      spec.field);
}

TEST(SceneRoundTrip, EveryKeyOfTheTestSceneDiffersFromItsDefault) {
  // Guards the round-trip test below: a key left at its default would round-trip trivially.
  Scene changed = everyKeyChanged();
  Scene defaults;
  for (const auto& spec : scene_detail::keySpecs()) {
    if (spec.legacyLight >= 0) continue;  // old names of the lights, checked below
    EXPECT_FALSE(sameValue(spec, changed, defaults)) << spec.name;
  }
  EXPECT_NE(changed.formula, defaults.formula);
  EXPECT_NE(changed.params, defaults.params);
}

TEST(SceneRoundTrip, EveryLightKeyDiffersFromItsDefaultInTheFirstLight) {
  const Scene changed = everyKeyChanged();
  ASSERT_EQ(changed.render.lights.sources.size(), 3u);
  Scene one, defaults;
  one.render.lights.sources = {changed.render.lights.sources.front()};
  defaults.render.lights.sources = {Light{}};
  for (const auto& spec : scene_detail::lightKeySpecs()) {
    EXPECT_FALSE(sameValue(spec, one, defaults)) << spec.name;
  }
}

TEST(SceneRoundTrip, EveryClipPlaneKeyDiffersFromItsDefaultInTheFirstPlane) {
  const Scene changed = everyKeyChanged();
  const scene_detail::ListSpec* list = scene_detail::findList(scene_detail::kClipPlanesKey);
  ASSERT_NE(list, nullptr);
  Scene one, defaults;
  one.render.clipPlanes = {changed.render.clipPlanes.front()};
  defaults.render.clipPlanes = {ClipPlane{}};
  for (const auto& spec : list->keys) {
    EXPECT_FALSE(sameValue(spec, one, defaults)) << spec.name;
  }
}

TEST(SceneRoundTrip, ClipPlanesAreWrittenAsTablesAndSetByNumber) {
  Scene s;
  s.render.clipPlanes = {{true, {0, 0, 1}, 0.5}, {false, {1, 1, 0}, -0.2}};
  const std::string text = saveScene(s);
  EXPECT_NE(text.find("\n[[clip.plane]]\nenabled = true\nnormal = [0.0, 0.0, 1.0]\noffset = 0.5\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(expectScene(parseScene(text, "cut.surf")), s) << text;
  // No planes: nothing written, and a file without them has none.
  EXPECT_EQ(saveScene(Scene{}).find("clip"), std::string::npos);
  // A later document changes one plane by number, or replaces the list.
  Scene changed = expectScene(parseScene(text + "\n", "cut.surf"));
  ASSERT_FALSE(applyOverrides(
      changed, std::vector<std::string>{"clip.plane.2.offset=0.75", "clip.plane.2.enabled=true"}));
  EXPECT_EQ(changed.render.clipPlanes[1].offset, 0.75);
  EXPECT_TRUE(changed.render.clipPlanes[1].enabled);
  EXPECT_EQ(changed.render.clipPlanes[0], s.render.clipPlanes[0]);
  ASSERT_FALSE(applyOverrides(changed, std::vector<std::string>{"clip.plane=[{normal=[1,0,0]}]"}));
  ASSERT_EQ(changed.render.clipPlanes.size(), 1u);
  EXPECT_EQ(changed.render.clipPlanes[0], (ClipPlane{true, {1, 0, 0}, 0}));
}

// A scene of three surfaces whose second differs from a new entry's defaults in every key.
Scene threeSurfaces() {
  Scene s;
  s.formula = "x^2 + y^2 + z^2 - r";
  s.level = 0.125;
  s.params = {{"r", 0.75}};
  s.render.materials.front.color = {0.1, 0.2, 0.3};
  SurfaceEntry second;
  second.formula = "z - r*x";
  second.level = -0.5;
  second.materials.front = {{0.2, 0.3, 0.4}, 0.11, 12.5, 0.4, 0.8};
  second.materials.back = {{0.6, 0.7, 0.8}, 0.22, 99, 0.35, 0.65};
  SurfaceEntry third;
  third.formula = "x*y";
  third.materials = surfaceMaterials(2);
  s.moreSurfaces = {second, third};
  return s;
}

TEST(SceneRoundTrip, EverySurfaceKeyDiffersFromANewEntrysDefault) {
  const scene_detail::ListSpec* list = scene_detail::findList(scene_detail::kSurfacesKey);
  ASSERT_NE(list, nullptr);
  ASSERT_NE(list->fresh, nullptr);
  Scene one, fresh;
  one.moreSurfaces = {threeSurfaces().moreSurfaces.front()};
  list->fresh(fresh, 1);
  for (const auto& spec : list->keys) EXPECT_FALSE(sameValue(spec, one, fresh)) << spec.name;
}

TEST(SceneRoundTrip, SeveralSurfacesAreWrittenAsTablesAndSetByNumber) {
  const Scene s = threeSurfaces();
  const std::string text = saveScene(s);
  // Every surface, the first included, is a [[surface]] table; nothing describes the first
  // one outside them.
  EXPECT_EQ(text.substr(0, text.find("\n[")).find("formula"), std::string::npos) << text;
  EXPECT_EQ(text.find("[materials."), std::string::npos) << text;
  EXPECT_EQ(text.find("\n[surface]\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n[[surface]]\nformula = \"x^2 + y^2 + z^2 - r\"\nlevel = 0.125\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(expectScene(parseScene(text, "three.surf")), s) << text;
  EXPECT_EQ(saveScene(expectScene(parseScene(text, "three.surf"))), text);

  Scene changed = s;
  ASSERT_FALSE(applyOverrides(
      changed, std::vector<std::string>{"surface.3.level=0.5", "surface.level=2",
                                        "surface.2.front.color=[1, 0, 0]", "formula=\"x\""}));
  EXPECT_EQ(changed.moreSurfaces[1].level, 0.5);
  EXPECT_EQ(changed.level, 2);  // surface.level and formula: the first surface's
  EXPECT_EQ(changed.formula, "x");
  EXPECT_EQ(changed.moreSurfaces[0].materials.front.color, (Vec3{1, 0, 0}));
  // Replacing the list: new entries take their own colors, the first one its formula.
  ASSERT_FALSE(applyOverrides(
      changed, std::vector<std::string>{"surface=[{formula=\"y\"}, {formula=\"z\"}]"}));
  EXPECT_EQ(changed.formula, "y");
  EXPECT_EQ(changed.render.materials, surfaceMaterials(0));
  ASSERT_EQ(changed.moreSurfaces.size(), 1u);
  EXPECT_EQ(changed.moreSurfaces[0].formula, "z");
  EXPECT_EQ(changed.moreSurfaces[0].materials, surfaceMaterials(1));
  EXPECT_NE(surfaceMaterials(1).front.color, surfaceMaterials(0).front.color);
}

TEST(SceneRoundTrip, SurfaceParametersJoinTheScenesParameters) {
  const Scene s = expectScene(
      parseScene("[params]\nb = 3\n[[surface]]\nformula = \"x - a\"\nparams = { a = 0.25 }\n"
                 "[[surface]]\nformula = \"y - a*b\"\n[surface.params]\na = 0.25\nc = 1\n",
                 "params.surf"));
  EXPECT_EQ(s.params,
            (std::vector<std::pair<std::string, double>>{{"b", 3}, {"a", 0.25}, {"c", 1}}));
  // Saved in [params], where they read back the same.
  EXPECT_EQ(expectScene(parseScene(saveScene(s), "saved.surf")), s);
}

TEST(SceneRoundTrip, SurfaceMaterialsReadAsSubTables) {
  const Scene s = expectScene(parseScene(
      "[[surface]]\nformula = \"x\"\n[[surface]]\nformula = \"y\"\n"
      "front = { color = [1, 0, 0], shininess = 7 }\n[surface.back]\ncolor = [0, 0, 1]\n",
      "sub.surf"));
  EXPECT_EQ(s.formula, "x");
  ASSERT_EQ(s.moreSurfaces.size(), 1u);
  EXPECT_EQ(s.moreSurfaces[0].materials.front.color, (Vec3{1, 0, 0}));
  EXPECT_EQ(s.moreSurfaces[0].materials.front.shininess, 7);
  EXPECT_EQ(s.moreSurfaces[0].materials.back.color, (Vec3{0, 0, 1}));
  EXPECT_EQ(s.moreSurfaces[0].materials.front.specular, surfaceMaterials(1).front.specular);
  // One [[surface]] table is a scene of one surface, saved in the short form.
  const Scene one =
      expectScene(parseScene("[[surface]]\nformula = \"x - 1\"\nlevel = 2\n", "one.surf"));
  EXPECT_EQ(one.formula, "x - 1");
  EXPECT_EQ(one.level, 2);
  EXPECT_TRUE(one.moreSurfaces.empty());
  EXPECT_NE(saveScene(one).find("\nformula = \"x - 1\"\n"), std::string::npos);
}

TEST(SceneSurfaces, TheSceneFunctionIsTheProductOfTheSurfaces) {
  const Scene s = threeSurfaces();
  ASSERT_EQ(surfaceCount(s), 3u);
  ParseResult parsed = parseSceneFormula(s);
  ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
  const Formula& f = std::get<Formula>(parsed);
  const std::vector<double> values = paramValues(s, f.graph);
  ASSERT_EQ(f.graph.params(), std::vector<std::string>{"r"});  // shared by the surfaces
  PointEvaluator eval(compileTape(f.graph, {f.root}));
  const double x = 0.3, y = -0.2, z = 0.9;
  const double expected = (x * x + y * y + z * z - 0.75 - 0.125) * (z - 0.75 * x + 0.5) * (x * y);
  EXPECT_NEAR(eval.eval1(x, y, z, values), expected, 1e-15);
  // Each surface alone, its level applied; the others' entries of the scene untouched.
  const Scene second = surfaceScene(s, 1);
  EXPECT_EQ(second.formula, "z - r*x");
  EXPECT_EQ(second.level, -0.5);
  EXPECT_TRUE(second.moreSurfaces.empty());
  EXPECT_EQ(second.render.materials, s.moreSurfaces[0].materials);
  EXPECT_EQ(second.params, s.params);
  // A formula error names its surface and points into that surface's formula.
  Scene bad = s;
  bad.moreSurfaces[1].formula = "x*)";
  std::size_t failed = 0;
  ParseResult broken = parseSceneFormula(bad, &failed);
  ASSERT_TRUE(std::holds_alternative<ParseError>(broken));
  EXPECT_EQ(failed, 2u);
  const std::string shown = formatSceneFormulaError(bad, failed, std::get<ParseError>(broken));
  EXPECT_EQ(shown.rfind("surface 3:\n  x*)\n    ^", 0), 0u) << shown;
}

TEST(SceneRoundTrip, NoLightsAtAllRoundTrip) {
  Scene s;
  s.render.lights.sources.clear();
  const std::string text = saveScene(s);
  EXPECT_NE(text.find("source = []"), std::string::npos) << text;
  EXPECT_EQ(expectScene(parseScene(text, "dark.surf")), s) << text;
}

TEST(SceneRoundTrip, EightLightsRoundTrip) {
  Scene s;
  s.render.lights.sources.assign(kMaxLights, Light{});
  for (int i = 0; i < kMaxLights; ++i) s.render.lights.sources[i].intensity = 0.1 * i;
  EXPECT_EQ(expectScene(parseScene(saveScene(s), "eight.surf")), s);
}

TEST(SceneRoundTrip, TheThesisLightKeysOfOldFilesStillRead) {
  const Scene s = expectScene(
      parseScene("formula = \"x\"\n[lights.directional]\nintensity = 0.3\ndirection = [0, 0, -1]\n"
                 "[lights.point]\nposition = [1, 2, 3]\ncolor = [0.5, 0.5, 0.5]\n",
                 "old.surf"));
  ASSERT_EQ(s.render.lights.sources.size(), 2u);
  EXPECT_EQ(s.render.lights.sources[0].kind, LightKind::Directional);
  EXPECT_EQ(s.render.lights.sources[0].intensity, 0.3);
  EXPECT_EQ(s.render.lights.sources[0].direction, (Vec3{0, 0, -1}));
  EXPECT_EQ(s.render.lights.sources[1].kind, LightKind::Point);
  EXPECT_EQ(s.render.lights.sources[1].position, (Vec3{1, 2, 3}));
  EXPECT_EQ(s.render.lights.sources[1].color, (Vec3{0.5, 0.5, 0.5}));
  EXPECT_EQ(s.render.lights.sources[1].intensity, 0.6);
}

TEST(SceneRoundTrip, ALightListInTheFileReplacesTheThesisLights) {
  const Scene s = expectScene(
      parseScene("formula = \"x\"\n[[lights.source]]\nkind = \"point\"\nposition = [0, 0, 5]\n"
                 "[[lights.source]]\nenabled = false\n",
                 "list.surf"));
  ASSERT_EQ(s.render.lights.sources.size(), 2u);
  EXPECT_EQ(s.render.lights.sources[0].kind, LightKind::Point);
  EXPECT_EQ(s.render.lights.sources[0].position, (Vec3{0, 0, 5}));
  EXPECT_EQ(s.render.lights.sources[0].intensity, Light{}.intensity);
  EXPECT_FALSE(s.render.lights.sources[1].enabled);
  EXPECT_EQ(s.render.lights.sources[1].kind, LightKind::Directional);
}

TEST(SceneRoundTrip, EveryKeySurvivesSaveAndParse) {
  const Scene original = everyKeyChanged();
  const std::string text = saveScene(original);
  const Scene loaded = expectScene(parseScene(text, "saved.surf"));
  EXPECT_EQ(loaded, original) << text;
  EXPECT_EQ(saveScene(loaded), text);  // and the text is stable
}

TEST(SceneRoundTrip, DefaultSceneRoundTrips) {
  const Scene defaults;
  EXPECT_EQ(expectScene(parseScene(saveScene(defaults), "d.surf")), defaults);
}

TEST(SceneRoundTrip, NegativeZeroKeepsItsSign) {
  Scene s;
  s.render.camera.target = {-0.0, 0, 0};
  const Scene loaded = expectScene(parseScene(saveScene(s), "z.surf"));
  EXPECT_TRUE(std::signbit(loaded.render.camera.target[0]));
}

TEST(SceneRoundTrip, SavedTextHoldsEveryKey) {
  const std::string text = saveScene(Scene{});
  for (const std::string& key : sceneKeys()) {
    const auto* spec = scene_detail::findKey(key);
    if (spec && spec->legacyLight >= 0) continue;  // written as lights.source
    const auto dot = key.rfind('.');
    const std::string leaf = dot == std::string::npos ? key : key.substr(dot + 1);
    if (dot == std::string::npos) {
      EXPECT_NE(text.find("\n" + leaf + " = "), std::string::npos) << key;
      continue;
    }
    // The leaf must appear inside its own [table] section.
    const auto header = text.find("\n[" + key.substr(0, dot) + "]\n");
    ASSERT_NE(header, std::string::npos) << key;
    const auto next = text.find("\n[", header + 1);
    const auto at = text.find("\n" + leaf + " = ", header);
    EXPECT_TRUE(at != std::string::npos && at < next) << key;
  }
  EXPECT_NE(text.find("\n[params]\n"), std::string::npos);
  // Each light is a [[lights.source]] table holding every light key.
  const auto light = text.find("\n[[lights.source]]\n");
  ASSERT_NE(light, std::string::npos) << text;
  const auto next = text.find("\n[", light + 1);
  for (const auto& spec : scene_detail::lightKeySpecs()) {
    const auto at = text.find("\n" + std::string(spec.name) + " = ", light);
    EXPECT_TRUE(at != std::string::npos && at < next) << spec.name;
  }
}

std::string readDoc() {
  // ctest sets ZS_SOURCE_DIR; the compiled-in path serves a binary started by hand.
  const char* env = std::getenv("ZS_SOURCE_DIR");
  const char* root = env ? env : ZS_SCENE_TEST_SOURCE_DIR;
  std::ifstream in(std::string(root) + "/docs/surf-format.md");
  std::stringstream doc;
  doc << in.rdbuf();
  return doc.str();
}

TEST(SceneDocs, NameEveryKey) {
  const std::string doc = readDoc();
  ASSERT_FALSE(doc.empty()) << "docs/surf-format.md is missing";
  for (const std::string& key : sceneKeys()) {
    EXPECT_NE(doc.find("`" + key + "`"), std::string::npos) << key << " is undocumented";
  }
}

TEST(SceneDocs, CompleteExampleLoads) {
  const std::string doc = readDoc();
  const auto begin = doc.find("```toml\n");
  ASSERT_NE(begin, std::string::npos);
  const auto end = doc.find("```\n", begin + 8);
  ASSERT_NE(end, std::string::npos);
  const Scene s = expectScene(parseScene(doc.substr(begin + 8, end - begin - 8), "example"));
  EXPECT_EQ(s.formula, "x^4 + y^4 + z^4 - a");
  EXPECT_EQ(s.render.samples, 2);
  EXPECT_EQ(s.params, (std::vector<std::pair<std::string, double>>{{"a", 1.0}}));
}

TEST(SceneParams, ValuesFollowTheGraphOrderWithDefaultsForMissingOnes) {
  Scene s;
  s.params = {{"c", 3.0}, {"a", 1.0}, {"unused", 9.0}};
  const ParseResult parsed = parseFormula("a*x^2 + b*y^2 + c*z^2 - 1");
  ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
  const Graph& g = std::get<Formula>(parsed).graph;
  ASSERT_EQ(g.params().size(), 3u);
  const std::vector<double> values = paramValues(s, g);
  ASSERT_EQ(values.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string& name = g.params()[i];
    const double expected = name == "a" ? 1.0 : name == "c" ? 3.0 : kDefaultParamValue;
    EXPECT_EQ(values[i], expected) << name;
  }
}

TEST(SceneParams, FileOrderIsKept) {
  const Scene s = expectScene(
      parseScene("formula = \"x\"\n[params]\nzeta = 1\nalpha = 2\nmid = 3\n", "p.surf"));
  ASSERT_EQ(s.params.size(), 3u);
  EXPECT_EQ(s.params[0].first, "zeta");
  EXPECT_EQ(s.params[1].first, "alpha");
  EXPECT_EQ(s.params[2].first, "mid");
}

}  // namespace
}  // namespace zs
