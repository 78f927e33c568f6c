// Formula errors inside files (mapped through TOML escapes), caret output, files on disk and
// the scene-or-formula argument.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>

#include "scene/scene_io.hpp"

namespace zs {
namespace {

SceneError expectError(const SceneResult& r) {
  if (std::holds_alternative<Scene>(r)) {
    ADD_FAILURE() << "accepted";
    return {};
  }
  return std::get<SceneError>(r);
}

struct FormulaInFile {
  const char* name;
  const char* text;
  int line;
  int column;
};

// In each, the formula's value is "x^2 + )" up to whitespace, and the parser stops at ')'.
const FormulaInFile kFormulaErrors[] = {
    {"basic string", "formula = \"x^2 + )\"\n", 1, 18},
    {"after an escape", "formula = \"\\tx^2 + )\"\n", 1, 20},
    {"after a unicode escape", "formula = \"\\u0078^2 + )\"\n", 1, 23},
    {"literal string", "formula = 'x^2 + )'\n", 1, 18},
    {"multi-line string", "# a comment\nformula = \"\"\"\nx^2 +\n  y^2 + )\"\"\"\n", 4, 9},
    {"line-ending backslash", "formula = \"\"\"x^2 + \\\n    )\"\"\"\n", 2, 5},
    {"after a multi-byte character", "# é\nformula = \"x^2 + )\" # ü\n", 2, 18},
};

void PrintTo(const FormulaInFile& c, std::ostream* os) {
  *os << c.name;
}

class FormulaErrorInFile : public ::testing::TestWithParam<FormulaInFile> {};

TEST_P(FormulaErrorInFile, PointsInsideTheString) {
  const FormulaInFile& c = GetParam();
  const SceneError e = expectError(parseScene(c.text, "f.surf"));
  EXPECT_EQ(e.key, "formula");
  EXPECT_EQ(e.line, c.line) << formatSceneError(e);
  EXPECT_EQ(e.column, c.column) << formatSceneError(e);
}

INSTANTIATE_TEST_SUITE_P(Scene, FormulaErrorInFile, ::testing::ValuesIn(kFormulaErrors));

TEST(SceneErrorFormat, ShowsTheLineAndACaret) {
  const SceneError e = expectError(parseScene("formula = \"x^2 + )\"\n", "f.surf"));
  const std::string shown = formatSceneError(e);
  EXPECT_EQ(shown.rfind("f.surf:1:18: error: formula: ", 0), 0u) << shown;
  EXPECT_NE(shown.find("\n  formula = \"x^2 + )\"\n" + std::string(2 + 17, ' ') + "^\n"),
            std::string::npos)
      << shown;
}

TEST(SceneErrorFormat, HintLineAndNoCaretWithoutPosition) {
  SceneError e{"a.surf", 0, 0, "", "cannot open scene file: gone", "check the path", "", 1};
  EXPECT_EQ(formatSceneError(e),
            "a.surf: error: cannot open scene file: gone\n  hint: check the path\n");
}

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("zs_scene_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::filesystem::path dir_;
};

TEST_F(TempDir, LoadSceneOrFormulaReadsAFile) {
  Scene s;
  s.formula = "x^4 + y^4 + z^4 - 1";
  s.render.camera.fovY = 25;
  const auto path = write("cube.surf", saveScene(s));
  const SceneResult r = loadSceneOrFormula(path.string());
  ASSERT_TRUE(std::holds_alternative<Scene>(r)) << formatSceneError(std::get<SceneError>(r));
  EXPECT_EQ(std::get<Scene>(r), s);
}

TEST_F(TempDir, ErrorsInAFileNameThePath) {
  const auto path = write("bad.surf", "formula = \"x\"\n[octree]\nlevel = 99\n");
  const SceneError e = expectError(loadScene(path));
  EXPECT_EQ(e.file, path.string());
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 9);
}

TEST_F(TempDir, MissingSurfFileIsAnErrorNotAFormula) {
  const auto path = dir_ / "missing.surf";
  const SceneError e = expectError(loadSceneOrFormula(path.string()));
  EXPECT_EQ(e.file, path.string());
  EXPECT_EQ(e.line, 0);
  EXPECT_NE(e.message.find("cannot open"), std::string::npos) << e.message;
}

TEST(SceneOrFormula, AFormulaGetsDefaults) {
  const SceneResult r = loadSceneOrFormula("x^2 + y^2 - z^2 - a");
  ASSERT_TRUE(std::holds_alternative<Scene>(r));
  Scene expected;
  expected.formula = "x^2 + y^2 - z^2 - a";
  EXPECT_EQ(std::get<Scene>(r), expected);
}

TEST(SceneOrFormula, AFormulaErrorIsShownWithACaret) {
  const SceneError e = expectError(loadSceneOrFormula("x^2 + )"));
  EXPECT_EQ(e.file, "<formula>");
  EXPECT_EQ(e.line, 1);
  EXPECT_EQ(e.column, 7);
  EXPECT_EQ(formatSceneError(e).rfind("<formula>:1:7: error: formula: ", 0), 0u);
  EXPECT_NE(formatSceneError(e).find("\n  x^2 + )\n        ^\n"), std::string::npos)
      << formatSceneError(e);
}

}  // namespace
}  // namespace zs
