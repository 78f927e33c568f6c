#include "app/mesh_export.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>

#include "app/text_output.hpp"
#include "mesh/mesh_io.hpp"
#include "parser/parser.hpp"
#include "pipeline/pipeline.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

int levelForCellSize(const Scene& scene, double cellSize) {
  const Box box = toBox(scene.domain);
  double extent = 0;
  for (std::size_t a = 0; a < 3; ++a) extent = std::max(extent, box.max[a] - box.min[a]);
  if (!(cellSize > 0)) return kMaxMeshLevel;
  const double level = std::ceil(std::log2(extent / cellSize));
  return int(std::clamp(level, 1.0, double(kMaxMeshLevel)));
}

namespace {

// The mesh of a scene of one surface.
std::string exportMesh(const Scene& scene, const MeshExport& request, MeshExportReport& report,
                       const std::function<void(const std::string&)>& progress) {
  const auto format = meshFormatFor(request.output);
  if (!format)
    return "error: cannot tell the mesh format from '" + request.output +
           "'\nhint: name the output .stl (binary STL), .ply or .obj\n";
  ParseResult parsed = parseSceneFormula(scene);
  if (auto* err = std::get_if<ParseError>(&parsed)) return formatError(scene.formula, *err);
  const Formula& formula = std::get<Formula>(parsed);
  auto built = buildMesh(formula, paramValues(scene, formula.graph), toBox(scene.domain),
                         toBall(scene.domain), request.settings, progress);
  if (auto* err = std::get_if<std::string>(&built)) return "error: " + *err + "\n";
  const MeshResult& result = std::get<MeshResult>(built);
  report.stats = result.stats;
  report.vertices = result.mesh.positions.size();
  report.triangles = result.mesh.triangles.size();
  // The summary's check runs beside the writing: one waits on the disk, the other does not.
  auto checked = std::async(std::launch::async, [&] { return checkMesh(result.mesh); });
  const auto start = std::chrono::steady_clock::now();
  std::string err = writeMesh(result.mesh, request.output, *format);
  report.writeSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.topology = checked.get();
  if (!err.empty()) return "error: " + err + "\n";
  return {};
}

std::string meshSummary(const MeshExportReport& r, const std::string& output) {
  const MeshTopology& t = r.topology;
  const MeshStats& s = r.stats;
  char buf[1024];
  std::string shape;
  if (t.closedManifold()) {
    shape = "a closed 2-manifold, consistently oriented";
  } else if (t.nonManifoldEdges == 0 && t.misorientedEdges == 0 && t.nonManifoldVertices == 0) {
    shape = "a 2-manifold whose boundary (" + std::to_string(t.boundaryEdges) +
            " edges) lies on the domain" +
            (s.poleVertices > 0 ? " and where F changes sign without a root" : "");
  } else {
    shape = "NOT a manifold: " + std::to_string(t.nonManifoldEdges) + " edges in 3+ triangles, " +
            std::to_string(t.misorientedEdges) + " misoriented, " +
            std::to_string(t.nonManifoldVertices) + " pinched vertices (please report this)";
  }
  std::snprintf(
      buf, sizeof buf,
      "wrote %s: %zu triangles, %zu vertices\n"
      "  %s; Euler characteristic %ld, %zu piece%s%s\n"
      "  largest vertex distance to the surface |F|/|grad F|: %.3g (%.2g of a cell of %.4g)\n"
      "  time: %.3f s (octree %.3f, grid %.3f, vertices %.3f, writing %.3f)\n",
      output.c_str(), r.triangles, r.vertices, shape.c_str(), t.euler, t.components,
      t.components == 1 ? "" : "s",
      t.closedManifold() ? (", volume " + std::to_string(t.volume)).c_str() : "", s.maxResidual,
      s.cellSize > 0 ? s.maxResidual / s.cellSize : 0.0, s.cellSize,
      s.totalSeconds + r.writeSeconds, s.octreeSeconds, s.gridSeconds, s.rootSeconds,
      r.writeSeconds);
  return buf;
}

}  // namespace

std::string exportMeshes(const Scene& scene, const MeshExport& request,
                         std::vector<SurfaceMesh>& meshes,
                         const std::function<void(const std::string&)>& progress) {
  meshes.clear();
  const std::size_t count = surfaceCount(scene);
  for (std::size_t i = 0; i < count; ++i) {
    MeshExport one = request;
    one.output = surfacePath(request.output, i, count).string();
    SurfaceMesh mesh{one.output, {}};
    if (std::string err = exportMesh(surfaceScene(scene, i), one, mesh.report, progress);
        !err.empty())
      return err;
    meshes.push_back(std::move(mesh));
  }
  return {};
}

std::string meshSummary(const std::vector<SurfaceMesh>& meshes) {
  std::string out;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    if (meshes.size() > 1)
      out += (i > 0 ? "\n" : "") + std::string("surface ") + std::to_string(i + 1) + " of " +
             std::to_string(meshes.size()) + ":\n";
    out += meshSummary(meshes[i].report, meshes[i].output);
  }
  return out;
}

}  // namespace zs::app
