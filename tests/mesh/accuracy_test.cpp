// Every vertex on F = 0: |F| / |grad F| at each surface vertex is below 1e-3 of a grid cell
// on the thesis surfaces and the gallery's classics, meshed in their scenes' own domains
// (boxes and balls). The formulas come from the example files themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh_fixture.hpp"
#include "scene/scene_io.hpp"

namespace zs {
namespace {

std::filesystem::path examplesDir() {
  const char* src = std::getenv("ZS_SOURCE_DIR");
  return std::filesystem::path(src ? src : ".") / "examples";
}

// The largest |F| / |grad F| over the mesh's surface vertices.
double worstResidual(const Formula& formula, std::span<const double> params, const Mesh& mesh) {
  Graph g = formula.graph;
  const auto grad = gradient(g, formula.root);
  PointEvaluator ev(compileTape(g, {formula.root, grad[0], grad[1], grad[2]}));
  double worst = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (mesh.kinds[v] != VertexKind::Surface) continue;
    const auto& p = mesh.positions[v];
    std::array<double, 4> out{};
    ev.eval(p[0], p[1], p[2], params, out);
    const double len = std::sqrt(out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
    if (out[0] == 0) continue;
    worst = std::max(worst, len > 0 ? std::abs(out[0]) / len : INFINITY);
  }
  return worst;
}

void checkExample(const std::filesystem::path& file, int level) {
  SCOPED_TRACE(file.filename().string());
  SceneResult loaded = loadScene(file);
  ASSERT_TRUE(std::holds_alternative<Scene>(loaded));
  const Scene& scene = std::get<Scene>(loaded);
  const ParseResult parsed = parseFormula(scene.formula);
  ASSERT_TRUE(std::holds_alternative<Formula>(parsed));
  const Formula& formula = std::get<Formula>(parsed);
  const std::vector<double> params = paramValues(scene, formula.graph);
  Box box{scene.domain.min, scene.domain.max};
  std::optional<Ball> ball;
  if (scene.domain.shape == DomainShape::Sphere) {
    const auto& c = scene.domain.center;
    const double r = scene.domain.radius;
    box = {{c[0] - r, c[1] - r, c[2] - r}, {c[0] + r, c[1] + r, c[2] + r}};
    ball = Ball{{c[0], c[1], c[2]}, r};
  }
  MeshSettings settings;
  settings.level = level;
  auto built = buildMesh(formula, params, box, ball, settings);
  ASSERT_TRUE(std::holds_alternative<MeshResult>(built));
  const MeshResult& r = std::get<MeshResult>(built);
  EXPECT_GT(r.mesh.triangles.size(), 0u);
  EXPECT_LE(worstResidual(formula, params, r.mesh), 1e-3 * r.stats.cellSize);
  const MeshTopology t = checkMesh(r.mesh);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.misorientedEdges, 0u);
  EXPECT_EQ(t.nonManifoldVertices, 0u);
  EXPECT_EQ(t.degenerateTriangles, 0u);
}

TEST(MeshAccuracy, ThesisSurfacesHaveEveryVertexOnTheSurface) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examplesDir() / "thesis")) {
    if (entry.path().extension() != ".surf") continue;
    checkExample(entry.path(), 6);
    ++count;
  }
  EXPECT_EQ(count, 7);
}

TEST(MeshAccuracy, GalleryClassicsHaveEveryVertexOnTheSurface) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examplesDir())) {
    if (entry.path().extension() != ".surf") continue;
    checkExample(entry.path(), 6);
    ++count;
  }
  EXPECT_GE(count, 10);
}

}  // namespace
}  // namespace zs
