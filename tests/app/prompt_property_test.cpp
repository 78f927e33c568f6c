// The prompt without a window (app/repl/headless_target.hpp) driven through random edit
// sequences, as a person types them: formulas (some that fail), `:set` of random keys of
// the schema with valid and invalid values, `:load` of .surf files. After each edit the
// picture the prompt wrote must equal what a fresh `zeroset render` of its `:save`d scene
// draws (the image tests' tolerance), and an edit it refused must leave the scene as it
// was. The session stage's own, longer run is tests/session/session_property_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <variant>

#include "app/repl/command.hpp"
#include "app/repl/headless_target.hpp"
#include "process.hpp"
#include "render/image.hpp"
#include "scene/scene_io.hpp"
#include "support/random_edit.hpp"

namespace zs::app {
namespace {

// Every picture small: the sizes go into every .surf the test writes or loads.
constexpr const char* kSmall = "[image]\nwidth = 48\nheight = 36\n";

std::string run(HeadlessTarget& target, const std::string& line) {
  auto parsed = parsePromptLine(line);
  if (auto* err = std::get_if<std::string>(&parsed)) return *err;
  return target.run(std::get<PromptCommand>(parsed));
}

std::string pathAfterWrote(const std::string& out) {
  const std::size_t at = out.rfind("wrote ");
  if (at == std::string::npos) return {};
  const std::size_t end = out.find('\n', at);
  return out.substr(at + 6, end == std::string::npos ? std::string::npos : end - at - 6);
}

TEST(PromptProperty, EveryEditDrawsWhatAFreshRenderOfTheSavedSceneDraws) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("zs-prompt-property-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  HeadlessTarget target(dir);
  const auto start = dir / "start.surf";
  std::ofstream(start) << "formula = \"x^2+y^2+z^2-1\"\n" << kSmall;
  ASSERT_NE(run(target, ":load " + start.string()).find("wrote "), std::string::npos);

  std::mt19937_64 rng(0x9e0'0001u);
  const auto saved = dir / "now.surf";
  std::string before = (run(target, ":save " + saved.string()), test::readText(saved));
  int refused = 0, compared = 0;
  constexpr int kSteps = 16;
  for (int step = 0; step < kSteps; ++step) {
    std::string line;
    switch (rng() % 4) {
      case 0: {
        const bool good = rng() % 3 != 0;
        line = good ? test::goodFormulas()[rng() % test::goodFormulas().size()]
                    : test::badFormulas()[rng() % test::badFormulas().size()];
        if (line.empty()) line = "x^2+(";  // an empty line is no edit at the prompt
        break;
      }
      case 1: {
        const auto file = dir / ("load-" + std::to_string(step) + ".surf");
        std::ofstream(file) << test::randomSurfText(rng, rng() % 2) << kSmall;
        line = ":load " + file.string();
        break;
      }
      default: {
        const Scene scene = std::get<Scene>(parseScene(before, "now.surf"));
        line = ":set " + test::randomAssignment(rng, scene);
        break;
      }
    }
    SCOPED_TRACE("step " + std::to_string(step) + ": " + line);
    const std::string out = run(target, line);
    run(target, ":save " + saved.string());
    const std::string now = test::readText(saved);
    const std::string picture = pathAfterWrote(out);
    if (picture.empty()) {
      ++refused;
      EXPECT_EQ(now, before) << "a refused edit changed the scene:\n" << out;
      continue;
    }
    // A fresh process draws the saved scene: what `zeroset render` makes of it.
    const auto reference = dir / ("reference-" + std::to_string(step) + ".png");
    test::Child render({ZS_ZEROSET_EXE, "render", saved.string(), "-o", reference.string()},
                       {{"DISPLAY", ""}}, test::Stdio::File, dir / "render.log");
    ASSERT_EQ(render.wait(60), 0) << test::readText(dir / "render.log");
    Image a, b;
    ASSERT_EQ(readPng(picture, a), "");
    ASSERT_EQ(readPng(reference.string(), b), "");
    const ImageDiff diff = compareImages(a, b);
    EXPECT_TRUE(withinTolerance(diff)) << diff.fractionOver * 100 << "% of pixels differ:\n" << now;
    ++compared;
    before = now;
  }
  EXPECT_GT(compared, 0);
  std::printf("%d prompt edits: %d refused, %d compared with a fresh render\n", kSteps, refused,
              compared);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace zs::app
