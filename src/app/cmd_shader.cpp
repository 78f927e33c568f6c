// `zeroset shader SCENE|FORMULA`: the complete fragment shader the renderer would compile.
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "pipeline/pipeline.hpp"

namespace zs::app {

void addShaderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("shader", "Print the fragment shader generated for a surface");
  auto args = std::make_shared<SceneArgs>();
  addSceneOptions(*cmd, *args);
  cmd->callback([args] {
    std::optional<Scene> scene = loadSceneArgs(*args);
    if (!scene) std::exit(1);
    scene->octree.level = 0;  // the shader does not depend on the octree
    auto prepared = prepareSurface(*scene);
    if (auto* err = std::get_if<std::string>(&prepared)) {
      std::cerr << *err;
      std::exit(1);
    }
    std::cout << std::get<PreparedSurface>(prepared).fragmentShader;
    std::exit(0);
  });
}

}  // namespace zs::app
