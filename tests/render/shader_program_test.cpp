// A shader the GL driver rejects gives a short message (which stage, the head of the
// driver's log) and a file with the whole log and the numbered source, never a thousand
// lines in the terminal (docs/codegen.md, "When a shader is rejected").
#include "render/shader_program.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "render_support.hpp"

namespace zs {
namespace {

const char* kVertex =
    "#version 330 core\n"
    "void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n";

// A fragment shader of many lines whose error is near the end, as a generated one's would be.
std::string longBrokenFragment() {
  std::string s = "#version 330 core\nout vec4 color;\n";
  for (int i = 0; i < 400; ++i) s += "float f" + std::to_string(i) + "(float x) { return x; }\n";
  s += "void main() { color = vec4(undeclared_name); }\n";
  return s;
}

std::string reportPath(const std::string& message) {
  const std::string marker = "The shader and the whole log: ";
  const std::size_t at = message.find(marker);
  if (at == std::string::npos) return {};
  std::string path = message.substr(at + marker.size());
  while (!path.empty() && (path.back() == '\n' || path.back() == ' ')) path.pop_back();
  return path;
}

TEST(ShaderProgram, ARejectedShaderGivesAFewLinesAndItsSourceInAFile) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  std::string log;
  EXPECT_EQ(compileProgram(kVertex, longBrokenFragment(), log), 0u);
  EXPECT_NE(log.find("fragment shader"), std::string::npos) << log;
  EXPECT_NE(log.find("internal error in zeroset"), std::string::npos) << log;
  EXPECT_LE(std::count(log.begin(), log.end(), '\n'), 20) << log;
  const std::string path = reportPath(log);
  ASSERT_FALSE(path.empty()) << log;
  std::ifstream in(path);
  std::stringstream whole;
  whole << in.rdbuf();
  EXPECT_NE(whole.str().find("undeclared_name"), std::string::npos);
  EXPECT_NE(whole.str().find("f399"), std::string::npos);  // the whole source, not its head
  std::remove(path.c_str());
}

TEST(ShaderProgram, AFailedLinkNamesTheLinkAndStaysShort) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  // Compiles on its own; the link fails because the prototype has no body.
  const std::string fragment =
      "#version 330 core\nout vec4 color;\nfloat missing(float x);\n"
      "void main() { color = vec4(missing(1.0)); }\n";
  std::string log;
  EXPECT_EQ(compileProgram(kVertex, fragment, log), 0u);
  EXPECT_NE(log.find("link"), std::string::npos) << log;
  EXPECT_LE(std::count(log.begin(), log.end(), '\n'), 20) << log;
  const std::string path = reportPath(log);
  ASSERT_FALSE(path.empty()) << log;
  std::remove(path.c_str());
}

}  // namespace
}  // namespace zs
