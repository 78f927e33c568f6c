// `zeroset mesh SCENE|FORMULA -o OUT.stl|.ply|.obj [--level N | --cell-size S] [--cap]
// [--threads N] [--set KEY=VALUE]...`: a triangle mesh of F = 0 in the scene's domain for
// printing and other tools; src/mesh does the work (docs/mesh.md).
#include <iostream>

#include "app/commands.hpp"
#include "app/mesh_export.hpp"
#include "app/scene_args.hpp"

namespace zs::app {

namespace {

struct MeshArgs {
  SceneArgs scene;
  MeshExport request;
  std::optional<double> cellSize;
  bool quiet = false;
};

int runMesh(MeshArgs& args) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  if (args.cellSize) args.request.settings.level = levelForCellSize(*scene, *args.cellSize);
  auto progress = [&](const std::string& line) {
    if (!args.quiet) std::cerr << "mesh: " << line << "\n" << std::flush;
  };
  std::vector<SurfaceMesh> meshes;
  if (std::string err = exportMeshes(*scene, args.request, meshes, progress); !err.empty()) {
    std::cerr << err;
    return 1;
  }
  std::cout << meshSummary(meshes);
  return 0;
}

}  // namespace

void addMeshCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "mesh",
      "Write a triangle mesh of F = 0 in the domain (binary STL, PLY or OBJ with normals): "
      "closed where the surface is, on the domain where it leaves it, or capped with --cap");
  auto args = std::make_shared<MeshArgs>();
  addSceneOptions(*cmd, args->scene);
  cmd->add_option(
         "-o,--output", args->request.output,
         "the mesh file: .stl (binary), .ply (binary, with normals) or .obj (with normals)")
      ->required();
  auto* level = cmd->add_option("--level", args->request.settings.level,
                                "grid level: 2^N cells along each axis of the domain (default 7)")
                    ->check(CLI::Range(1, kMaxMeshLevel));
  cmd->add_option("--cell-size", args->cellSize,
                  "the largest grid cell wanted, in scene units (picks the level)")
      ->check(CLI::PositiveNumber)
      ->excludes(level);
  cmd->add_flag("--cap", args->request.settings.cap,
                "close the solid F < 0 along the domain's boundary (box faces or sphere), for "
                "printing");
  cmd->add_option("--threads", args->request.settings.threads, "worker threads (default 2)")
      ->check(CLI::Range(1, 256));
  cmd->add_flag("-q,--quiet", args->quiet, "no progress lines on stderr");
  cmd->callback([args] { std::exit(runMesh(*args)); });
}

}  // namespace zs::app
