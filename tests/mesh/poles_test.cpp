// Where F changes sign without vanishing (a pole, a jump, the edge of F's domain) the grid
// sees a sign change but there is no surface: without a cap those triangles are left out,
// with a cap they bound the solid {F < 0} (docs/mesh.md, "Poles and domain edges").
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_check.hpp"
#include "mesh_fixture.hpp"

namespace zs {
namespace {

using testing::cube;
using testing::meshOf;

// Every vertex within a cell of the plane x = x0.
void expectOnlyThePlane(const MeshResult& r, double x0) {
  ASSERT_GT(r.mesh.triangles.size(), 1000u);
  for (const auto& p : r.mesh.positions)
    ASSERT_NEAR(p[0], x0, r.stats.cellSize) << p[1] << ", " << p[2];
}

TEST(MeshPoles, ThePoleOfOneOverXIsNotMeshed) {
  const MeshResult r = meshOf("1/x - 1", cube(1.5), 5);
  EXPECT_GT(r.stats.poleVertices, 0u);
  expectOnlyThePlane(r, 1.0);
}

TEST(MeshPoles, TheEdgeOfSqrtsDomainIsNotMeshed) {
  // The root x = -0.06 and the domain's edge x = -0.1 fall in the same brick.
  const MeshResult r = meshOf("sqrt(x + 0.1) - 0.2", cube(1.5), 5);
  EXPECT_GT(r.stats.poleVertices, 0u);
  expectOnlyThePlane(r, -0.06);
}

TEST(MeshPoles, LogOfTheSquaredRadiusIsTheUnitSphere) {
  const MeshResult r = meshOf("log(x^2 + y^2 + z^2)", cube(1.5), 6);
  const MeshTopology t = checkMesh(r.mesh);
  EXPECT_TRUE(t.closedManifold());
  EXPECT_EQ(t.euler, 2);
  for (const auto& p : r.mesh.positions) ASSERT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 1e-6);
}

TEST(MeshPoles, APoleOnGridCornersLeavesTheSphereOpenThere) {
  // F = (r^2 - 1) / x: infinite on the grid plane x = 0, the sphere elsewhere.
  const MeshResult r = meshOf("(x^2 + y^2 + z^2 - 1)/x", cube(1.5), 5);
  const MeshTopology t = checkMesh(r.mesh);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.misorientedEdges, 0u);
  EXPECT_EQ(t.components, 2u);  // two hemispheres, parted along the pole
  for (const auto& p : r.mesh.positions) {
    ASSERT_TRUE(std::isfinite(p[0]));
    ASSERT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 1e-6);
  }
}

TEST(MeshPoles, CappedThePoleBoundsTheSolid) {
  // {1/x - 1 < 0} in the cube: x < 0 and x > 1, 13.5 + 4.5.
  const MeshResult r = meshOf("1/x - 1", cube(1.5), 5, true);
  const MeshTopology t = checkMesh(r.mesh);
  EXPECT_TRUE(t.closedManifold());
  EXPECT_NEAR(t.volume, 18.0, 0.01 * 18.0);
}

}  // namespace
}  // namespace zs
