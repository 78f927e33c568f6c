#pragma once
// The example surfaces the viewer's next/previous keys cycle through: takes the source tree
// (or the executable's location) and puts out examples/thesis/*.surf followed by
// examples/*.surf, each sorted by name; when no such file exists, the seven surfaces of the
// thesis' Table 5.1 built in, with the thesis' best settings (octree level 1, 10 intervals,
// epsilon 0.01).
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "scene/scene.hpp"

namespace zs::app {

struct Example {
  std::string name;            // file stem, or the thesis' name of a built-in surface
  std::filesystem::path file;  // empty for a built-in
  std::string formula;         // built-ins only
};

// The examples/ folder: $ZS_SOURCE_DIR/examples, the installed gallery
// ../share/zeroset/examples beside the executable's folder (mirrored in the build tree), or
// ../examples and ../../examples next to the executable, the first one that exists.
std::filesystem::path findExamplesDir();

std::vector<Example> listExamples(const std::filesystem::path& examplesDir);

// The scene of one example: the file's (errors come back as formatted text) or, for a
// built-in, its formula with the thesis settings.
std::variant<Scene, std::string> loadExample(const Example& example);

// "3 of 12: name" in the current language, as the panel shows the example being looked at.
std::string exampleLabel(int index, int count, const std::string& name);

}  // namespace zs::app
