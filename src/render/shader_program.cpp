#include "render/shader_program.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <vector>

#include "codegen/glsl_validation.hpp"

namespace zs {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(std::size_t(std::max(length, 1)), '\0');
  if (isProgram)
    glGetProgramInfoLog(object, length, nullptr, text.data());
  else
    glGetShaderInfoLog(object, length, nullptr, text.data());
  return std::string(text.data());
}

GLuint compileStage(GLenum stage, std::string_view source, std::string& log) {
  GLuint shader = glCreateShader(stage);
  const GLchar* text = source.data();
  const GLint length = GLint(source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  const bool vertex = stage == GL_VERTEX_SHADER;
  log += formatDriverShaderError(vertex ? "vertex shader" : "fragment shader",
                                 vertex ? Stage::Vertex : Stage::Fragment, infoLog(shader, false),
                                 source);
  glDeleteShader(shader);
  return 0;
}

}  // namespace

unsigned compileProgram(std::string_view vertex, std::string_view fragment, std::string& log) {
  log.clear();
  GLuint vs = compileStage(GL_VERTEX_SHADER, vertex, log);
  GLuint fs = compileStage(GL_FRAGMENT_SHADER, fragment, log);
  if (!vs || !fs) {
    if (vs) glDeleteShader(vs);
    if (fs) glDeleteShader(fs);
    return 0;
  }
  GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);  // flagged; freed with the program
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok == GL_TRUE) return program;
  log += formatDriverShaderError("shader program (the link of its two stages)", Stage::Fragment,
                                 infoLog(program, true), fragment);
  glDeleteProgram(program);
  return 0;
}

}  // namespace zs
