#pragma once
// The steps of buildMesh after the grid is filled (mesher.cpp runs them in order):
//   marchBricks the zero set through each cell's six tetrahedra: one mesh vertex per grid
//               edge it crosses (numbered in the order met), triangles and quadrilaterals
//   placeRoots  each such vertex at the root on its edge, with the gradient's normal
//   capBox      the box domain's faces where F < 0, sharing the vertices of the edges
//   clipBall    an open ball domain: triangles cut along the sphere, on F = 0 there
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "mesh/flat_index.hpp"
#include "mesh/grid.hpp"
#include "mesh/mesh.hpp"

namespace zs::mesh {

struct GridEdge {
  std::uint64_t negativeKey = 0, positiveKey = 0;  // grid corners
  double negativeValue = 0, positiveValue = 0;     // the field there
};

struct Marched {
  // Edges that lie on a brick's face (those of the domain's faces among them): edgeKey ->
  // mesh vertex. An edge inside a brick is met by that brick alone and needs no lookup.
  FlatIndex edgeIndex{1 << 16};
  std::vector<GridEdge> edges;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 4>> quads;
  std::size_t cells = 0;   // cells the zero set crosses
  std::size_t bricks = 0;  // bricks evaluated and marched
};

// The key of the grid edge between two corners whose coordinates differ by 0 or 1 (one
// corner lower or equal on every axis): the lower corner and the set of axes.
std::uint64_t edgeKey(std::uint64_t cornerA, std::uint64_t cornerB);
// The same from the lower corner and the axes bits (bit a: the edge moves along axis a).
inline std::uint64_t edgeKeyAt(std::uint64_t lowCorner, int axes) {
  return (lowCorner << 3) | std::uint64_t(axes);
}

// Evaluates and marches the seed bricks and every brick the closure rule (grid.hpp) reaches,
// in parallel (a thread per evaluator); the vertices are numbered in the order of the seeds
// and of the rule's waves whatever the thread count, so the mesh is reproducible.
Marched marchBricks(const Grid& grid, std::vector<std::uint64_t> seeds,
                    std::span<FieldEvaluator> evaluators);

// Fills mesh.positions/normals/kinds for the marched edges; returns the largest |F|/|grad F|.
double placeRoots(const Grid& grid, const Marched& marched, std::span<FieldEvaluator> evaluators,
                  Mesh& mesh);

// Splits the quadrilaterals along their shorter diagonal into mesh.triangles.
void addTriangles(const Marched& marched, Mesh& mesh);

// The field on the box's six faces, which the cap needs everywhere, bricks or not.
class BoxFaces {
 public:
  BoxFaces(const Grid& grid, FieldEvaluator& evaluator);
  bool negative(int face, std::uint64_t cornerKey) const;
  // The bricks beside a face square the zero set crosses: they must be marched, so that the
  // cap's boundary edges have their vertices.
  std::vector<std::uint64_t> bricksBesideCrossedSquares() const;

 private:
  std::uint32_t n_, b_;
  std::vector<double> values_;  // per face, (n + 1)^2 corners
};

void capBox(const Grid& grid, const BoxFaces& faces, const Marched& marched, Mesh& mesh);

void clipBall(const Ball& ball, double cellSize, FieldEvaluator& evaluator, Mesh& mesh);

// Without a cap: drops the triangles at a pole, a jump or the edge of F's domain (a vertex of
// VertexKind::Pole).
void dropPoleTriangles(Mesh& mesh);

// Drops the vertices no triangle uses, renumbering the triangles.
void dropUnusedVertices(Mesh& mesh);

}  // namespace zs::mesh
