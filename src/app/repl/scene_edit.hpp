#pragma once
// Scene edits shared by the prompt's two targets (the viewer window, the headless renderer)
// and the viewer's panel: takes a Scene and a command or a file name, puts out the changed
// scene or error text ready to print (caret for formulas, file:line:column for scenes).
#include <filesystem>
#include <string>

#include "app/repl/command.hpp"
#include "scene/scene.hpp"

namespace zs::app {

// Formula (parsed first, so a typo gives the caret and leaves the scene alone), Load (the
// whole scene is replaced) and Set (one key). Other kinds are not edits: returns an error.
// "" on success; on failure `scene` is unchanged.
std::string applyToScene(const PromptCommand& command, Scene& scene);

// "" when `scene` would load back from its own .surf text; otherwise the loader's message
// (a value outside its range, say). The panel checks every edit with this, so a saved view
// always loads.
std::string checkScene(const Scene& scene);

// Writes saveScene(scene) to `path`; "" or an error naming the file.
std::string writeSceneFile(const std::filesystem::path& path, const Scene& scene);

// dir/stem-0001.ext, dir/stem-0002.ext, ...: the first that does not exist yet.
std::filesystem::path nextFreePath(const std::filesystem::path& dir, const std::string& stem,
                                   const std::string& extension);

}  // namespace zs::app
