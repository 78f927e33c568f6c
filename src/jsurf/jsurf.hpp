#pragma once
// SURFER's .jsurf scene files (IMAGINARY's SURFER and its jsurf renderer): takes the text of
// one and puts out the zeroset Scene that shows the same picture — formula, parameters,
// zoom and clipping sphere, orientation, camera, lights, materials, background — plus
// warnings for what zeroset cannot show the same way, or a SceneError with file:line:column
// for what cannot be read at all. exportJsurf goes the other way and writes a file SURFER
// opens. Neither throws. The mapping of every key is in docs/jsurf.md.
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_io.hpp"

namespace zs::jsurf {

using Imported = ImportedScene;  // warnings: print with formatWarning
using ImportResult = zs::ImportResult;

ImportResult importJsurf(std::string_view text, std::string_view fileName);

// Reads the file and imports it; a missing or unreadable file is a SceneError with line 0.
ImportResult loadJsurf(const std::filesystem::path& path);

// True for a name ending in ".jsurf" (any case).
bool isJsurfPath(std::string_view path);

struct Exported {
  std::string text;
  std::vector<std::string> warnings;  // what SURFER will show differently, one line each
};

// The .jsurf text of `scene`, or why SURFER cannot show it (a formula that is not a
// polynomial in x, y, z, or that uses what SURFER's formula language lacks).
std::variant<Exported, std::string> exportJsurf(const Scene& scene);

// formatSceneWarning, under the name jsurf's callers have used.
std::string formatWarning(const SceneError& warning);

}  // namespace zs::jsurf
