// --set KEY=VALUE: the same keys, validation and hints as a file, columns into the assignment.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "scene/scene_io.hpp"

namespace zs {
namespace {

void expectApplied(Scene& s, const char* assignment) {
  if (auto e = applyOverride(s, assignment)) ADD_FAILURE() << formatSceneError(*e);
}

TEST(SceneOverride, SetsVectorsNumbersEnumsAndBooleans) {
  Scene s;
  expectApplied(s, "camera.eye=[0,0,3]");
  expectApplied(s, "domain.min=[-2,-2,-2]");
  expectApplied(s, "octree.level=3");
  expectApplied(s, "octree.criteria=\"uniform\"");
  expectApplied(s, "lights.point.intensity = 0.3");
  expectApplied(s, "highlights.border.enabled=false");
  expectApplied(s, "samples=2");
  EXPECT_EQ(s.render.camera.eye, (Vec3{0, 0, 3}));
  EXPECT_EQ(s.domain.min, (Vec3{-2, -2, -2}));
  EXPECT_EQ(s.octree.level, 3);
  EXPECT_EQ(s.octree.criteria, Criteria::Uniform);
  EXPECT_EQ(s.render.lights.sources[1].intensity, 0.3);
  EXPECT_FALSE(s.render.border.enabled);
  EXPECT_EQ(s.render.samples, 2);
}

TEST(SceneOverride, LightsByNumberAndAsAWholeList) {
  Scene s;
  expectApplied(s, "lights.source.2.intensity=0.25");
  expectApplied(s, "lights.source.1={kind=\"point\", position=[1, 2, 3]}");
  ASSERT_EQ(s.render.lights.sources.size(), 2u);
  EXPECT_EQ(s.render.lights.sources[1].intensity, 0.25);
  EXPECT_EQ(s.render.lights.sources[0].kind, LightKind::Point);
  EXPECT_EQ(s.render.lights.sources[0].position, (Vec3{1, 2, 3}));
  EXPECT_EQ(s.render.lights.sources[0].intensity, 0.8);  // kept: only the keys named change
  expectApplied(s,
                "lights.source=[{kind=\"directional\", direction=[0,0,-1]}, {}, {enabled=false}]");
  ASSERT_EQ(s.render.lights.sources.size(), 3u);
  EXPECT_EQ(s.render.lights.sources[0].direction, (Vec3{0, 0, -1}));
  EXPECT_FALSE(s.render.lights.sources[2].enabled);
  expectApplied(s, "materials.back.diffuse=0.5");
  expectApplied(s, "shading.color=\"gauss\"");
  EXPECT_EQ(s.render.materials.back.diffuse, 0.5);
  EXPECT_EQ(s.render.shading.color, ColorMode::Gauss);
}

TEST(SceneOverride, ALightThatDoesNotExistIsRefusedWithItsColumn) {
  Scene s;
  const auto e = applyOverride(s, "lights.source.5.intensity=0.25");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->file, "--set");
  EXPECT_EQ(e->line, 1);
  EXPECT_EQ(e->column, 15);
  EXPECT_NE(e->message.find("no light 5"), std::string::npos) << e->message;
  EXPECT_NE(e->hint.find("from 1 to 2"), std::string::npos) << e->hint;
  EXPECT_EQ(s, Scene{});
}

TEST(SceneOverride, ParamsAreAddedThenReplaced) {
  Scene s;
  expectApplied(s, "params.a=0.2");
  expectApplied(s, "params.b=1");
  expectApplied(s, "params.a=0.7");
  ASSERT_EQ(s.params.size(), 2u);
  EXPECT_EQ(s.params[0], (std::pair<std::string, double>{"a", 0.7}));
  EXPECT_EQ(s.params[1], (std::pair<std::string, double>{"b", 1.0}));
}

TEST(SceneOverride, FormulaAndInlineTable) {
  Scene s;
  expectApplied(s, "formula=\"x^2 + y^2 - 1\"");
  expectApplied(s, "camera={fov_y=30, projection=\"orthographic\", height=4}");
  EXPECT_EQ(s.formula, "x^2 + y^2 - 1");
  EXPECT_EQ(s.render.camera.fovY, 30);
  EXPECT_EQ(s.render.camera.projection, Projection::Orthographic);
  EXPECT_EQ(s.render.camera.height, 4);
}

TEST(SceneOverride, SeveralAreCheckedTogetherAfterTheLast) {
  // The first assignment alone makes up parallel to the view (eye (0,0,4) -> origin); with
  // the second it is fine. Either order works.
  for (const std::vector<std::string>& sets :
       {std::vector<std::string>{"camera.up=[0,0,1]", "camera.eye=[0,5,0]"},
        std::vector<std::string>{"camera.eye=[0,5,0]", "camera.up=[0,0,1]"},
        std::vector<std::string>{"domain.min=[3,3,3]", "domain.max=[4,4,4]"}}) {
    Scene s;
    const auto e = applyOverrides(s, sets);
    EXPECT_FALSE(e) << formatSceneError(*e);
  }
  Scene s;
  ASSERT_FALSE(
      applyOverrides(s, std::vector<std::string>{"camera.up=[0,0,1]", "camera.eye=[0,5,0]"}));
  EXPECT_EQ(s.render.camera.up, (Vec3{0, 0, 1}));
  EXPECT_EQ(s.render.camera.eye, (Vec3{0, 5, 0}));
}

TEST(SceneOverride, SeveralThatStayInconsistentPointAtTheLatestKeyInvolved) {
  Scene s;
  const Scene before = s;
  const std::vector<std::string> sets{"camera.eye=[0,5,0]", "octree.level=2", "camera.up = [0,1,0]",
                                      "samples=2"};
  const auto e = applyOverrides(s, sets);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->key, "camera.up");
  EXPECT_NE(e->message.find("parallel to the view direction"), std::string::npos);
  // The third assignment, at its value.
  EXPECT_EQ(e->column, 13) << formatSceneError(*e);
  EXPECT_NE(formatSceneError(*e).find("camera.up = [0,1,0]"), std::string::npos);
  EXPECT_EQ(s, before);  // unchanged on error
}

