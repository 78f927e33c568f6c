// Malformed scene files: each is rejected with the exact file:line:column, the key, and
// (where one helps) a hint.
#include <gtest/gtest.h>

#include <cctype>
#include <ostream>
#include <string>

#include "scene/scene_io.hpp"

namespace zs {
namespace {

struct BadScene {
  const char* name;
  const char* text;
  int line;
  int column;
  const char* key;      // expected SceneError::key
  const char* message;  // a substring of the message
  const char* hint;     // a substring of the hint ("" = not checked)
};

const BadScene kBadScenes[] = {
    {"toml syntax: unclosed array", "formula = \"x\"\n[camera]\neye = [0, 0,\n", 3, 14, "", "", ""},
    {"toml syntax: unterminated string", "formula = \"x^2 - 1\n", 1, 19, "", "", ""},
    {"toml syntax: key without value", "formula = \"x\"\nsamples =\n", 2, 10, "", "", ""},
    {"duplicate key", "formula = \"x\"\n[octree]\nlevel = 1\nlevel = 2\n", 4, 9, "", "level", ""},
    {"duplicate table", "formula = \"x\"\n[camera]\nfov_y = 30\n[camera]\n", 4, 1, "", "camera",
     ""},
    {"wrong type: string for integer", "formula = \"x\"\n[octree]\nlevel = \"3\"\n", 3, 9,
     "octree.level", "must be an integer, got a string", ""},
    {"wrong type: float for integer", "formula = \"x\"\n[tracing]\nhits = 2.5\n", 3, 8,
     "tracing.hits", "must be an integer", "decimal point"},
    {"wrong type: string for boolean", "formula = \"x\"\n[reflection]\nenabled = \"yes\"\n", 3, 11,
     "reflection.enabled", "must be a boolean", "without quotes"},
    {"unknown key in a table", "formula = \"x\"\n[camera]\nfovy = 40\n", 3, 1, "camera.fovy",
     "unknown key \"camera.fovy\"", "did you mean \"fov_y\"?"},
    {"unknown table", "formula = \"x\"\n[camara]\neye = [0, 0, 4]\n", 2, 2, "camara", "unknown key",
     "did you mean \"camera\"?"},
    {"key in the wrong table", "formula = \"x\"\nfov_y = 40\n", 2, 1, "fov_y", "unknown key",
     "did you mean \"camera.fov_y\"?"},
    {"unknown key far from any", "formula = \"x\"\n[tracing]\nquality = 3\n", 3, 1,
     "tracing.quality", "unknown key", "valid keys in [tracing]: method, intervals, epsilon"},
    {"octree level out of range", "formula = \"x\"\n[octree]\nlevel = 13\n", 3, 9, "octree.level",
     "must be [0, 12], got 13", ""},
    {"zero intervals", "formula = \"x\"\n[tracing]\nintervals = 0\n", 3, 13, "tracing.intervals",
     "[1, 1000]", ""},
    {"negative epsilon", "formula = \"x\"\n[tracing]\nepsilon = -0.1\n", 3, 11, "tracing.epsilon",
     "must be > 0", ""},
    {"too many samples", "formula = \"x\"\nsamples = 9\n", 2, 11, "samples", "[1, 8]", ""},
    {"fov_y of 180", "formula = \"x\"\n[camera]\nfov_y = 180\n", 3, 9, "camera.fov_y",
     "(0.0, 180.0), got 180.0", ""},
    {"vector of 2 numbers", "formula = \"x\"\n[camera]\neye = [0, 4]\n", 3, 7, "camera.eye",
     "exactly 3 numbers, got 2", "[x, y, z]"},
    {"number where a vector goes", "formula = \"x\"\n[domain]\nmin = -1\n", 3, 7, "domain.min",
     "must be a vector of 3 numbers", "[x, y, z]"},
    {"string inside a vector", "formula = \"x\"\n[camera]\neye = [0, \"4\", 1]\n", 3, 11,
     "camera.eye.y", "must be a number, got a string", ""},
    {"nan", "formula = \"x\"\n[tracing]\nepsilon = nan\n", 3, 11, "tracing.epsilon",
     "finite number", ""},
    {"infinity inside a vector", "formula = \"x\"\n[lights.point]\nposition = [1, 2, -inf]\n", 3,
     19, "lights.point.position.z", "finite number, got -inf", ""},
    {"color above 1", "formula = \"x\"\nbackground = [1.5, 0, 0]\n", 2, 15, "background.x",
     "[0.0, 1.0]", ""},
    {"zero opacity", "formula = \"x\"\nopacity = 0\n", 2, 11, "opacity", "(0.0, 1.0]", ""},
    {"bad enum word", "formula = \"x\"\n[camera]\nprojection = \"persp\"\n", 3, 14,
     "camera.projection", "no option \"persp\"",
     "did you mean \"perspective\"? expected one of \"perspective\", \"orthographic\""},
    {"misspelled enum word", "formula = \"x\"\n[octree]\ncriteria = \"thesys\"\n", 3, 12,
     "octree.criteria", "no option", "did you mean \"thesis\"?"},
    {"domain min above max", "formula = \"x\"\n[domain]\nmin = [0, 2, 0]\nmax = [1, 1, 1]\n", 4, 7,
     "domain.max", "domain.min.y (2.0) must be less than domain.max.y (1.0)", ""},
    {"eye equals target", "formula = \"x\"\n[camera]\neye = [0, 0, 0]\n", 3, 7, "camera.eye",
     "same point", ""},
    {"zero up vector", "formula = \"x\"\n[camera]\nup = [0, 0, 0]\n", 3, 6, "camera.up",
     "zero vector", ""},
    {"up along the view direction", "formula = \"x\"\n[camera]\nup = [0, 0, -2]\n", 3, 6,
     "camera.up", "parallel to the view direction", ""},
    {"light: unknown key",
     "formula = \"x\"\n[[lights.source]]\nkind = \"point\"\nposiiton = [0, 0, 5]\n", 4, 1,
     "lights.source.1.posiiton", "unknown key", "did you mean \"position\"?"},
    {"light: unknown kind",
     "formula = \"x\"\n[[lights.source]]\n[[lights.source]]\nkind = \"spot\"\n", 4, 8,
     "lights.source.2.kind", "has no option \"spot\"", "\"directional\", \"point\""},
    {"light: negative intensity", "formula = \"x\"\n[[lights.source]]\nintensity = -1\n", 3, 13,
     "lights.source.1.intensity", "must be >= 0.0", ""},
    {"light: zero direction", "formula = \"x\"\n[[lights.source]]\ndirection = [0, 0, 0]\n", 3, 13,
     "lights.source.1.direction", "zero vector", ""},
    {"light: not a table", "formula = \"x\"\n[lights]\nsource = [1]\n", 3, 11, "lights.source.1",
     "must be a table, got an integer", ""},
    {"contour function with a parameter",
     "formula = \"x\"\n[shading.contours]\nfunction = \"z - a\"\n", 3, 17,
     "shading.contours.function", "\"a\" is a parameter", "z - 0.5"},
    {"contour function that does not parse",
     "formula = \"x\"\n[shading.contours]\nfunction = \"z +\"\n", 3, 15,
     "shading.contours.function", "shading.contours.function: expected an operand", ""},
    {"contour function not a string", "formula = \"x\"\n[shading.contours]\nfunction = 3\n", 3, 12,
     "shading.contours.function", "must be a string", ""},
    {"clip plane: zero normal", "formula = \"x\"\n[[clip.plane]]\nnormal = [0, 0, 0]\n", 3, 10,
     "clip.plane.1.normal", "zero vector", ""},
    {"clip plane: unknown key", "formula = \"x\"\n[[clip.plane]]\nofset = 1\n", 3, 1,
     "clip.plane.1.ofset", "unknown key", "did you mean \"offset\"?"},
    {"clip plane: five planes", "formula = \"x\"\nclip.plane = [{}, {}, {}, {}, {}]\n", 2, 31,
     "clip.plane", "at most 4 clip planes, got 5", "enabled = false"},
    {"light: nine lights",
     "formula = \"x\"\nlights.source = [{}, {}, {}, {}, {}, {}, {}, {}, {}]\n", 2, 50,
     "lights.source", "at most 8 lights, got 9", "enabled = false"},
    {"light: old and new keys together",
     "formula = \"x\"\n[lights.point]\nintensity = 0.2\n[[lights.source]]\nkind = \"point\"\n", 4,
     1, "lights.source", "both describe the lights", "[[lights.source]]"},
    {"light: old keys after a list",
     "formula = \"x\"\n[[lights.source]]\nkind = \"point\"\n[lights.directional]\nintensity = "
     "0.2\n",
     5, 13, "lights.directional.intensity", "lists its lights in [[lights.source]]",
     "lights.source.N"},
    {"material ambient above 1", "formula = \"x\"\n[materials.back]\nambient = 1.5\n", 3, 11,
     "materials.back.ambient", "[0.0, 1.0], got 1.5", ""},
    {"unknown color mode", "formula = \"x\"\n[shading]\ncolor = \"gaussian\"\n", 3, 9,
     "shading.color", "has no option \"gaussian\"",
     "\"material\", \"gauss\", \"mean\", \"normal\""},
    {"negative curvature range", "formula = \"x\"\nshading.curvature_range = -1\n", 2, 27,
     "shading.curvature_range", "must be >= 0.0", ""},
    {"zero light direction", "formula = \"x\"\n[lights.directional]\ndirection = [0, 0, 0]\n", 3,
     13, "lights.directional.direction", "zero vector", ""},
    {"table expected", "formula = \"x\"\ncamera = 3\n", 2, 10, "camera", "must be a table",
     "[camera]"},
    {"parameter named x", "formula = \"x\"\n[params]\nx = 1\n", 3, 1, "params.x",
     "not a parameter name", ""},
    {"parameter with a string value", "formula = \"x\"\n[params]\na = \"big\"\n", 3, 5, "params.a",
     "must be a number", ""},
    {"formula not a string", "formula = 3\n", 1, 11, "formula", "must be a string",
     "double quotes"},
    {"no formula", "[octree]\nlevel = 2\n", 1, 1, "formula", "no formula", "formula = "},
    {"a level but no formula", "[surface]\nlevel = 2\n", 1, 1, "formula", "no formula",
     "formula = "},
    {"surface table without a formula", "[[surface]]\nformula = \"x\"\n[[surface]]\nlevel = 1\n", 3,
     1, "surface.2.formula", "this surface has no formula", "[[surface]] table needs one"},
    {"surface formula that does not parse", "[[surface]]\nformula = \"x^^2\"\n", 2, 14,
     "surface.1.formula", "surface.1.formula: expected an operand", ""},
    {"formula beside surface tables", "formula = \"x\"\n[[surface]]\nformula = \"y\"\n", 1, 11,
     "formula", "lists its surfaces in [[surface]] tables", "first [[surface]] table"},
    {"materials after surface tables",
     "[[surface]]\nformula = \"y\"\n[materials.front]\ncolor = [1, 0, 0]\n", 3, 1,
     "materials.front", "lists its surfaces in [[surface]] tables", "first [[surface]] table"},
    {"five surfaces",
     "surface = [{formula = \"x\"}, {formula = \"x\"}, {formula = \"x\"}, {formula = \"x\"}, "
     "{formula = \"x\"}]\n",
     1, 80, "surface", "at most 4 surfaces, got 5", "product"},
    {"no surfaces", "surface = []\n", 1, 11, "surface", "at least one surface", "[[surface]]"},
    {"a parameter given two values by two surfaces",
     "[[surface]]\nformula = \"x - a\"\nparams = { a = 1 }\n[[surface]]\nformula = \"y - a\"\n"
     "params = { a = 2 }\n",
     6, 16, "surface.2.params.a", "parameter a is 2.0 here but 1.0 above",
     "share their parameters"},
    {"a surface key under [surface]", "formula = \"x\"\n[surface]\nformula = \"y\"\n", 3, 1,
     "surface.formula", "is a key of a [[surface]] table, not of [surface]", "two brackets"},
    {"unknown key under [surface]", "formula = \"x\"\n[surface]\nlevl = 1\n", 3, 1, "surface.levl",
     "unknown key", "level"},
    {"unknown surface key", "[[surface]]\nformula = \"x\"\nfront.colour = [1, 0, 0]\n", 3, 7,
     "surface.1.front.colour", "unknown key", "front.color"},
    {"surface color out of range", "[[surface]]\nformula = \"x\"\nback.color = [2, 0, 0]\n", 3, 15,
     "surface.1.back.color.x", "must be [0.0, 1.0], got 2.0", ""},
};

// gtest prints the case's name instead of its bytes.
void PrintTo(const BadScene& bad, std::ostream* os) {
  *os << bad.name;
}

class MalformedScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(MalformedScene, IsRejectedAtItsPosition) {
  const BadScene& bad = GetParam();
  const SceneResult r = parseScene(bad.text, "bad.surf");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r)) << bad.name << " was accepted";
  const SceneError& e = std::get<SceneError>(r);
  const std::string shown = formatSceneError(e);
  EXPECT_EQ(e.file, "bad.surf");
  EXPECT_EQ(e.line, bad.line) << shown;
  EXPECT_EQ(e.column, bad.column) << shown;
  EXPECT_EQ(e.key, bad.key) << shown;
  EXPECT_NE(e.message.find(bad.message), std::string::npos) << shown;
  EXPECT_NE(e.hint.find(bad.hint), std::string::npos) << shown;
  const std::string where =
      "bad.surf:" + std::to_string(bad.line) + ":" + std::to_string(bad.column) + ": error: ";
  EXPECT_EQ(shown.rfind(where, 0), 0u) << shown;
}

INSTANTIATE_TEST_SUITE_P(Scene, MalformedScene, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& info) {
                           std::string n;
                           for (const char* c = info.param.name; *c; ++c) {
                             n += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
                           }
                           return n;
                         });

}  // namespace
}  // namespace zs
