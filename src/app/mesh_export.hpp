#pragma once
// Meshing a scene to a file, shared by `zeroset mesh` and the viewer's export: takes a
// Scene, a grid level, whether to cap, the output path, puts out the file and a summary.
#include <functional>
#include <string>
#include <vector>

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

// One mesh written: where, and what it is.
struct SurfaceMesh {
  std::string output;
  MeshExportReport report;
};

// One mesh per surface of the scene, each closed (or ending on the domain) on its own, where
// the union's mesh would have every intersection curve as a non-manifold edge: written to
// `request.output`, or for several surfaces to its stem numbered from 1 (out-1.stl, ...).
// "" on success (and `meshes` filled, in surface order); otherwise a message ready to print.
std::string exportMeshes(const Scene& scene, const MeshExport& request,
                         std::vector<SurfaceMesh>& meshes,
                         const std::function<void(const std::string&)>& progress = {});

// A summary of several lines per mesh for the terminal: counts, times, accuracy, topology,
// each headed "surface N of M:" when there are several.
std::string meshSummary(const std::vector<SurfaceMesh>& meshes);

}  // namespace zs::app
