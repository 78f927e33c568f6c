// Bad scripts never crash: random edits of real scripts, deep nesting, huge degrees. Each
// ends in a scene or in an error placed inside the text.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "surfscript/surf_import.hpp"

namespace zs::surfscript {
namespace {

std::string readData(const std::string& name) {
  std::ifstream in(std::string(ZS_SURF_TEST_DATA) + "/" + name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int lineCount(const std::string& text) {
  return 1 + int(std::count(text.begin(), text.end(), '\n'));
}

void expectPlaced(const std::string& text, const ImportResult& r) {
  if (const auto* e = std::get_if<SceneError>(&r)) {
    EXPECT_FALSE(e->message.empty());
    EXPECT_EQ(e->message.find("a bug in zeroset"), std::string::npos) << text << "\n" << e->message;
    EXPECT_GE(e->line, 0);
    EXPECT_LE(e->line, lineCount(text));
  }
}

TEST(SurfRobustness, RandomEditsOfRealScripts) {
  std::mt19937 rng(20261208);
  const std::string alphabet = "xyz0123456789.+-*/^(),;=\" _abcdefghijklmnopqrstuvw\n";
  for (const char* name :
       {"cone_turned.pic", "kummer_camera.pic", "plane_in_cube.pic", "curves.pic"}) {
    const std::string original = readData(name);
    ASSERT_FALSE(original.empty()) << name;
    for (int trial = 0; trial < 300; ++trial) {
      std::string text = original;
      const int edits = 1 + int(rng() % 4);
      for (int k = 0; k < edits; ++k) {
        const std::size_t at = rng() % text.size();
        switch (rng() % 3) {
          case 0:
            text.erase(at, 1 + rng() % 3);
            break;
          case 1:
            text.insert(at, 1, alphabet[rng() % alphabet.size()]);
            break;
          default:
            text[at] = alphabet[rng() % alphabet.size()];
            break;
        }
        if (text.empty()) text = ";";
      }
      expectPlaced(text, importSurfScript(text, name));
      auto run = runSurfScript(text, name);
      if (const auto* e = std::get_if<SceneError>(&run)) EXPECT_LE(e->line, lineCount(text));
    }
  }
}

TEST(SurfRobustness, DeepNestingAndHugeDegreesAreErrors) {
  const std::string deep =
      "surface = " + std::string(5000, '(') + "x" + std::string(5000, ')') + ";";
  auto r = importSurfScript(deep, "deep.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_NE(std::get<SceneError>(r).message.find("nested too deeply"), std::string::npos);

  std::string chain = "surface = x";
  for (int i = 0; i < 5000; ++i) chain += " + x";
  r = importSurfScript(chain + "; draw_surface;", "chain.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_NE(std::get<SceneError>(r).message.find("nested too deeply"), std::string::npos);

  r = importSurfScript("surface = x^256^256;", "degree.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_NE(std::get<SceneError>(r).message.find("degree"), std::string::npos);

  r = importSurfScript("surface = " + std::string(3000, '-') + "x;", "signs.pic");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
}

}  // namespace
}  // namespace zs::surfscript
