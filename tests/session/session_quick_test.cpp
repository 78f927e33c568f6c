// The session as the page holds it (GLSL ES), natively: the first picture by the tape interpreter
// (prepareQuick) beside prepare(), which it must leave alone.
#include <gtest/gtest.h>

#include "codegen/glsl_validation.hpp"
#include "session/session.hpp"

namespace zs::session {
namespace {

TEST(SessionQuick, FirstPictureComesWithoutTouchingThePreparedSurface) {
  Session s(SessionOptions{ShaderDialect::Es300, false});
  ASSERT_EQ(s.loadFormula("x^2+y^2+z^2-1"), "");
  ASSERT_EQ(s.prepare(), "");
  const int generation = s.generation();
  const std::string ownShader = s.fragmentShader();

  ASSERT_EQ(s.setFormula("x^4+y^4+z^4-a"), "");
  ASSERT_EQ(s.prepareQuick(), "");
  EXPECT_TRUE(s.quickPrepared());
  EXPECT_GT(s.quickTape().size(), 16u);
  EXPECT_GT(s.quickHierarchy().count, 0);
  EXPECT_GT(s.quickFrame(64, 48).vertices, 0);
  const ValidationResult es = validateGlsl(s.quickFragmentShader(), Stage::Fragment);
  EXPECT_TRUE(es.ok) << es.log;
  // The surface on screen is still the sphere's until prepare().
  EXPECT_EQ(s.generation(), generation);
  EXPECT_EQ(s.fragmentShader(), ownShader);

  // One interpreter shader serves every polynomial: the page compiles it once.
  const std::string interpreter = s.quickFragmentShader();
  ASSERT_EQ(s.setFormula("x*y*z-0.1"), "");
  ASSERT_EQ(s.prepareQuick(), "");
  EXPECT_EQ(s.quickFragmentShader(), interpreter);
  // ... and it is one of those the page compiles ahead of typing.
  const std::vector<std::string> ahead = s.interpreterShaders();
  ASSERT_EQ(ahead.size(), 2u);
  EXPECT_EQ(ahead[0], interpreter);
}

TEST(SessionQuick, SaysWhyWhenItCannotInterpret) {
  Session s(SessionOptions{ShaderDialect::Es300, false});
  ASSERT_EQ(s.loadFormula("x^2+y^2+z^2-1"), "");
  ASSERT_EQ(s.applyOverrides(std::vector<std::string>{"shading.color=\"gauss\""}), "");
  EXPECT_NE(s.prepareQuick(), "");
  EXPECT_FALSE(s.quickPrepared());
}

}  // namespace
}  // namespace zs::session
