#pragma once
// Compiles and links a vertex + fragment shader pair on the current GL context. Takes the
// two source texts, puts out a program id or a short message: which stage failed and the
// head of the driver's log, with the whole log and the numbered source in a file whose
// path the message names (zeroset's shaders run to a thousand lines; a terminal is no place
// for them).
#include <string>
#include <string_view>

namespace zs {

// 0 on failure, with `log` filled. Requires a current context with glad loaded.
unsigned compileProgram(std::string_view vertex, std::string_view fragment, std::string& log);

}  // namespace zs
