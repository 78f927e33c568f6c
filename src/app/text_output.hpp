#pragma once
// Writing a command's report to a file: takes a path and the text, writes it as is and
// says on stderr when it cannot (`error: cannot write PATH`), so every command reports a
// failed write the same way.
#include <filesystem>
#include <string>

namespace zs::app {

bool writeTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace zs::app
