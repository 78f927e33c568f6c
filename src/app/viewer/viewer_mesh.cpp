// "Export mesh" (the panel's button, the M key): the shown scene meshed at the panel's level
// and written as STL beside the scene's file (or in the output folder when the scene has
// no file or its folder is not writable), on a thread of its own so the window stays live.
#include <GLFW/glfw3.h>
#include <unistd.h>

#include <cstdio>

#include "app/mesh_export.hpp"
#include "app/repl/scene_edit.hpp"
#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"

namespace zs::app {

void Viewer::startMeshExport() {
  if (meshExport_.valid()) {
    stats_.status = i18n::tr("a mesh export is still running");
    return;
  }
  std::filesystem::path dir = options_.outputDir;
  std::string stem = "zeroset";
  if (!sceneFile_.empty()) {
    const std::filesystem::path beside =
        sceneFile_.parent_path().empty() ? "." : sceneFile_.parent_path();
    if (::access(beside.c_str(), W_OK) == 0) dir = beside;
    stem = sceneFile_.stem().string();
  }
  MeshExport request;
  request.settings.level = panel_.meshLevel;
  request.settings.cap = panel_.meshCap;
  request.output =
      nextFreePath(dir, stem + "-level" + std::to_string(request.settings.level), ".stl").string();
  stats_.status = i18n::format(i18n::tr("exporting a mesh at level %d..."), request.settings.level);
  meshExport_ = std::async(std::launch::async, [scene = session_.scene(), request] {
    std::vector<SurfaceMesh> meshes;
    const std::string error = exportMeshes(scene, request, meshes);
    glfwPostEmptyEvent();  // wake the loop to show it
    if (!error.empty()) return FileJobResult{error, panelError(error)};
    return FileJobResult{meshSummary(meshes),
                         i18n::format(i18n::tr("mesh written: %s"), meshes.front().output.c_str())};
  });
}

void Viewer::finishMeshExport() {
  finishFileJob(meshExport_);
}

void Viewer::finishFileJob(std::future<FileJobResult>& job) {
  if (!job.valid() || job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  const FileJobResult result = job.get();
  stats_.status = result.status.substr(0, result.status.find('\n'));
  uiFrames_ = 3;
  std::fputs(result.log.c_str(), stdout);
  std::fflush(stdout);
}

}  // namespace zs::app
