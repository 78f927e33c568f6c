// Running surf scripts: surf's defaults, types and conversions, and the place and hint of
// every error a user can make.
#include <gtest/gtest.h>

#include <cmath>

#include "expr/tape.hpp"
#include "parser/parser.hpp"
#include "surfscript/script_run.hpp"

namespace zs::surfscript {
namespace {

ScriptRun ran(const std::string& text) {
  auto r = runScript(text);
  if (auto* e = std::get_if<ScriptError>(&r)) {
    ADD_FAILURE() << text << "\n" << e->place.line << ":" << e->place.column << ": " << e->message;
    return {};
  }
  return std::get<ScriptRun>(std::move(r));
}

ScriptError failed(const std::string& text) {
  auto r = runScript(text);
  EXPECT_TRUE(std::holds_alternative<ScriptError>(r)) << text;
  if (auto* e = std::get_if<ScriptError>(&r)) return *e;
  return {};
}

double at(const Poly& p, double x, double y, double z) {
  const auto parsed = parseFormula(p.formula());
  if (!std::holds_alternative<Formula>(parsed)) {
    ADD_FAILURE() << p.formula();
    return NAN;
  }
  const Formula& f = std::get<Formula>(parsed);
  return PointEvaluator(compileTape(f.graph, {f.root})).eval1(x, y, z);
}

TEST(SurfRun, DefaultsAreSurfs) {
  const ScriptRun r = ran("surface = x^2 + y^2 + z^2 - 25; draw_surface;");
  ASSERT_EQ(r.screen.size(), 1u);
  const Globals& g = r.screen[0].globals;
  EXPECT_EQ(g.integer("width"), 200);
  EXPECT_EQ(g.number("radius"), 10);
  EXPECT_EQ(g.number("spec_z"), 25);
  EXPECT_EQ(g.integer("illumination"), 7);
  EXPECT_EQ(g.integer("light1_vol"), 50);
  EXPECT_EQ(g.integer("light2_vol"), 0);
  EXPECT_EQ(g.integer("color_file_format"), 1) << "sun";
  ASSERT_NE(g.poly("surface"), nullptr);
  EXPECT_EQ(g.poly("surface")->degree(), 2);
  EXPECT_EQ(g.poly("surface2"), nullptr);
}

TEST(SurfRun, NumbersFollowSurfsRules) {
  const ScriptRun r =
      ran("double PI = 2*arcsin(1); double h = 1/2; int n = 2^3; double p = pow(2.0, 0.5);"
          "width = 100.0; illumination = ambient_light + diffuse_light;"
          "surface = PI*x + h*y + n*z + p; draw_surface;");
  const Globals& g = r.screen.back().globals;
  EXPECT_EQ(g.integer("width"), 100) << "a whole number with a point is taken for an integer";
  EXPECT_EQ(g.integer("illumination"), 3);
  const Poly& s = *g.poly("surface");
  EXPECT_NEAR(at(s, 1, 0, 0) - at(s, 0, 0, 0), M_PI, 1e-15);
  EXPECT_NEAR(at(s, 0, 1, 0) - at(s, 0, 0, 0), 0.5, 1e-15);
  EXPECT_NEAR(at(s, 0, 0, 1) - at(s, 0, 0, 0), 8, 1e-15);
  EXPECT_NEAR(at(s, 0, 0, 0), std::sqrt(2.0), 1e-15);
}

TEST(SurfRun, RotateTurnsAsSurfDoes) {
  // surf's polyarith.cc: about z, p(c x + s y, -s x + c y, z).
  const ScriptRun r =
      ran("poly f = x; surface = rotate(f, 0.5, zAxis); surface2 = rotate(f, 0.5, yAxis);"
          "surface3 = rotate(y, 0.5, xAxis); draw_surface;");
  const Globals& g = r.screen.back().globals;
  const double c = std::cos(0.5), s = std::sin(0.5);
  EXPECT_NEAR(at(*g.poly("surface"), 0.3, 0.7, 0.1), c * 0.3 + s * 0.7, 1e-15);
  EXPECT_NEAR(at(*g.poly("surface2"), 0.3, 0.7, 0.1), c * 0.3 + s * 0.1, 1e-15);
  EXPECT_NEAR(at(*g.poly("surface3"), 0.3, 0.7, 0.1), c * 0.7 + s * 0.1, 1e-15);
  EXPECT_EQ(g.poly("surface")->written().formula(), "x") << "the turn is kept aside";
}

TEST(SurfRun, CommandsLeaveDrawingsAndPictures) {
  const ScriptRun r = ran(
      "surface = x^2 + y^2 - z; draw_surface; filename = \"a.jpg\"; color_file_format = jpg;"
      "save_color_image; clear_screen; width = 50; surface = z; draw_surface;"
      "filename = \"b\" + itostrn(3, 7) + \".ppm\"; color_file_format = ppm; save_color_image;");
  ASSERT_EQ(r.saved.size(), 2u);
  EXPECT_EQ(r.saved[0].fileName, "a.jpg");
  EXPECT_EQ(r.saved[0].format, ImageFormat::Jpeg);
  EXPECT_EQ(r.saved[0].screen.size(), 1u);
  EXPECT_EQ(r.saved[1].fileName, "b007.ppm");
  EXPECT_EQ(r.saved[1].format, ImageFormat::Ppm);
  EXPECT_EQ(r.saved[1].width, 50);
  EXPECT_EQ(r.saved[1].screen.size(), 1u) << "clear_screen emptied the screen";
}

TEST(SurfRun, WhatZerosetDoesDifferentlyIsANote) {
  const ScriptRun r =
      ran("surface = -x^2 + y; cut_with_plane;\n double t = arcsin(0.5); draw_surface;");
  ASSERT_EQ(r.notes.size(), 3u);
  EXPECT_NE(r.notes[0].message.find("(-x)^2"), std::string::npos);
  EXPECT_NE(r.notes[1].message.find("cut_with_plane"), std::string::npos);
  EXPECT_NE(r.notes[2].message.find("arcsin"), std::string::npos);
  EXPECT_EQ(r.notes[2].place.line, 2);
}

struct BadScript {
  const char* text;
  int line, column;
  const char* message;  // a part of it
  const char* hint;     // a part of it
};

TEST(SurfRun, EveryErrorNamesItsPlaceAndAFix) {
  const BadScript cases[] = {
      {"widht = 100;", 1, 1, "unknown variable 'widht'", "did you mean width?"},
      {"surface = x^2;\ndraw_surfce;", 2, 1, "unknown command 'draw_surfce'",
       "did you mean draw_surface?"},
      {"width = x^2;", 1, 9, "width is an integer; this is a polynomial", ""},
      {"width = 100.5;", 1, 9, "width is an integer", "round it"},
      {"radius = \"big\";", 1, 10, "radius is a number; this is a string", ""},
      {"surface = x / (y + 1);", 1, 16, "divides a polynomial by numbers only", ""},
      {"surface = x / 0;", 1, 13, "division by zero", ""},
      {"double a = 1 / (2 - 2);", 1, 14, "division by zero", ""},
      {"surface = x^2.0;", 1, 13, "exponent is a whole number", "x^2"},
      {"surface = sqrt(x);", 1, 16, "sqrt takes a number", "not to polynomials"},
      {"surface = foo(x);", 1, 11, "unknown function 'foo'", ""},
      {"surface = rotate(x, 1, wAxis);", 1, 24, "xAxis, yAxis or zAxis", ""},
      {"surface = rotate(x, 1);", 1, 11, "rotate takes 3 arguments", "rotate(POLY, ANGLE"},
      {"surface = x + b;", 1, 15, "unknown name 'b'", "double b"},
      {"double a = 1; double a = 2;", 1, 22, "declared twice", ""},
      {"double width = 3;", 1, 8, "one of surf's own names", ""},
      {"poly p; surface = p;", 1, 19, "has no polynomial yet", ""},
      {"save_color_image;", 1, 1, "needs a file name", "filename"},
      {"filename = \"a.ps\"; color_file_format = postscript_color; save_color_image;", 1, 58,
       "not color_file_format 4", "jpg"},
      {"filename = \"|lpr\"; save_color_image;", 1, 20, "pipe", ""},
      {"surface = diff(x^2, x);", 1, 11, "diff", "write the polynomial"},
      {"double d = sqrt(-1);", 1, 12, "is not a number", ""},
  };
  for (const BadScript& c : cases) {
    const ScriptError e = failed(c.text);
    EXPECT_EQ(e.place.line, c.line) << c.text;
    EXPECT_EQ(e.place.column, c.column) << c.text << ": " << e.message;
    EXPECT_NE(e.message.find(c.message), std::string::npos) << c.text << ": " << e.message;
    EXPECT_NE(e.hint.find(c.hint), std::string::npos) << c.text << ": " << e.hint;
  }
}

}  // namespace
}  // namespace zs::surfscript
