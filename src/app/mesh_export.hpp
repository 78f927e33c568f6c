#pragma once
// Meshing a scene to a file, shared by `zeroset mesh` and the viewer's export: takes a
// Scene, a grid level, whether to cap, the output path, puts out the file and a summary.
#include <functional>
#include <string>

#include "mesh/mesh.hpp"
#include "mesh/mesh_check.hpp"
#include "scene/scene.hpp"

namespace zs::app {

struct MeshExport {
  MeshSettings settings;  // level, cap, threads
  std::string output;     // .stl, .ply or .obj
};

struct MeshExportReport {
  MeshStats stats;
  MeshTopology topology;
  std::size_t vertices = 0, triangles = 0;
  double writeSeconds = 0;
};

// The level whose cells are no larger than `cellSize` in the scene's domain (at least 1,
// at most kMaxMeshLevel).
int levelForCellSize(const Scene& scene, double cellSize);

// "" on success (and `report` filled); otherwise a message ready to print.
std::string exportMesh(const Scene& scene, const MeshExport& request, MeshExportReport& report,
                       const std::function<void(const std::string&)>& progress = {});

// A summary of several lines for the terminal: counts, times, accuracy, topology.
std::string meshSummary(const MeshExportReport& report, const std::string& output);

}  // namespace zs::app
