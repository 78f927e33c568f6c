#include "app/text_output.hpp"

#include <fstream>
#include <iostream>

namespace zs::app {

bool writeTextFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  if (file) return true;
  std::cerr << "error: cannot write " << path.string() << "\n";
  return false;
}

std::filesystem::path surfacePath(const std::filesystem::path& path, std::size_t i,
                                  std::size_t count) {
  if (count <= 1) return path;
  std::filesystem::path numbered = path;
  numbered.replace_filename(path.stem().string() + "-" + std::to_string(i + 1) +
                            path.extension().string());
  return numbered;
}

}  // namespace zs::app
