#pragma once
// The zeroset command line: one function per subcommand registers it with CLI11; each
// lives in its own cmd_*.cpp.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace zs::app {

void addCheckCommand(CLI::App& app);
void addOctreeCommand(CLI::App& app);
void addShaderCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addSingularCommand(CLI::App& app);
void addMeshCommand(CLI::App& app);
void addImportCommand(CLI::App& app);
void addExportCommand(CLI::App& app);
void addGalleryCommand(CLI::App& app);
void addProbeCommand(CLI::App& app);
void addAssembleCommand(CLI::App& app);
void addPrintCommand(CLI::App& app);
void addSurfCommand(CLI::App& app);

// zeroset run as surf, surf-alggeo or surf-alggeo-nox: surf's command line (cmd_surf.cpp);
// `args` without the program's name.
int runSurfCommandLine(const std::vector<std::string>& args);

// `zeroset` with no arguments: the formula prompt (repl/prompt.hpp).
int runPrompt();

}  // namespace zs::app
