// `zeroset print` as a user runs it, read back with poppler's tools: the text of the page
// (pdftotext) holds the title, the formula and the parameter values, and the picture in it
// (pdfimages) is `zeroset render`'s picture of the same scene, pixel for pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "print/page.hpp"
#include "process.hpp"
#include "viewer_session.hpp"

namespace zs::test {
namespace {

std::string quoted(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

TEST(Print, ThePageHoldsTheFormulaTheValuesAndThePictureOfRender) {
  const auto dir = freshDir("print");
  const std::string zeroset = ZS_ZEROSET_EXE;
  const std::string formula = "'x^2 + y^2 - z^2 - a' --set params.a=0.25";
  ASSERT_EQ(shell(zeroset + " print " + formula + " --dpi 40 --title 'One sheet' -o " +
                  quoted(dir / "page.pdf") + " > /dev/null"),
            0);
  // The picture: a square as wide as the text, at 40 dpi.
  const int side = int(std::lround(printing::pictureSide(printing::Paper::A4) / 72.0 * 40));
  ASSERT_EQ(shell(zeroset + " render " + formula + " --size " + std::to_string(side) + "x" +
                  std::to_string(side) + " -o " + quoted(dir / "render.png") + " > /dev/null"),
            0);

  ASSERT_EQ(shell("pdftotext -raw " + quoted(dir / "page.pdf") + " " + quoted(dir / "page.txt")),
            0);
  const std::string text = readText(dir / "page.txt");
  EXPECT_NE(text.find("One sheet"), std::string::npos) << text;
  // Typeset, not typed: x², and a real minus sign (pdftotext writes a superscript inline).
  EXPECT_NE(text.find("x2"), std::string::npos) << text;
  EXPECT_NE(text.find("\u2212 z2"), std::string::npos) << text;
  EXPECT_EQ(text.find("x^2"), std::string::npos) << text;
  EXPECT_NE(text.find("= 0"), std::string::npos) << text;
  EXPECT_NE(text.find("a = 0.25"), std::string::npos) << text;

  ASSERT_EQ(shell("pdfimages -png " + quoted(dir / "page.pdf") + " " + quoted(dir / "image")), 0);
  const Image printed = loadPng(dir / "image-000.png");
  const Image rendered = loadPng(dir / "render.png");
  ASSERT_EQ(printed.width, side);
  ASSERT_EQ(printed.height, side);
  ASSERT_EQ(rendered.width, side);
  int differing = 0;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const std::uint8_t* a = printed.pixel(x, y);
      const std::uint8_t* b = rendered.pixel(x, y);
      differing += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
    }
  }
  EXPECT_EQ(differing, 0) << "the page's picture is not render's";
}

// A scene of several surfaces: one equation per surface, in order, each at its level.
TEST(Print, SeveralSurfacesHaveAnEquationEach) {
  const auto dir = freshDir("print_surfaces");
  ASSERT_EQ(
      shell(std::string(ZS_ZEROSET_EXE) + " print 'x^2 + y^2 + z^2 - 1' --surface 'z' " +
            "--set surface.2.level=0.5 --dpi 30 -o " + quoted(dir / "page.pdf") + " > /dev/null"),
      0);
  ASSERT_EQ(shell("pdftotext -raw " + quoted(dir / "page.pdf") + " " + quoted(dir / "page.txt")),
            0);
  const std::string text = readText(dir / "page.txt");
  const auto sphere = text.find("− 1 = 0");
  const auto plane = text.find("z = 0.5");
  EXPECT_NE(sphere, std::string::npos) << text;
  EXPECT_NE(plane, std::string::npos) << text;
  EXPECT_LT(sphere, plane) << text;
}

TEST(Print, SvgPagesAndBadPapersAndExtensions) {
  const auto dir = freshDir("print-svg");
  const std::string zeroset = ZS_ZEROSET_EXE;
  ASSERT_EQ(shell(zeroset + " print 'x^4 + y^4 + z^4 - 1' --dpi 30 --paper letter -o " +
                  quoted(dir / "page.svg") + " > /dev/null"),
            0);
  const std::string svg = readText(dir / "page.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("612"), std::string::npos) << "letter is 612 points wide";
  EXPECT_NE(shell(zeroset + " print x -o " + quoted(dir / "p.pdf") + " --paper B5 2> " +
                  quoted(dir / "paper.err")),
            0);
  EXPECT_NE(readText(dir / "paper.err").find("hint: A4, A3 or letter"), std::string::npos);
  EXPECT_NE(
      shell(zeroset + " print x -o " + quoted(dir / "p.png") + " 2> " + quoted(dir / "ext.err")),
      0);
  EXPECT_NE(readText(dir / "ext.err").find(".pdf or .svg"), std::string::npos)
      << readText(dir / "ext.err");
}

}  // namespace
}  // namespace zs::test
