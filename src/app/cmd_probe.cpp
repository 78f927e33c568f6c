// `zeroset probe SCENE|FORMULA --pixel X,Y [--size WxH] [--set KEY=VALUE]... [--json]`: what
// lies under one pixel of the picture `zeroset render` would draw: the point, F, grad F, the
// unit normal, K, H, k1, k2 (src/probe does the work, on the CPU).
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "parser/parser.hpp"
#include "probe/probe.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

namespace {

struct ProbeArgs {
  SceneArgs scene;
  std::string pixel, size;
  bool json = false;
};

bool parsePair(const std::string& text, char sep, int& a, int& b) {
  char rest = 0;
  const std::string format = std::string("%d") + sep + "%d%c";
  return std::sscanf(text.c_str(), format.c_str(), &a, &b, &rest) == 2;
}

int runProbe(const ProbeArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  int width = scene->width, height = scene->height;
  if (!args.size.empty() &&
      !(parsePair(args.size, 'x', width, height) && width > 0 && height > 0)) {
    std::cerr << "error: --size '" << args.size << "' is not WIDTHxHEIGHT\n"
              << "hint: e.g. --size 800x600, the size of the picture the pixel belongs to\n";
    return 1;
  }
  int x = 0, y = 0;
  if (!parsePair(args.pixel, ',', x, y)) {
    std::cerr << "error: --pixel '" << args.pixel << "' is not X,Y\n"
              << "hint: e.g. --pixel 400,300, counted from the top-left pixel (0,0)\n";
    return 1;
  }
  SceneProbe probe(*scene);
  if (!probe.error().empty()) {
    std::cerr << probe.error();
    return 1;
  }
  auto result = probe.pixel(*scene, width, height, x, y);
  if (auto* err = std::get_if<std::string>(&result)) {
    std::cerr << "error: " << *err << "\n";
    return 1;
  }
  const ProbeResult& r = std::get<ProbeResult>(result);
  std::cout << (args.json ? probeJson(r) : probeText(r));
  return 0;
}

}  // namespace

void addProbeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "probe",
      "Inspect one pixel of the picture `render` would draw: the first point of F = 0 on its "
      "ray, F, grad F, the unit normal, the Gaussian and mean curvature K, H and the principal "
      "curvatures k1, k2");
  auto args = std::make_shared<ProbeArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option("--pixel", args->pixel, "the pixel X,Y, from the top-left (0,0)")->required();
  cmd->add_option("--size", args->size,
                  "the picture's size WIDTHxHEIGHT (default: the scene's, 800x600)");
  cmd->add_flag("--json", args->json, "one JSON object instead of name: value lines");
  cmd->callback([args] { std::exit(runProbe(*args)); });
}

}  // namespace zs::app
