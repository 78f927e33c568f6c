#include "mesh/march.hpp"

#include <cmath>
#include <thread>

#include "mesh/kuhn.hpp"

namespace zs::mesh {

std::uint64_t edgeKey(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);  // packed keys order like coords
  std::uint64_t axes = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (keyAxis(lo, axis) != keyAxis(hi, axis)) axes |= std::uint64_t(1) << axis;
  return (lo << 3) | axes;
}

Marched marchCells(const Grid& grid) {
  Marched m;
  const auto& edges = cellEdges();
  m.edgeIndex.reserve(grid.cells().size() * 3 / 2);
  m.edges.reserve(grid.cells().size() * 3 / 2);
  for (std::size_t i = 0; i < grid.cells().size(); ++i) {
    const std::uint64_t cell = grid.cells()[i];
    const std::uint32_t* corner = grid.cellCorners(i);
    int neg = 0;
    for (int c = 0; c < 8; ++c) neg |= int(grid.negative(corner[c])) << c;
    if (neg == 0 || neg == 0xff) continue;
    std::array<std::uint32_t, kCellEdges> local{};
    for (int e = 0; e < kCellEdges; ++e) {
      const CellEdge ce = edges[std::size_t(e)];
      const bool loNeg = (neg >> ce.lo) & 1, hiNeg = (neg >> ce.hi) & 1;
      if (loNeg == hiNeg) continue;
      const std::uint64_t key = ((cell + cornerOffset(ce.lo)) << 3) | std::uint64_t(ce.lo ^ ce.hi);
      bool inserted;
      local[std::size_t(e)] = m.edgeIndex.insert(key, std::uint32_t(m.edges.size()), inserted);
      if (!inserted) continue;
      const int n = loNeg ? ce.lo : ce.hi, p = loNeg ? ce.hi : ce.lo;
      m.edges.push_back({corner[n], corner[p], cell + cornerOffset(n),
                         cell + cornerOffset(p)});
    }
    for (int t = 0; t < 6; ++t) {
      const TetPiece& piece = tetPiece(t, neg);
      if (piece.count == 3) {
        m.triangles.push_back({local[piece.edges[0]], local[piece.edges[1]], local[piece.edges[2]]});
      } else if (piece.count == 4) {
        m.quads.push_back({local[piece.edges[0]], local[piece.edges[1]], local[piece.edges[2]],
                           local[piece.edges[3]]});
      }
    }
  }
  return m;
}

namespace {

std::array<float, 3> unit(const P3& g, const std::array<float, 3>& fallback) {
  const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (!(len > 0) || !std::isfinite(len)) return fallback;
  return {float(g[0] / len), float(g[1] / len), float(g[2] / len)};
}

double dist2(const P3& a, const P3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace

double placeRoots(const Grid& grid, const Marched& marched, std::span<FieldEvaluator> evaluators,
                  Mesh& mesh) {
  const std::size_t n = marched.edges.size();
  mesh.positions.resize(n);
  mesh.normals.resize(n);
  mesh.kinds.resize(n);
  const std::size_t threads = std::min<std::size_t>(evaluators.size(), n / 1024 + 1);
  std::vector<double> worst(threads, 0.0);
  auto work = [&](std::size_t t) {
    FieldEvaluator& ev = evaluators[t];
    for (std::size_t i = t; i < n; i += threads) {
      const GridEdge& e = marched.edges[i];
      const P3 a = grid.position(e.negativeKey), b = grid.position(e.positiveKey);
      const FieldEvaluator::Root r = ev.rootOnEdge(a, b, grid.value(e.negative), grid.value(e.positive));
      mesh.positions[i] = r.position;
      // Where the gradient vanishes or is undefined, the edge's direction (negative to
      // positive) still points out of the solid.
      const std::array<float, 3> along = unit({b[0] - a[0], b[1] - a[1], b[2] - a[2]}, {0, 0, 1});
      mesh.normals[i] = unit(r.gradient, along);
      mesh.kinds[i] = r.onBall ? VertexKind::Cap : VertexKind::Surface;
      if (!r.onBall) worst[t] = std::max(worst[t], r.residual);
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
  }
  double w = 0;
  for (double x : worst) w = std::max(w, x);
  return w;
}

void addTriangles(const Marched& marched, Mesh& mesh) {
  mesh.triangles.reserve(mesh.triangles.size() + marched.triangles.size() + 2 * marched.quads.size());
  mesh.triangles.insert(mesh.triangles.end(), marched.triangles.begin(), marched.triangles.end());
  for (const auto& q : marched.quads) {
    // Either diagonal keeps both triangles inside the tetrahedron; the shorter one gives
    // better-shaped triangles.
    if (dist2(mesh.positions[q[0]], mesh.positions[q[2]]) <= dist2(mesh.positions[q[1]], mesh.positions[q[3]])) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      mesh.triangles.push_back({q[0], q[1], q[3]});
      mesh.triangles.push_back({q[1], q[2], q[3]});
    }
  }
}

void dropUnusedVertices(Mesh& mesh) {
  std::vector<std::uint32_t> remap(mesh.positions.size(), FlatIndex::kAbsent);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) remap[v] = 0;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == FlatIndex::kAbsent) continue;
    remap[v] = next;
    mesh.positions[next] = mesh.positions[v];
    mesh.normals[next] = mesh.normals[v];
    mesh.kinds[next] = mesh.kinds[v];
    ++next;
  }
  mesh.positions.resize(next);
  mesh.normals.resize(next);
  mesh.kinds.resize(next);
  for (auto& t : mesh.triangles)
    for (std::uint32_t& v : t) v = remap[v];
}

}  // namespace zs::mesh
