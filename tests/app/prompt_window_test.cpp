// The prompt with a display (run under xvfb-run): lines piped into `zeroset` replace the
// surface in the window, and :png / :save see what the window shows.
#include <gtest/gtest.h>

#include <variant>

#include "process.hpp"
#include "render/image.hpp"
#include "scene/scene_io.hpp"

namespace zs::test {
namespace {

TEST(PromptWindow, PipedLinesDriveTheWindow) {
  const auto dir = freshDir("prompt-window");
  Child c({ZS_ZEROSET_EXE}, {{"HOME", dir.string()}, {"ZS_OUTPUT_DIR", dir.string()}}, Stdio::Pipe);
  const auto png = dir / "torus.png", surf = dir / "torus.surf";
  c.write(
      "(x^2 + y^2 + z^2 + 0.6^2 - 0.25^2)^2 - 4*0.6^2*(x^2 + y^2)\n"
      ":set camera.eye=[0, 3, 2.5]\n"
      ":png " +
      png.string() +
      "\n"
      ":save " +
      surf.string() +
      "\n"
      "x^^2\n"
      ":quit\n");
  c.readUntil("\x01", 120);  // everything, up to end of output
  EXPECT_EQ(c.wait(30), 0);
  const std::string& out = c.output();
  EXPECT_EQ(out.find("note: no window"), std::string::npos) << "the window opened:\n" << out;
  EXPECT_EQ(out.find("wrote "), std::string::npos) << "a window, not PNG files, shows formulas";
  EXPECT_NE(out.find("screenshot: " + png.string()), std::string::npos) << out;
  EXPECT_NE(out.find("saved: " + surf.string()), std::string::npos) << out;
  EXPECT_NE(out.find("^"), std::string::npos) << "the typo's caret";

  Image image;
  ASSERT_EQ(readPng(png.string(), image), "");
  EXPECT_EQ(image.width, 800);
  SceneResult saved = loadScene(surf);
  ASSERT_TRUE(std::holds_alternative<Scene>(saved)) << out;
  EXPECT_EQ(std::get<Scene>(saved).render.camera.eye, (Vec3{0, 3, 2.5}));
  EXPECT_NE(std::get<Scene>(saved).formula.find("4*0.6^2"), std::string::npos);
}

}  // namespace
}  // namespace zs::test

namespace zs::test {
namespace {

// The prompt on a terminal next to the window: libedit reads on its own thread while the
// window runs on the main thread. Closing the window ends the prompt too.
TEST(PromptWindow, TerminalPromptBesideTheWindowEndsWithIt) {
  const auto dir = freshDir("prompt-window-pty");
  Child c({ZS_ZEROSET_EXE}, {{"HOME", dir.string()}, {"ZS_OUTPUT_DIR", dir.string()}}, Stdio::Pty);
  ASSERT_TRUE(c.readUntil("F(x,y,z) = ", 30)) << c.output();
  const auto png = dir / "saddle.png";
  c.write("x^4 - z^4 - y\r:png " + png.string() + "\r");
  ASSERT_TRUE(c.readUntil("screenshot: ", 60)) << c.output();
  Image image;
  EXPECT_EQ(readPng(png.string(), image), "");

  // Ctrl+Q in the window while the prompt waits for a line.
  const auto idFile = dir / "window.id";
  shell("xdotool search --sync --onlyvisible --pid " + std::to_string(c.pid()) + " > " +
        idFile.string());
  std::string window = readText(idFile);
  window = window.substr(0, window.find('\n'));
  ASSERT_FALSE(window.empty());
  shell("xdotool windowfocus --sync " + window + " mousemove --window " + window +
        " 600 300 key ctrl+q");
  EXPECT_EQ(c.wait(30), 0) << c.output();
}

}  // namespace
}  // namespace zs::test
