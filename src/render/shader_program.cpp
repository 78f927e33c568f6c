#include "render/shader_program.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace zs {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(std::size_t(std::max(length, 1)), '\0');
  if (isProgram) glGetProgramInfoLog(object, length, nullptr, text.data());
  else glGetShaderInfoLog(object, length, nullptr, text.data());
  return std::string(text.data());
}

GLuint compileStage(GLenum stage, std::string_view source, const char* name, std::string& log) {
  GLuint shader = glCreateShader(stage);
  const GLchar* text = source.data();
  const GLint length = GLint(source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  log += std::string(name) + " shader failed to compile (driver log):\n" +
         infoLog(shader, false) + "\n--- " + name + " shader source ---\n" +
         numberedSource(source);
  glDeleteShader(shader);
  return 0;
}

}  // namespace

std::string numberedSource(std::string_view source) {
  std::string out;
  int line = 1;
  std::size_t start = 0;
  while (start <= source.size()) {
    std::size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    char prefix[16];
    std::snprintf(prefix, sizeof prefix, "%5d| ", line++);
    out += prefix;
    const std::string_view text = source.substr(start, end - start);
    out.append(text);
    out += '\n';
    // "#line N [S]": the next line is line N, as the compiler's log counts it.
    if (text.rfind("#line ", 0) == 0) line = std::atoi(std::string(text.substr(6)).c_str());
    if (end == source.size()) break;
    start = end + 1;
  }
  return out;
}

unsigned compileProgram(std::string_view vertex, std::string_view fragment, std::string& log) {
  log.clear();
  GLuint vs = compileStage(GL_VERTEX_SHADER, vertex, "vertex", log);
  GLuint fs = compileStage(GL_FRAGMENT_SHADER, fragment, "fragment", log);
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
  log += "shader program failed to link (driver log):\n" + infoLog(program, true) +
         "\n--- fragment shader source ---\n" + numberedSource(fragment);
  glDeleteProgram(program);
  return 0;
}

}  // namespace zs
