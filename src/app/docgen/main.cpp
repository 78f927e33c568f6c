// zeroset-docgen man SECTIONS.roff OUT | bash OUT | zsh OUT: writes the man page or a
// completion script for the zeroset command line to OUT (a build step; never installed).
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/cli.hpp"
#include "app/docgen/cli_doc.hpp"
#include "scene/scene_io.hpp"

int main(int argc, char** argv) {
  const std::string what = argc > 2 ? argv[1] : "";
  const std::string outPath = argv[argc - 1];
  CLI::App app;
  zs::app::addCommands(app);
  const zs::docgen::CliDoc doc = zs::docgen::describe(app);
  std::string text;
  if (what == "man" && argc == 4) {
    std::ifstream in(argv[2]);
    std::stringstream sections;
    sections << in.rdbuf();
    const std::string page = zs::docgen::manPage(doc, ZS_VERSION, sections.str());
    if (!in || page.empty()) {
      std::cerr << "zeroset-docgen: " << argv[2]
                << " must hold the line .\\\" @COMMANDS@ exactly once\n";
      return 1;
    }
    text = page;
  } else if (what == "bash" && argc == 3) {
    text = zs::docgen::bashCompletion(doc, zs::sceneKeys());
  } else if (what == "zsh" && argc == 3) {
    text = zs::docgen::zshCompletion(doc, zs::sceneKeys());
  } else {
    std::cerr << "usage: zeroset-docgen man SECTIONS.roff OUT | bash OUT | zsh OUT\n";
    return 2;
  }
  std::ofstream out(outPath, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::cerr << "zeroset-docgen: cannot write " << outPath << "\n";
    return 1;
  }
  return 0;
}
