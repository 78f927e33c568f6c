#include "app/cli.hpp"

#include "app/commands.hpp"

#ifndef ZS_VERSION
#define ZS_VERSION "unknown"
#endif

namespace zs::app {

void addCommands(CLI::App& app) {
  app.name("zeroset");
  app.description("zeroset - see implicit surfaces F(x,y,z) = 0");
  app.set_version_flag("--version", std::string("zeroset ") + ZS_VERSION);
  app.require_subcommand(1);
  addCheckCommand(app);
  addRenderCommand(app);
  addPrintCommand(app);
  addSurfCommand(app);
  addOctreeCommand(app);
  addShaderCommand(app);
  addBenchCommand(app);
  addViewCommand(app);
  addSingularCommand(app);
  addProbeCommand(app);
  addMeshCommand(app);
  addImportCommand(app);
  addExportCommand(app);
  addGalleryCommand(app);
  addAssembleCommand(app);
  // After the subcommands, so they do not inherit the top-level footer.
  app.footer(
      "Run `zeroset SUBCOMMAND --help` for a subcommand's options, or `man zeroset`. "
      "Without a subcommand, zeroset prompts for formulas.");
  for (CLI::App* cmd : app.get_subcommands([](CLI::App*) { return true; })) {
    for (const CLI::Option* opt : cmd->get_options()) {
      if (opt->get_positional()) {
        cmd->footer("A formula may begin with a minus sign: zeroset " + cmd->get_name() +
                    " \"-x^2-y^2+z\"" +
                    (cmd->get_name() == "render"  ? " -o out.png"
                     : cmd->get_name() == "print" ? " -o page.pdf"
                                                  : "") +
                    ".");
        break;
      }
    }
  }
}

}  // namespace zs::app
