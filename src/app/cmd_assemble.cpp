// `zeroset assemble -o OUT.png BAND.png...`: the bands of `zeroset render --tile I/N`, top
// first, stacked into one PNG (render/image.hpp stackPngs, one band in memory at a time).
#include <iostream>

#include "app/commands.hpp"
#include "render/image.hpp"

namespace zs::app {

void addAssembleCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "assemble", "Stack the bands of `zeroset render --tile I/N` (top first) into one PNG");
  struct Args {
    std::string output;
    std::vector<std::string> parts;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("-o,--output", args->output, "the PNG to write")->required();
  cmd->add_option("bands", args->parts, "the bands' PNGs, tile 0 (the top) first")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->callback([args] {
    if (std::string err = stackPngs(args->parts, args->output); !err.empty()) {
      std::cerr << "error: " << err << "\n";
      std::exit(1);
    }
    std::printf("wrote %s from %zu bands\n", args->output.c_str(), args->parts.size());
    std::exit(0);
  });
}

}  // namespace zs::app
