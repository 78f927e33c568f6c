// The topology the mesher promises, checked by counting: closed 2-manifolds with the Euler
// characteristic of the sphere (2), the torus (0) and a genus-2 surface (-2), consistently
// oriented outwards (positive volume within 1% of the analytic one), open meshes whose
// boundary lies on the domain, and capped solids that are closed again.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/mesh_check.hpp"
#include "mesh_fixture.hpp"

namespace zs {
namespace {

using testing::cube;
using testing::meshOf;

constexpr double kPi = std::numbers::pi;

void expectClosed(const MeshTopology& t, long euler) {
  EXPECT_EQ(t.boundaryEdges, 0u);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.misorientedEdges, 0u);
  EXPECT_EQ(t.nonManifoldVertices, 0u);
  EXPECT_EQ(t.degenerateTriangles, 0u);
  EXPECT_EQ(t.euler, euler);
  EXPECT_GT(t.faces, 100u);
}

void expectNoSelfIntersections(const Mesh& m) {
  EXPECT_EQ(countSelfIntersections(m), 0u);
}

TEST(MeshTopology, SphereIsAClosedManifoldOfEulerCharacteristicTwo) {
  for (int level : {3, 5, 7}) {
    const MeshResult r = meshOf("x^2 + y^2 + z^2 - 1", cube(1.5), level);
    const MeshTopology t = checkMesh(r.mesh);
    SCOPED_TRACE(level);
    expectClosed(t, 2);
    EXPECT_EQ(t.components, 1u);
    if (level == 7) {
      EXPECT_NEAR(t.volume, 4.0 / 3.0 * kPi, 0.01 * 4.0 / 3.0 * kPi);
    }
    if (level == 5) {
      expectNoSelfIntersections(r.mesh);
    }
  }
}

// Below level 3 a brick is the whole domain (2 or 4 cells a side): still a closed sphere.
TEST(MeshTopology, CoarsestLevelsAreClosedToo) {
  for (int level : {1, 2}) {
    SCOPED_TRACE(level);
    const MeshTopology t = checkMesh(meshOf("x^2 + y^2 + z^2 - 1", cube(1.5), level).mesh);
    EXPECT_TRUE(t.closedManifold());
    EXPECT_EQ(t.euler, 2);
  }
}

// The bricks are evaluated and the roots refined on several threads; the mesh must not
// depend on how the work was shared.
TEST(MeshTopology, SameMeshWhateverTheThreadCount) {
  const Formula f = std::get<Formula>(parseFormula(
      "4*(2.618*x^2 - y^2)*(2.618*y^2 - z^2)*(2.618*z^2 - x^2) - 4.236*(x^2 + y^2 + z^2 - 1)^2"));
  std::vector<Mesh> meshes;
  for (unsigned threads : {1u, 2u, 5u}) {
    MeshSettings s;
    s.level = 6;
    s.cap = true;
    s.threads = threads;
    meshes.push_back(std::get<MeshResult>(buildMesh(f, {}, cube(1.5), std::nullopt, s)).mesh);
  }
  for (std::size_t i = 1; i < meshes.size(); ++i) {
    EXPECT_EQ(meshes[i].positions, meshes[0].positions);
    EXPECT_EQ(meshes[i].triangles, meshes[0].triangles);
  }
  EXPECT_GT(meshes[0].triangles.size(), 10000u);
}

TEST(MeshTopology, SphereInABallDomainIsClosedToo) {
  const MeshResult r = meshOf("x^2 + y^2 + z^2 - 1", cube(1.5), 6, false, Ball{{0, 0, 0}, 1.5});
  expectClosed(checkMesh(r.mesh), 2);
}

TEST(MeshTopology, TorusHasEulerCharacteristicZeroAndItsVolume) {
  const double R = 1.0, rr = 0.4;
  const MeshResult r = meshOf("(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + z^2)", cube(1.5), 7,
                              false, std::nullopt, {R, rr});
  const MeshTopology t = checkMesh(r.mesh);
  expectClosed(t, 0);
  EXPECT_EQ(t.components, 1u);
  const double exact = 2 * kPi * kPi * R * rr * rr;
  EXPECT_NEAR(t.volume, exact, 0.01 * exact);
  expectNoSelfIntersections(r.mesh);
}

TEST(MeshTopology, ThickenedFigureEightHasGenusTwo) {
  // The curve x(x-1)^2(x-2) + y^2 = 0 is a figure eight in the plane z = 0; a thin tube
  // around it bounds a handlebody of genus 2: Euler characteristic 2 - 2g = -2.
  const Box box{{-0.3, -0.8, -0.3}, {2.3, 0.8, 0.3}};
  const MeshResult r = meshOf("(x*(x-1)^2*(x-2) + y^2)^2 + z^2 - 0.01", box, 8);
  const MeshTopology t = checkMesh(r.mesh);
  expectClosed(t, -2);
  EXPECT_EQ(t.components, 1u);
  expectNoSelfIntersections(r.mesh);
}

TEST(MeshTopology, ManyComponentsEachClosed) {
  // Eight small spheres: Euler characteristic 16, eight pieces.
  const MeshResult r = meshOf("((x^2-1)^2 + (y^2-1)^2 + (z^2-1)^2) - 0.1", cube(1.6), 6);
  const MeshTopology t = checkMesh(r.mesh);
  expectClosed(t, 16);
  EXPECT_EQ(t.components, 8u);
}

TEST(MeshTopology, OpenSurfaceEndsOnTheBoxAndTheCapClosesIt) {
  // A plane through the box: an open disc whose boundary lies on the box's faces.
  const MeshResult open = meshOf("z - 0.3*x + 0.1", cube(1), 5);
  const MeshTopology t = checkMesh(open.mesh);
  EXPECT_GT(t.boundaryEdges, 0u);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.misorientedEdges, 0u);
  EXPECT_EQ(t.euler, 1);
  for (const auto& p : open.mesh.positions)
    for (double c : p) EXPECT_LE(std::abs(c), 1.0);
  // Capped: the solid below the plane in the box, a closed ball (Euler 2), and its volume
  // is that of {z < 0.3x - 0.1} in the box: 4 * 0.9.
  const MeshResult capped = meshOf("z - 0.3*x + 0.1", cube(1), 5, true);
  const MeshTopology c = checkMesh(capped.mesh);
  expectClosed(c, 2);
  EXPECT_NEAR(c.volume, 4.0 * (1 - 0.1), 1e-4);  // vertices kept off grid corners
}

