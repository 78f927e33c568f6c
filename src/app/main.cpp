// zeroset: implicit surfaces F(x, y, z) = 0, ray-traced. Each subcommand lives in its own
// cmd_*.cpp; cli.cpp assembles them.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/commands.hpp"
#include "app/formula_args.hpp"

namespace {

// The name zeroset was run under, without its folder.
std::string programName(const char* argv0) {
  const std::string path = argv0 ? argv0 : "";
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  // Under surf's names zeroset is surf (Singular's plot runs `surf FILE`); under SURFER's,
  // SURFER with a file: the viewer where there is a display, else a picture beside the file
  // (docs/surf.md).
  const std::string name = programName(argv[0]);
  if (name == "surf" || name == "surf-alggeo" || name == "surf-alggeo-nox")
    return zs::app::runSurfCommandLine({args.begin() + 1, args.end()});
  if (name == "surfer") {
    std::vector<std::string> files;
    for (std::size_t i = 1; i < args.size(); ++i)
      if (!args[i].empty() && args[i][0] != '-') files.push_back(args[i]);
    if (files.size() != 1) {
      std::cerr << "surfer: give one SURFER file (zeroset shows it)\n";
      return 1;
    }
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((display && *display) || (wayland && *wayland))
      args = {args[0], "view", "--input-format", "jsurf", files[0]};
    else
      args = {args[0], "render", "--input-format", "jsurf", files[0], "-o", files[0] + ".png"};
  } else if (argc == 1) {
    return zs::app::runPrompt();
  }
  CLI::App app;
  zs::app::addCommands(app);
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
