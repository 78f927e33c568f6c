// `zeroset gallery`: the example surfaces, one per line — name, degree, the one line of the
// file's description — in the order the viewer's next/previous keys visit them.
#include <algorithm>
#include <iostream>

#include "app/commands.hpp"
#include "app/gallery.hpp"
#include "scene/description.hpp"

namespace zs::app {
namespace {

int runGallery(const std::string& search) {
  const std::filesystem::path dir = findExamplesDir();
  const std::vector<GalleryEntry> entries = describeExamples(listExamples(dir));
  std::size_t nameWidth = 4;
  for (const GalleryEntry& e : entries) nameWidth = std::max(nameWidth, e.name.size());
  std::cout << "name" << std::string(nameWidth - 4 + 2, ' ') << "degree  description\n";
  int shown = 0;
  for (const GalleryEntry& e : entries) {
    if (!search.empty() && !galleryMatches(e, search)) continue;
    std::cout << e.name << std::string(nameWidth - e.name.size() + 2, ' ') << e.degree
              << std::string(e.degree.size() < 8 ? 8 - e.degree.size() : 1, ' ')
              << (e.summary.empty() ? "(no description)" : shortened(e.summary, 100)) << "\n";
    ++shown;
  }
  if (dir.empty()) std::cout << "(no examples folder found: these are the built-in surfaces)\n";
  if (shown == 0) {
    std::cerr << "no example matches \"" << search << "\"\n";
    return 1;
  }
  return 0;
}

}  // namespace

void addGalleryCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("gallery", "List the example surfaces: name, degree, description");
  auto search = std::make_shared<std::string>();
  cmd->add_option("search", *search,
                  "show only examples whose name or description holds this text");
  cmd->callback([search] { std::exit(runGallery(*search)); });
}

}  // namespace zs::app
