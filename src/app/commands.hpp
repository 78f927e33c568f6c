#pragma once
// The zeroset command line: one function per subcommand registers it with CLI11.
#include <CLI/CLI.hpp>

namespace zs::app {

void addCheckCommand(CLI::App& app);

}  // namespace zs::app