TEST(SceneOverride, SeveralStopAtTheFirstMalformedOne) {
  Scene s;
  const auto e = applyOverrides(s, std::vector<std::string>{"octree.level=2", "samples", "x=1"});
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("expected KEY=VALUE, got \"samples\""), std::string::npos);
  EXPECT_EQ(s.octree.level, Scene{}.octree.level);
}

struct BadOverride {
  const char* assignment;
  int column;
  const char* key;
  const char* message;
  const char* hint;
};

void PrintTo(const BadOverride& bad, std::ostream* os) {
  *os << bad.assignment;
}

class BadOverrides : public ::testing::TestWithParam<BadOverride> {};

TEST_P(BadOverrides, AreRejectedAndLeaveTheSceneAlone) {
  const BadOverride& bad = GetParam();
  Scene s;
  s.params = {{"a", 0.25}};
  const Scene before = s;
  const auto e = applyOverride(s, bad.assignment);
  ASSERT_TRUE(e.has_value()) << bad.assignment << " was accepted";
  const std::string shown = formatSceneError(*e);
  EXPECT_EQ(e->file, "--set");
  EXPECT_EQ(e->line, 1) << shown;
  EXPECT_EQ(e->column, bad.column) << shown;
  EXPECT_EQ(e->key, bad.key) << shown;
  EXPECT_NE(e->message.find(bad.message), std::string::npos) << shown;
  EXPECT_NE(e->hint.find(bad.hint), std::string::npos) << shown;
  EXPECT_EQ(shown.rfind("--set:1:" + std::to_string(bad.column) + ": error: ", 0), 0u) << shown;
  EXPECT_EQ(s, before);
}

const BadOverride kBadOverrides[] = {
    {"camera.fovy=30", 8, "camera.fovy", "unknown key", "did you mean \"fov_y\"?"},
    {"octree.level=13", 14, "octree.level", "[0, 12]", ""},
    {"camera.eye=[0,0]", 12, "camera.eye", "exactly 3 numbers", ""},
    {"camera.projection=orthographic", 19, "camera.projection", "", "double quotes"},
    {"camera.projection=\"ortho\"", 19, "camera.projection", "no option", "orthographic"},
    {"domain.min=[5,5,5]", 12, "domain.min", "must be less than domain.max", ""},
    {"camera.target=[0,0,4]", 15, "camera.target", "same point", ""},
    {"formula=\"x^2 + )\"", 16, "formula", "formula: ", ""},
    {"params.a=\"big\"", 10, "params.a", "must be a number", ""},
    {"octree.level", 13, "", "expected KEY=VALUE", "--set camera.eye"},
    {"octree.level=", 14, "octree.level", "missing VALUE", ""},
    {"=3", 1, "", "missing KEY", ""},
};

INSTANTIATE_TEST_SUITE_P(Scene, BadOverrides, ::testing::ValuesIn(kBadOverrides));

}  // namespace
}  // namespace zs
