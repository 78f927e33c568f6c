// Both headless backends give a core context with glad loaded, and the ray tracer reports
// bad shaders and bad hierarchies as errors with logs instead of crashing.
#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "codegen/shader_assembly.hpp"
#include "render_support.hpp"

namespace zs {
namespace {

class ContextTest : public ::testing::TestWithParam<Backend> {};

TEST_P(ContextTest, CoreContextWithLoadedEntryPoints) {
  std::string error;
  GlContext* ctx = test::context(GetParam(), error);
  ASSERT_NE(ctx, nullptr) << error;
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 33) << GlContext::describeCurrent();
  // The profile bit, not GL_VERSION's text: NVIDIA's says "3.3.0 NVIDIA …", no "Core".
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << GlContext::describeCurrent();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(ContextTest, CompileErrorsComeBackWithDriverLogAndNumberedSource) {
  std::string error;
  ASSERT_NE(test::context(GetParam(), error), nullptr) << error;
  RayTracer tracer;
  std::string log;
  const std::string broken =
      "#version 330 core\nout vec4 c;\nvoid main() {\n  c = vec4(1.0) +;\n}\n";
  EXPECT_FALSE(tracer.build(vertexShaderSource(), broken, RenderSettings{}, log));
  EXPECT_FALSE(tracer.ready());
  // A few lines naming the stage; the numbered source goes to the file they name.
  EXPECT_NE(log.find("GL driver rejected the fragment shader"), std::string::npos) << log;
  const std::string marker = "The shader and the whole log: ";
  const std::size_t at = log.find(marker);
  ASSERT_NE(at, std::string::npos) << log;
  std::string path = log.substr(at + marker.size());
  path.erase(path.find_last_not_of("\n ") + 1);
  std::ifstream in(path);
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("c = vec4(1.0) +;"), std::string::npos) << report;
  std::remove(path.c_str());
  Frame frame = tracer.render(RenderSettings{}, Domain{}, 8, 8);
  EXPECT_NE(frame.error, "");  // no program: an error, not a crash
}

TEST_P(ContextTest, RejectedInputLeavesTheTracerUsable) {
  std::string error;
  ASSERT_NE(test::context(GetParam(), error), nullptr) << error;
  auto tracer = test::makeTracer({"x^2+y^2+z^2-1"}, error);
  ASSERT_NE(tracer, nullptr) << error;
  const std::vector<float> bad(13, 0.0f);
  EXPECT_NE(tracer->setHierarchy(bad), "");
  EXPECT_NE(tracer->render(test::testSettings(), Domain{}, 0, 10).error, "");
  EXPECT_NE(tracer->render(test::testSettings(), Domain{}, 100000, 10).error, "");
  Frame frame = tracer->render(test::testSettings(), Domain{}, 16, 16);
  ASSERT_EQ(frame.error, "");
  EXPECT_GT(1.0 - test::fractionNear(frame.color, {1, 1, 1}), 0.2);  // the sphere is there
}

INSTANTIATE_TEST_SUITE_P(Backends, ContextTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         [](const auto& info) {
                           return info.param == Backend::Egl ? "Egl" : "OsMesa";
                         });

}  // namespace
}  // namespace zs