TEST(MeshTopology, CappedGyroidCellIsClosed) {
  const MeshResult r =
      meshOf("sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", cube(3.14159), 6, true);
  const MeshTopology t = checkMesh(r.mesh);
  expectClosed(t, t.euler);  // closed and manifold; the genus is whatever the cell cuts
  EXPECT_EQ(t.boundaryEdges, 0u);
  // The gyroid splits the cube into two congruent labyrinths: half the volume each.
  const double box = std::pow(2 * 3.14159, 3);
  EXPECT_NEAR(t.volume, box / 2, 0.01 * box);
  expectNoSelfIntersections(r.mesh);
}

TEST(MeshTopology, CappedBallDomainIsClosed) {
  // A plane through a ball: the capped solid is a half ball, closed, Euler 2.
  const MeshResult r = meshOf("z - 0.2", cube(1.2), 6, true, Ball{{0, 0, 0}, 1.2});
  const MeshTopology t = checkMesh(r.mesh);
  expectClosed(t, 2);
  const double h = 1.2 + 0.2;  // the cap of height h of a ball of radius 1.2 lies below z = 0.2
  const double exact = kPi * h * h * (3 * 1.2 - h) / 3;
  EXPECT_NEAR(t.volume, exact, 0.02 * exact);
}

TEST(MeshTopology, OpenBallDomainEndsOnTheSphere) {
  const MeshResult r = meshOf("z - 0.2", cube(1.2), 6, false, Ball{{0, 0, 0}, 1.2});
  const MeshTopology t = checkMesh(r.mesh);
  EXPECT_EQ(t.nonManifoldEdges, 0u);
  EXPECT_EQ(t.misorientedEdges, 0u);
  EXPECT_EQ(t.euler, 1);  // a disc
  for (const auto& p : r.mesh.positions) {
    EXPECT_LE(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.2 * (1 + 1e-9));
    EXPECT_NEAR(p[2], 0.2, 1e-9);
  }
}

}  // namespace
}  // namespace zs

namespace zs {
namespace {

TEST(MeshCheck, FindsWhatItLooksFor) {
  // Two triangles through each other, and one pair that only shares a vertex.
  Mesh m;
  m.positions = {{0, 0, 0},     {2, 0, 0},       {0, 2, 0}, {0.5, 0.5, -1},
                 {0.5, 0.5, 1}, {1.5, 1.5, 0.5}, {5, 5, 5}, {6, 5, 5}};
  m.normals.resize(m.positions.size());
  m.kinds.resize(m.positions.size());
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 6, 7}};
  EXPECT_EQ(countSelfIntersections(m), 1u);
  const MeshTopology t = checkMesh(m);
  EXPECT_EQ(t.boundaryEdges, 9u);
  EXPECT_FALSE(t.closedManifold());
  EXPECT_EQ(t.nonManifoldVertices, 1u);  // vertex 0: two triangles meeting only there
  // A tetrahedron's surface: closed, Euler 2, and flipping one face is caught.
  Mesh tet;
  tet.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tet.normals.resize(4);
  tet.kinds.resize(4);
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const MeshTopology c = checkMesh(tet);
  EXPECT_TRUE(c.closedManifold());
  EXPECT_EQ(c.euler, 2);
  EXPECT_NEAR(c.volume, 1.0 / 6.0, 1e-15);
  tet.triangles[3] = {1, 3, 2};
  EXPECT_EQ(checkMesh(tet).misorientedEdges, 3u);
}

}  // namespace
}  // namespace zs
