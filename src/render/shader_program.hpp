#pragma once
// Compiles and links a vertex + fragment shader pair on the current GL context. Takes the
// two source texts, puts out a program id or a log: the driver's message plus the failing
// source with line numbers, so an error like "0:212(35): ..." can be read in place.
#include <string>
#include <string_view>

namespace zs {

// 0 on failure, with `log` filled. Requires a current context with glad loaded.
unsigned compileProgram(std::string_view vertex, std::string_view fragment, std::string& log);

// "   1| line" for every line, restarting where a "#line N" directive says, as the
// compiler counts: what a shader error is read against.
std::string numberedSource(std::string_view source);

}  // namespace zs
