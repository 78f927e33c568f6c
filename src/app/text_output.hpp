#pragma once
// Writing a command's report to a file: takes a path and the text, writes it as is and
// says on stderr when it cannot (`error: cannot write PATH`), so every command reports a
// failed write the same way.
#include <cstddef>
#include <filesystem>
#include <string>

namespace zs::app {

bool writeTextFile(const std::filesystem::path& path, const std::string& text);

// Where a command writes surface i (0-based) of `count`: `path` itself for one surface,
// else its stem numbered from 1 (poster.stl -> poster-2.stl).
std::filesystem::path surfacePath(const std::filesystem::path& path, std::size_t i,
                                  std::size_t count);

}  // namespace zs::app
