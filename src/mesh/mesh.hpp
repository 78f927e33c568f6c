#pragma once
// The mesh stage: takes a formula, its parameter values and a domain (a box, or a ball),
// puts out a triangle mesh of F = 0 for printing and other tools (docs/mesh.md).
//
// Method: the interval octree (src/interval) keeps the cells of a uniform grid of 2^level
// cells per axis where the surface may be; those cells, closed under "the zero set crosses
// a shared face", are split into six Kuhn tetrahedra each and F = 0 is marched through
// them. Each vertex is the root of F on a grid edge (bracketed, so it stays on its edge),
// which keeps the piecewise-linear guarantees: a closed, consistently oriented 2-manifold
// without self-intersections wherever the surface stays inside the domain. Normals come
// from the symbolic gradient. `cap` closes the solid {F < 0} along the domain boundary.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "expr/graph.hpp"
#include "interval/octree.hpp"

namespace zs {

struct MeshSettings {
  int level = 7;                        // 2^level grid cells per axis of the domain's bounding box
  unsigned threads = 2;                 // for the octree, the vertex evaluations and the edge roots
  bool cap = false;                     // close the solid {F < 0} along the domain boundary
  std::size_t nodeBudget = 50'000'000;  // octree boxes tested before giving up
};

inline constexpr int kMaxMeshLevel = 12;

// Where a vertex lies: on F = 0 (a root on a grid edge, or F = 0 on the ball's sphere for
// an open ball domain), on the cap (the domain boundary where F < 0), or where F changes
// sign without vanishing (a pole, a jump, the edge of F's domain): such vertices bound the
// capped solid {F < 0} but are not part of F = 0, so without a cap their triangles are left
// out.
enum class VertexKind : std::uint8_t { Surface, Cap, Pole };

struct Mesh {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<float, 3>> normals;  // unit; the gradient's direction (F grows)
  std::vector<VertexKind> kinds;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from F > 0
};

struct MeshStats {
  std::size_t cells = 0;       // grid cells the zero set crosses, marched
  std::size_t gridValues = 0;  // F evaluated at brick corners
  double octreeSeconds = 0, gridSeconds = 0, rootSeconds = 0, totalSeconds = 0;
  double cellSize = 0;           // the grid's smallest cell edge
  double maxResidual = 0;        // largest |F| / |grad F| at a surface vertex
  std::size_t poleVertices = 0;  // sign changes without a root (VertexKind::Pole)
};

struct MeshResult {
  Mesh mesh;
  MeshStats stats;
};

// Called with one line of progress at each stage ("octree: ...").
using MeshProgress = std::function<void(const std::string&)>;

// Never throws for user input: a bad level, an empty formula or an octree over budget give
// a message for the user. With `ball`, the domain is that ball and `box` its bounding box.
std::variant<MeshResult, std::string> buildMesh(const Formula& formula,
                                                std::span<const double> params, const Box& box,
                                                std::optional<Ball> ball,
                                                const MeshSettings& settings,
                                                const MeshProgress& progress = {});

}  // namespace zs
