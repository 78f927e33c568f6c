// Bad input never crashes: thousands of damaged copies of a good .jsurf file (bytes
// replaced, deleted, duplicated) are each either refused with a positioned error or
// imported into a scene that exports and imports again.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "jsurf/jsurf.hpp"

namespace zs::jsurf {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string damage(std::string text, std::mt19937& rng) {
  static const std::string kBytes = "0123456789.-+eE =:\\\n\r\t#!u()^*/xyzab ONOFF\x80\xff";
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int i = 0; i < edits && !text.empty(); ++i) {
    const std::size_t at = rng() % text.size();
    switch (rng() % 3) {
      case 0:
        text[at] = kBytes[rng() % kBytes.size()];
        break;
      case 1:
        text.erase(at, 1 + rng() % 8);
        break;
      default:
        text.insert(at, text.substr(at, 1 + rng() % 16));
        break;
    }
  }
  return text;
}

TEST(JsurfRobustness, DamagedFilesAreRefusedOrImportedNeverCrash) {
  const std::string good = readFile(std::string(ZS_JSURF_TEST_DATA) + "/turned-quartic.jsurf");
  ASSERT_FALSE(good.empty());
  std::mt19937 rng(12);
  int refused = 0, imported = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::string text = damage(good, rng);
    const ImportResult r = importJsurf(text, "damaged.jsurf");
    if (const auto* err = std::get_if<SceneError>(&r)) {
      ++refused;
      EXPECT_FALSE(err->message.empty());
      EXPECT_EQ(err->message.find("a bug in zeroset"), std::string::npos) << err->message << "\n"
                                                                          << text;
      continue;
    }
    ++imported;
    auto exported = exportJsurf(std::get<Imported>(r).scene);
    // A damaged formula may still parse but no longer be SURFER's (e.g. "x^2y"): refused
    // with a reason, never a crash.
    if (const auto* e = std::get_if<Exported>(&exported)) {
      const ImportResult again = importJsurf(e->text, "again.jsurf");
      EXPECT_TRUE(std::holds_alternative<Imported>(again))
          << formatSceneError(std::get<SceneError>(again)) << e->text;
    } else {
      EXPECT_FALSE(std::get<std::string>(exported).empty());
    }
  }
  EXPECT_GT(refused, 100);
  EXPECT_GT(imported, 100);
}

}  // namespace
}  // namespace zs::jsurf
