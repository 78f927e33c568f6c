#include "app/gallery.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "expr/degree.hpp"
#include "i18n/translate.hpp"
#include "parser/parser.hpp"
#include "scene/description.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

GalleryEntry describeExample(const Example& example) {
  GalleryEntry entry;
  entry.name = example.name;
  if (example.file.empty()) {
    entry.description = N_("Built in: thesis Table 5.1, with the thesis' best settings.");
  } else {
    std::ifstream in(example.file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    entry.description = sceneDescription(text.str());
    entry.summary = summaryLine(text.str());
    std::string stem = example.name;
    std::replace(stem.begin(), stem.end(), '/', '-');
    const std::filesystem::path root = example.name.find('/') == std::string::npos
                                           ? example.file.parent_path()
                                           : example.file.parent_path().parent_path();
    std::error_code ec;
    if (const auto picture = root / "images" / (stem + ".png");
        std::filesystem::is_regular_file(picture, ec))
      entry.picture = picture;
  }
  if (example.file.empty()) entry.summary = entry.description;
  auto loaded = loadExample(example);
  entry.degree = "?";
  if (const Scene* scene = std::get_if<Scene>(&loaded)) {
    ParseResult parsed = parseSceneFormula(*scene);
    if (const Formula* f = std::get_if<Formula>(&parsed)) {
      const auto degree = polynomialDegree(f->graph, f->root);
      entry.degree = degree ? std::to_string(*degree) : "-";
    }
  } else {
    entry.summary = N_("(does not load: run zeroset render on it to see why)");
  }
  return entry;
}

std::vector<GalleryEntry> describeExamples(const std::vector<Example>& examples) {
  std::vector<GalleryEntry> entries;
  entries.reserve(examples.size());
  for (const Example& e : examples) entries.push_back(describeExample(e));
  return entries;
}

bool galleryMatches(const GalleryEntry& entry, const std::string& needle) {
  const std::string n = lower(needle);
  // The summary as the panel shows it, in the viewer's language, too.
  return lower(entry.name).find(n) != std::string::npos ||
         lower(entry.description).find(n) != std::string::npos ||
         lower(i18n::tr(entry.summary)).find(n) != std::string::npos;
}

}  // namespace zs::app
