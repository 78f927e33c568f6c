#pragma once
// The gallery: the example surfaces (viewer/examples.hpp) with what a person picks by —
// name, degree and the one line of the file's description comment (examples/README.md). Used by
// `zeroset gallery` and the viewer's gallery panel. A file without a description, or one
// that does not load, is still listed (its summary says so).
#include <filesystem>
#include <string>
#include <vector>

#include "app/viewer/examples.hpp"

namespace zs::app {

struct GalleryEntry {
  std::string name;
  std::string degree;       // "6"; "-" when F is not a polynomial; "?" when it does not load
  std::string summary;      // the description's one line (scene/description.hpp); "" if none
  std::string description;  // the whole comment block
  // examples/images/NAME.png (thesis/N-x: thesis-N-x.png), the gallery's picture of it;
  // empty when there is none.
  std::filesystem::path picture;
};

GalleryEntry describeExample(const Example& example);
std::vector<GalleryEntry> describeExamples(const std::vector<Example>& examples);

// Case-insensitive: does `needle` occur in the entry's name, description, or its summary in
// the current language? (ASCII letters only are folded.)
bool galleryMatches(const GalleryEntry& entry, const std::string& needle);

}  // namespace zs::app
