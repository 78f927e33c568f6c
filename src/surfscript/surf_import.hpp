#pragma once
// surf's scripts as zeroset scenes and pictures (docs/surf.md). importSurfScript gives the
// scene of the script's last surface drawing, for `zeroset render/view/import/mesh/print
// FILE.pic`; runSurfScript gives every picture the script saves, for the `surf` command.
// Errors and notes carry file:line:column; nothing here throws.
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/scene_io.hpp"
#include "surfscript/script_run.hpp"

namespace zs::surfscript {

// One save_color_image: the file, its format and the scene drawn in it.
struct ScriptPicture {
  std::string fileName;
  ImageFormat format = ImageFormat::Sun;
  Scene scene;
  SceneError place;  // where the script saves it (file, line, column), for messages
};

struct ScriptPictures {
  std::vector<ScriptPicture> pictures;
  std::vector<SceneError> warnings;
};

ImportResult importSurfScript(std::string_view text, std::string_view fileName);
ImportResult loadSurfScript(const std::filesystem::path& path);

std::variant<ScriptPictures, SceneError> runSurfScript(std::string_view text,
                                                       std::string_view fileName);

// True for a name ending in ".pic" (any case): surf's scripts as SURFER-2008 keeps them.
bool isSurfScriptPath(std::string_view path);

}  // namespace zs::surfscript
