#pragma once
// What a mesh is, checked: closed, edge-manifold, consistently oriented, vertex-manifold;
// its Euler characteristic, enclosed volume and pieces. The tests and `zeroset mesh`'s
// report use it; nothing here trusts how the mesh was built.
#include <cstddef>

#include "mesh/mesh.hpp"

namespace zs {

struct MeshTopology {
  std::size_t vertices = 0, edges = 0, faces = 0;  // vertices: those some triangle uses
  std::size_t boundaryEdges = 0;                   // in one triangle
  std::size_t nonManifoldEdges = 0;                // in three or more
  std::size_t misorientedEdges = 0;                // in two triangles that run it the same way
  std::size_t nonManifoldVertices = 0;             // triangles around it form more than one fan
  std::size_t degenerateTriangles = 0;             // a repeated vertex
  std::size_t components = 0;                      // connected through shared edges
  long euler = 0;                                  // V - E + F
  double volume = 0;  // signed, by the divergence theorem (closed meshes)

  bool closedManifold() const {
    return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0 &&
           nonManifoldVertices == 0 && degenerateTriangles == 0;
  }
};

MeshTopology checkMesh(const Mesh& mesh);

// Pairs of triangles with no common vertex that cross each other (an edge of one through
// the other): 0 for a mesh without self-intersections. Binned, for tests and small meshes.
std::size_t countSelfIntersections(const Mesh& mesh);

}  // namespace zs
