#pragma once
// The Kuhn (Freudenthal) split of a grid cell into six tetrahedra along its main diagonal,
// and the pieces of F = 0 inside one tetrahedron. Every cell is split the same way, so the
// tetrahedra of neighbouring cells meet face to face: the split has no cracks to mend.
//
// A corner of the cell is 0..7 (bit a set: the far side along axis a). The tetrahedra's
// edges join corners u and v with u's bits a subset of v's: the 12 cell edges, the 6 face
// diagonals that leave the corner (0,0,0) of their face, and the main diagonal: 19 edges.
#include <array>
#include <cstdint>

namespace zs::mesh {

struct CellEdge {
  std::uint8_t lo = 0, hi = 0;  // corners; lo's bits are a subset of hi's
};

inline constexpr int kCellEdges = 19;
const std::array<CellEdge, kCellEdges>& cellEdges();

// The piece of the zero set in one tetrahedron for one pattern of corner signs: nothing, a
// triangle, or a quadrilateral (a cycle of 4 edges), as cell edge ids, ordered so that the
// normal (right-hand rule) points from the negative corners to the positive ones.
struct TetPiece {
  std::uint8_t count = 0;  // 0, 3 or 4
  std::array<std::uint8_t, 4> edges{};
};

// negativeCorners: bit c set when cell corner c is negative (F < 0).
const TetPiece& tetPiece(int tet, int negativeCorners);

}  // namespace zs::mesh
