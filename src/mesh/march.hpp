#pragma once
// The steps of buildMesh after the grid is filled (mesher.cpp runs them in order):
//   marchCells  the zero set through each cell's six tetrahedra: one mesh vertex per grid
//               edge it crosses (numbered in the order met), triangles and quadrilaterals
//   placeRoots  each such vertex at the root on its edge, with the gradient's normal
//   capBox      the box domain's faces where F < 0, sharing the vertices of the edges
//   clipBall    an open ball domain: triangles cut along the sphere, on F = 0 there
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "mesh/grid.hpp"
#include "mesh/mesh.hpp"

namespace zs::mesh {

struct GridEdge {
  std::uint32_t negative = 0, positive = 0;  // grid corners (Grid::vertex indices)
  std::uint64_t negativeKey = 0, positiveKey = 0;
};

struct Marched {
  FlatIndex edgeIndex{1 << 16};  // (lower corner key << 3 | axes) -> mesh vertex
  std::vector<GridEdge> edges;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 4>> quads;
};

// The key of the grid edge between two corners whose coordinates differ by 0 or 1 (one
// corner lower or equal on every axis): the lower corner and the set of axes.
std::uint64_t edgeKey(std::uint64_t cornerA, std::uint64_t cornerB);

Marched marchCells(const Grid& grid);

// Fills mesh.positions/normals/kinds for the marched edges; returns the largest |F|/|grad F|.
double placeRoots(const Grid& grid, const Marched& marched, std::span<FieldEvaluator> evaluators,
                  Mesh& mesh);

// Splits the quadrilaterals along their shorter diagonal into mesh.triangles.
void addTriangles(const Marched& marched, Mesh& mesh);

// The corners of the box's faces (evaluated by the caller before the cells are closed) and
// the cells beside a face square the zero set crosses, which must be marched.
std::vector<std::uint64_t> boxFaceCorners(std::uint32_t n);
std::vector<std::uint64_t> cellsBesideCrossedFaces(const Grid& grid);
void capBox(const Grid& grid, const Marched& marched, Mesh& mesh);

void clipBall(const Ball& ball, double cellSize, FieldEvaluator& evaluator, Mesh& mesh);

// Drops the vertices no triangle uses, renumbering the triangles.
void dropUnusedVertices(Mesh& mesh);

}  // namespace zs::mesh
