// zeroset: implicit surfaces F(x, y, z) = 0, ray-traced. Each subcommand lives in its own
// cmd_*.cpp; cli.cpp assembles them.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/commands.hpp"
#include "app/formula_args.hpp"

int main(int argc, char** argv) {
  if (argc == 1) return zs::app::runPrompt();
  CLI::App app;
  zs::app::addCommands(app);
  std::vector<std::string> args(argv, argv + argc);
  zs::app::protectMinusFormulas(args, app);
  std::vector<char*> pointers;
  for (std::string& a : args) pointers.push_back(a.data());
  try {
    app.parse(int(pointers.size()), pointers.data());
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return 0;
}
