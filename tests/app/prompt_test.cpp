// The prompt (`zeroset` with no arguments) without a display: through a pseudo-terminal
// (prompt, line editing, history) and through a pipe (no prompt, scripts). Each formula is
// rendered to a PNG whose path is printed; :save writes a .surf that :load reads back.
#include <gtest/gtest.h>

#include <variant>

#include "process.hpp"
#include "render/image.hpp"
#include "scene/scene_io.hpp"

namespace zs::test {
namespace {

constexpr const char* kPrompt = "F(x,y,z) = ";

std::vector<EnvChange> headlessEnv(const std::filesystem::path& dir) {
  return {{"DISPLAY", ""},
          {"WAYLAND_DISPLAY", ""},
          {"HOME", dir.string()},
          {"ZS_OUTPUT_DIR", dir.string()}};
}

// Non-white pixels of a PNG: the surface is there.
int drawnPixels(const std::filesystem::path& path) {
  Image image;
  if (!readPng(path.string(), image).empty()) return -1;
  int count = 0;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    count += image.rgba[i] < 250 || image.rgba[i + 1] < 250 || image.rgba[i + 2] < 250;
  return count;
}

std::string pathAfter(const std::string& text, const std::string& marker, std::size_t from = 0) {
  const auto at = text.find(marker, from);
  if (at == std::string::npos) return {};
  const auto start = at + marker.size();
  return text.substr(start, text.find_first_of("\r\n", start) - start);
}

TEST(Prompt, TerminalPromptsRendersAndRecallsHistory) {
  const auto dir = freshDir("pty");
  Child c({ZS_ZEROSET_EXE}, headlessEnv(dir), Stdio::Pty);
  ASSERT_TRUE(c.readUntil(kPrompt, 30)) << c.output();

  c.write("x^2 + y^2 + z^2 - 1\r");
  ASSERT_TRUE(c.readUntil("wrote ", 60)) << c.output();
  ASSERT_TRUE(c.readUntil(kPrompt, 30, c.output().find("wrote ")));
  const std::string first = pathAfter(c.output(), "wrote ");
  EXPECT_GT(drawnPixels(first), 10000) << first;

  // A typo prints the caret under the formula and the prompt comes back.
  std::size_t mark = c.output().size();
  c.write("x^2 + * y\r");
  ASSERT_TRUE(c.readUntil("^", 30, mark + 12)) << c.output();
  ASSERT_TRUE(c.readUntil(kPrompt, 30, mark + 12)) << c.output();
  EXPECT_NE(c.output().find("error", mark), std::string::npos) << c.output().substr(mark);

  // Up arrow twice recalls the sphere (libedit history); Enter renders it again.
  mark = c.output().size();
  c.write("\x1b[A\x1b[A\r");
  ASSERT_TRUE(c.readUntil("wrote ", 60, mark)) << c.output().substr(mark);
  const std::string second = pathAfter(c.output(), "wrote ", mark);
  EXPECT_NE(second, first);
  EXPECT_GT(drawnPixels(second), 10000);

  mark = c.output().size();
  c.write(":save " + (dir / "view.surf").string() + "\r");
  ASSERT_TRUE(c.readUntil("saved: ", 30, mark)) << c.output().substr(mark);
  c.write(":quit\r");
  EXPECT_EQ(c.wait(30), 0);
  SceneResult saved = loadScene(dir / "view.surf");
  ASSERT_TRUE(std::holds_alternative<Scene>(saved));
  EXPECT_EQ(std::get<Scene>(saved).formula, "x^2 + y^2 + z^2 - 1");
  EXPECT_TRUE(std::filesystem::exists(dir / ".zeroset_history"));
}

TEST(Prompt, PipeRunsScriptsWithoutPrompting) {
  const auto dir = freshDir("pipe");
  Child c({ZS_ZEROSET_EXE}, headlessEnv(dir), Stdio::Pipe);
  const auto png = dir / "cuboid.png", surf = dir / "cuboid.surf";
  c.write(
      "x^4 + y^4 + z^4 - a\n"
      ":set params.a=0.5\n"
      ":set tracing.epsilon=0.01\n"
      ":set camera.eye=[1, 2, 4]\n"
      "x^^2\n"
      ":set tracing.epsilon=-1\n"
      ":bogus\n"
      ":png " +
      png.string() +
      "\n"
      ":save " +
      surf.string() +
      "\n"
      ":help\n");
  c.closeInput();
  ASSERT_TRUE(c.readUntil(":quit", 120)) << c.output();  // the end of :help
  EXPECT_EQ(c.wait(30), 0);
  const std::string& out = c.output();
  EXPECT_EQ(out.find(kPrompt), std::string::npos) << "no prompt on a pipe";
  EXPECT_NE(out.find("unknown command ':bogus'"), std::string::npos) << out;
  EXPECT_NE(out.find("x^^2\n    ^"), std::string::npos) << "caret under the error:\n" << out;
  EXPECT_NE(out.find("tracing.epsilon"), std::string::npos) << "range error names the key";
  EXPECT_GT(drawnPixels(png), 1000);

  // The scene kept every good change and none of the bad ones.
  SceneResult saved = loadScene(surf);
  ASSERT_TRUE(std::holds_alternative<Scene>(saved)) << out;
  const Scene& s = std::get<Scene>(saved);
  EXPECT_EQ(s.formula, "x^4 + y^4 + z^4 - a");
  ASSERT_EQ(s.params.size(), 1u);
  EXPECT_EQ(s.params[0].second, 0.5);
  EXPECT_EQ(s.render.tracing.epsilon, 0.01);
  EXPECT_EQ(s.render.camera.eye, (Vec3{1, 2, 4}));
}

TEST(Prompt, SaveLoadSaveRoundTripsEveryKey) {
  const auto dir = freshDir("roundtrip");
  Child c({ZS_ZEROSET_EXE}, headlessEnv(dir), Stdio::Pipe);
  const auto first = dir / "first.surf", second = dir / "second.surf";
  c.write(
      "sin(x*k) + y^2 + z^2 - 0.5\n"
      ":set params.k=2.5\n"
      ":set lights.point={position=[0.5, 3, 1], intensity=0.25, color=[1, 0.5, 0.5]}\n"
      ":set highlights.silhouette.enabled=false\n"
      ":set octree.criteria=\"uniform\"\n"
      ":save " +
      first.string() +
      "\n"
      "x^2 - 1\n"
      ":load " +
      first.string() +
      "\n"
      ":save " +
      second.string() + "\n");
  c.closeInput();
  c.readUntil("\x01", 120);  // everything, up to end of output
  EXPECT_EQ(c.wait(30), 0);
  const Scene a = std::get<Scene>(loadScene(first)), b = std::get<Scene>(loadScene(second));
  EXPECT_EQ(a, b) << c.output();
  EXPECT_EQ(readText(first), readText(second));
  EXPECT_EQ(a.render.lights.sources[1].intensity, 0.25);
  EXPECT_FALSE(a.render.silhouette.enabled);
  EXPECT_EQ(a.octree.criteria, Criteria::Uniform);
}

}  // namespace
}  // namespace zs::test
