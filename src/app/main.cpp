// zeroset: implicit surfaces F(x, y, z) = 0, ray-traced. Each subcommand lives in its own
// cmd_*.cpp; this file only assembles them.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/formula_args.hpp"

#ifndef ZS_VERSION
#define ZS_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  if (argc == 1) return zs::app::runPrompt();
  CLI::App app{"zeroset - see implicit surfaces F(x,y,z) = 0"};
  app.set_version_flag("--version", std::string("zeroset ") + ZS_VERSION);
  app.require_subcommand(1);
  zs::app::addCheckCommand(app);
  zs::app::addRenderCommand(app);
  zs::app::addOctreeCommand(app);
  zs::app::addShaderCommand(app);
  zs::app::addBenchCommand(app);
  zs::app::addViewCommand(app);
  zs::app::addSingularCommand(app);
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
