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

}  // namespace zs::app
