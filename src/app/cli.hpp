#pragma once
// The zeroset command line as one CLI11 tree: takes an empty app, puts out the zeroset
// command with every subcommand registered (commands.hpp). main() parses with it; the man
// page and shell completion generators (src/app/docgen) walk the same tree, so --help,
// `man zeroset` and completion agree.
#include <CLI/CLI.hpp>

namespace zs::app {

// Makes `app` the zeroset command: its name and description, --version, every subcommand,
// and the footers that point to `man zeroset` and say a formula may begin with a minus
// sign (formula_args.hpp).
void addCommands(CLI::App& app);

}  // namespace zs::app
