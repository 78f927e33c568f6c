#pragma once
// The prompt's edits, for both of its targets (the viewer window, the headless renderer):
// takes a session and a command, carries the command out on the session with its verb
// (session/session.hpp) and puts out error text ready to print (caret for formulas,
// file:line:column for scenes). Also the files the prompt and the viewer write.
#include <filesystem>
#include <string>

#include "app/repl/command.hpp"
#include "session/session.hpp"

namespace zs::app {

// Formula, Load (.surf or .jsurf) and Set (one key); other kinds are not edits and return an
// error. "" on success; on failure the session's scene is unchanged. Builds nothing: the
// target prepares.
std::string applyPromptEdit(const PromptCommand& command, session::Session& session);

// Writes saveScene(scene) to `path`, whole or not at all; "" or an error naming the file.
std::string writeSceneFile(const std::filesystem::path& path, const Scene& scene);

// dir/stem-0001.ext, dir/stem-0002.ext, ...: the first that does not exist yet.
std::filesystem::path nextFreePath(const std::filesystem::path& dir, const std::string& stem,
                                   const std::string& extension);

}  // namespace zs::app
