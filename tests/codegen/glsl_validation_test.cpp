// glslang validation: accepts valid desktop GLSL (no SPIR-V rules), rejects and reports
// invalid GLSL, links (missing bodies), and numbers source lines as #line sets them.
#include "codegen/glsl_validation.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace zs {
namespace {

// The text of the report file an internal error message names on its last line.
std::string reportText(const std::string& message) {
  const std::string marker = "The shader and the whole log: ";
  const std::size_t at = message.find(marker);
  if (at == std::string::npos) return {};
  std::string path = message.substr(at + marker.size());
  path.erase(path.find_last_not_of('\n') + 1);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(GlslValidation, AcceptsPlainUniformsWithoutLayouts) {
  // With an OpenGL client set, glslang would demand layout(location) here.
  const ValidationResult r = validateGlsl(
      "#version 330 core\nuniform float k[3];\nout vec4 c;\nvoid main() { c = vec4(k[1]); }\n",
      Stage::Fragment);
  EXPECT_TRUE(r.ok) << r.log;
}

TEST(GlslValidation, ReportsEveryErrorWithItsLine) {
  const ValidationResult r = validateGlsl(
      "#version 330 core\nout vec4 c;\nvoid main() {\n  c = vec4(a);\n  c = vec4(b);\n}\n",
      Stage::Fragment);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.log.find("0:4:"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("0:5:"), std::string::npos) << "cascading errors\n" << r.log;
}

TEST(GlslValidation, LinkingCatchesAPrototypeWithoutBody) {
  const ValidationResult r = validateGlsl(
      "#version 330 core\nfloat f(float);\nout vec4 c;\nvoid main() { c = vec4(f(1.0)); }\n",
      Stage::Fragment);
  EXPECT_FALSE(r.ok) << r.log;
}

TEST(GlslValidation, VertexStage) {
  EXPECT_TRUE(
      validateGlsl("#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n", Stage::Vertex)
          .ok);
  EXPECT_FALSE(
      validateGlsl("#version 330 core\nvoid main() { gl_FragDepth = 0.0; }\n", Stage::Vertex).ok);
}

TEST(GlslValidation, NumbersLinesFollowingLineDirectives) {
  const std::string numbered =
      numberSourceLines("#version 330 core\n// a\n#line 1 1\nb\nc\n#line 7 2\nd\n");
  EXPECT_EQ(numbered,
            "0:1 | #version 330 core\n0:2 | // a\n0:3 | #line 1 1\n1:1 | b\n1:2 | c\n"
            "1:3 | #line 7 2\n2:7 | d\n");
}

TEST(GlslValidation, InternalErrorSaysItIsABugAndShowsEverything) {
  const ValidationResult r =
      validateGlsl("#version 330 core\nvoid main() { oops; }\n", Stage::Fragment);
  ASSERT_FALSE(r.ok);
  const std::string message = formatInternalShaderError("fragment shader for x", r);
  EXPECT_NE(message.find("internal error in zeroset"), std::string::npos);
  EXPECT_NE(message.find("bug"), std::string::npos);
  EXPECT_NE(message.find(r.log), std::string::npos);
  // The source goes to a file the message names, not into the terminal.
  EXPECT_EQ(message.find("0:2 | void main() { oops; }"), std::string::npos) << message;
  EXPECT_NE(reportText(message).find("0:2 | void main() { oops; }"), std::string::npos) << message;
}

TEST(GlslValidation, DriverErrorShowsDriverAndGlslangLogs) {
  const std::string message = formatDriverShaderError(
      "fragment shader", Stage::Fragment, "0:1(1): error: too many uniforms",
      "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
  EXPECT_NE(message.find("which glslang accepted"), std::string::npos) << message;
  EXPECT_NE(message.find("0:1(1): error: too many uniforms"), std::string::npos);
  EXPECT_NE(reportText(message).find("0:3 | void main()"), std::string::npos) << message;
}

}  // namespace
}  // namespace zs
