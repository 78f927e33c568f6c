#include "codegen/glsl_validation.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>

namespace zs {
namespace {

void initializeGlslangOnce() {
  static std::once_flag once;
  // Never finalized: glslang's process state lives as long as the program.
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage toGlslang(Stage stage) {
  switch (stage) {
    case Stage::Vertex:
      return EShLangVertex;
    case Stage::Fragment:
      return EShLangFragment;
  }
  return EShLangFragment;
}

// Parses "#line L" or "#line L S" (after optional blanks); false for anything else.
bool parseLineDirective(std::string_view line, long& number, long& string) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string_view::npos || line[i] != '#') return false;
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string_view::npos || line.substr(i, 4) != "line") return false;
  const std::string rest(line.substr(i + 4));
  char* end = nullptr;
  const long l = std::strtol(rest.c_str(), &end, 10);
  if (end == rest.c_str()) return false;
  char* end2 = nullptr;
  const long s = std::strtol(end, &end2, 10);
  number = l;
  if (end2 != end) string = s;
  return true;
}

}  // namespace

std::string numberSourceLines(std::string_view source) {
  std::string out;
  long line = 1, string = 0;
  std::size_t pos = 0;
  while (pos < source.size()) {
    std::size_t end = source.find('\n', pos);
    if (end == std::string_view::npos) end = source.size();
    const std::string_view text = source.substr(pos, end - pos);
    out += std::to_string(string) + ":" + std::to_string(line) + " | ";
    out.append(text);
    out += '\n';
    long newLine = 0, newString = string;
    if (parseLineDirective(text, newLine, newString)) {
      line = newLine;
      string = newString;
    } else {
      ++line;
    }
    pos = end + 1;
  }
  return out;
}

ValidationResult validateGlsl(std::string_view source, Stage stage) {
  initializeGlslangOnce();
  ValidationResult result;
  result.numberedSource = numberSourceLines(source);

  // No setEnv* calls: with an OpenGL client glslang applies SPIR-V-for-GL rules and rejects
  // valid desktop GLSL. Cascading errors: report all of them.
  const EShLanguage language = toGlslang(stage);
  glslang::TShader shader(language);
  const char* text = source.data();
  const int length = static_cast<int>(source.size());
  // Without names, so the log says "S:L" with the string number that #line sets.
  shader.setStringsWithLengths(&text, &length, 1);
  const auto messages = static_cast<EShMessages>(EShMsgDefault | EShMsgCascadingErrors);
  const bool compiled = shader.parse(GetDefaultResources(), 330, false, messages);
  result.log = shader.getInfoLog();
  if (!compiled) return result;

  // A single-stage link catches what compilation alone does not, e.g. a prototype whose
  // body never got spliced in, or a missing main().
  glslang::TProgram program;
  program.addShader(&shader);
  const bool linked = program.link(messages);
  result.log += program.getInfoLog();
  result.ok = linked;
  return result;
}

namespace {

// The first `lines` lines of `log`, and how many were left out.
std::string head(std::string_view log, int lines) {
  std::size_t end = 0;
  for (int i = 0; i < lines && end < log.size(); ++i) {
    const std::size_t nl = log.find('\n', end);
    end = nl == std::string_view::npos ? log.size() : nl + 1;
  }
  std::string s(log.substr(0, end));
  if (!s.empty() && s.back() != '\n') s += '\n';
  if (end < log.size()) {
    int more = 0;
    for (std::size_t i = end; i < log.size(); ++i) more += log[i] == '\n';
    s += "... (" + std::to_string(std::max(more, 1)) + " more lines in the file below)\n";
  }
  return s;
}

// A shader that zeroset got wrong runs to a thousand lines: the whole report goes to a file
// in the temporary folder, and the message names it. Where no file can be written, the
// report is the message.
std::string withReportFile(std::string message, const std::string& report) {
  static std::atomic<int> counter{0};
  std::error_code ec;
  const std::filesystem::path path = std::filesystem::temp_directory_path(ec) /
                                     ("zeroset-internal-error-" + std::to_string(::getpid()) + "-" +
                                      std::to_string(++counter) + ".txt");
  std::ofstream out(path);
  if (!ec && out && (out << message << report) && (out.flush(), out)) {
    return message + "The shader and the whole log: " + path.string() + "\n";
  }
  return message + report;
}

}  // namespace

std::string formatInternalShaderError(std::string_view what, const ValidationResult& result) {
  std::string s = "internal error in zeroset: the generated ";
  s.append(what);
  s += " was rejected by glslang.\n"
       "This is a bug in zeroset's shader code generator, not a problem with your input; "
       "please report it with the file named below.\n--- glslang log ---\n";
  std::string report = "--- glslang log ---\n" + result.log;
  if (report.back() != '\n') report += '\n';
  report += "--- shader source (string:line as in the log) ---\n" + result.numberedSource;
  return withReportFile(s + head(result.log, 12), report);
}

std::string formatDriverShaderError(std::string_view what, Stage stage, std::string_view driverLog,
                                    std::string_view source) {
  const ValidationResult glslang = validateGlsl(source, stage);
  std::string s = "internal error in zeroset: the GL driver rejected the ";
  s.append(what);
  s += glslang.ok ? ", which glslang accepted.\n" : ", which glslang rejects too.\n";
  s += "--- driver log ---\n" + head(driverLog, 12);
  std::string report = "--- driver log ---\n" + std::string(driverLog);
  if (report.back() != '\n') report += '\n';
  report += "--- glslang log ---\n" + glslang.log;
  if (report.back() != '\n') report += '\n';
  report += "--- shader source (string:line as in the logs) ---\n" + glslang.numberedSource;
  return withReportFile(s, report);
}

}  // namespace zs
