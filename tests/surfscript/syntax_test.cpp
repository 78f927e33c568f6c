// surf's script syntax: statements, precedence, comments, and the place of every error.
#include <gtest/gtest.h>

#include "surfscript/script_syntax.hpp"

namespace zs::surfscript {
namespace {

std::vector<Statement> parsed(const std::string& text) {
  auto r = parseScript(text);
  if (auto* e = std::get_if<ScriptError>(&r)) {
    ADD_FAILURE() << text << "\n" << e->place.line << ":" << e->place.column << " " << e->message;
    return {};
  }
  return std::get<std::vector<Statement>>(r);
}

ScriptError failed(const std::string& text) {
  auto r = parseScript(text);
  EXPECT_TRUE(std::holds_alternative<ScriptError>(r)) << text;
  if (auto* e = std::get_if<ScriptError>(&r)) return *e;
  return {};
}

// The tree as a fully parenthesized string.
std::string shape(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Number:
      return e.text;
    case Expr::Kind::Name:
      return e.text;
    case Expr::Kind::String:
      return "\"" + e.text + "\"";
    case Expr::Kind::Negate:
      return "(-" + shape(e.args[0]) + ")";
    case Expr::Kind::Binary:
      return "(" + shape(e.args[0]) + e.op + shape(e.args[1]) + ")";
    case Expr::Kind::Call: {
      std::string s = e.text + "(";
      for (std::size_t i = 0; i < e.args.size(); ++i) s += (i ? "," : "") + shape(e.args[i]);
      return s + ")";
    }
  }
  return {};
}

TEST(SurfSyntax, StatementsOfAGalleryScript) {
  const auto s = parsed(
      "width=120; // size\n"
      "double PI = 2*arcsin(1);\n"
      "/* several\n lines */ poly p;\n"
      "surface=rotate(surface,-1.44,yAxis);\n"
      "draw_surface;\n"
      "filename=\"/tmp/a.jpg\";");
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(s[0].kind, Statement::Kind::Assign);
  EXPECT_EQ(s[0].name, "width");
  EXPECT_EQ(s[1].kind, Statement::Kind::Declare);
  EXPECT_EQ(s[1].type, "double");
  EXPECT_EQ(shape(s[1].value), "(2*arcsin(1))");
  EXPECT_EQ(s[2].kind, Statement::Kind::Declare);
  EXPECT_FALSE(s[2].hasValue);
  EXPECT_EQ(s[2].place.line, 4);
  EXPECT_EQ(s[2].place.column, 11);
  EXPECT_EQ(shape(s[3].value), "rotate(surface,(-1.44),yAxis)");
  EXPECT_EQ(s[4].kind, Statement::Kind::Command);
  EXPECT_EQ(s[5].value.kind, Expr::Kind::String);
  EXPECT_EQ(s[5].value.text, "/tmp/a.jpg");
}

// surf's own: a sign binds tightest and ^ groups to the left (surf 1.0.6 draws
// -x^2-y^2-z^2+16 as a hyperboloid).
TEST(SurfSyntax, Precedence) {
  EXPECT_EQ(shape(parsed("s = -x^2;")[0].value), "((-x)^2)");
  EXPECT_EQ(shape(parsed("s = 2^-1;")[0].value), "(2^(-1))");
  EXPECT_EQ(shape(parsed("s = a-b-c;")[0].value), "((a-b)-c)");
  EXPECT_EQ(shape(parsed("s = a/b*c;")[0].value), "((a/b)*c)");
  EXPECT_EQ(shape(parsed("s = a^b^c;")[0].value), "((a^b)^c)");
  EXPECT_EQ(shape(parsed("s = 2*x^2+y*-3;")[0].value), "((2*(x^2))+(y*(-3)))");
  EXPECT_EQ(shape(parsed("s = -(x^2);")[0].value), "(-(x^2))");
  EXPECT_EQ(shape(parsed("s = (x+1)^2;")[0].value), "((x+1)^2)");
  EXPECT_EQ(shape(parsed("s = 1.5e-3 + .5;")[0].value), "(1.5e-3+.5)");
  EXPECT_TRUE(parsed("s = 12;")[0].value.integer);
  EXPECT_FALSE(parsed("s = 12.0;")[0].value.integer);
}

TEST(SurfSyntax, ErrorsNameTheirPlace) {
  ScriptError e = failed("width = 100\nheight = 50;");
  EXPECT_EQ(e.place.line, 1);
  EXPECT_EQ(e.place.column, 12) << "right after the value the ';' is missing from";
  EXPECT_NE(e.message.find("';'"), std::string::npos);

  e = failed("filename = \"a.jpg;\nsave_color_image;");
  EXPECT_EQ(e.place.line, 1);
  EXPECT_EQ(e.place.column, 12);
  EXPECT_NE(e.message.find("never closed"), std::string::npos);

  e = failed("x = 1;\n/* open");
  EXPECT_EQ(e.place.line, 2);
  EXPECT_NE(e.message.find("comment"), std::string::npos);

  e = failed("surface = x^2 + ;");
  EXPECT_EQ(e.place.column, 17);

  e = failed("surface = (x + 1;");
  EXPECT_NE(e.message.find("')'"), std::string::npos);

  e = failed("width = 3 $ 4;");
  EXPECT_EQ(e.place.column, 11);

  e = failed("surface = rotate(surface, 1 yAxis);");
  EXPECT_NE(e.message.find("rotate"), std::string::npos);

  e = failed("surface = x^2");
  EXPECT_EQ(e.place.column, 14);

  e = failed("= 3;");
  EXPECT_EQ(e.place.column, 1);
}

}  // namespace
}  // namespace zs::surfscript
