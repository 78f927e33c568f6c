#include "mesh/march.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "interval/parallel.hpp"
#include "mesh/huge_pages.hpp"
#include "mesh/kuhn.hpp"

namespace zs::mesh {

std::uint64_t edgeKey(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);  // packed keys order like coords
  std::uint64_t axes = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (keyAxis(lo, axis) != keyAxis(hi, axis)) axes |= std::uint64_t(1) << axis;
  return edgeKeyAt(lo, int(axes));
}

namespace {

// What one run of consecutive bricks marched: its edges numbered locally, in the order met.
struct Chunk {
  std::vector<GridEdge> edges;
  std::vector<std::uint64_t> faceKeys;  // per edge: its edgeKey on a brick face, or kInside
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 4>> quads;
  std::vector<std::uint64_t> neighbours;  // bricks beside crossed faces, maybe taken already
  std::size_t cells = 0;
  static constexpr std::uint64_t kInside = ~std::uint64_t(0);

  void clear() {  // keeps the buffers
    edges.clear(), faceKeys.clear(), triangles.clear(), quads.clear(), neighbours.clear();
    cells = 0;
  }
};

constexpr std::size_t kChunkBricks = 64;

void marchChunk(const Grid& grid, std::span<const std::uint64_t> bricks, FieldEvaluator& evaluator,
                Chunk& out) {
  const auto& edges = cellEdges();
  const std::uint32_t b = grid.brickCells(), m = b + 1;
  const std::size_t stride[3] = {1, m, std::size_t(m) * m};
  std::array<std::size_t, 8> cornerAt{};
  for (int c = 0; c < 8; ++c)
    cornerAt[std::size_t(c)] =
        (c & 1) * stride[0] + ((c >> 1) & 1) * stride[1] + ((c >> 2) & 1) * stride[2];
  // Per brick: (corner, axes) -> local edge id, so a brick looks each edge up once.
  std::vector<std::uint32_t> seen(stride[2] * m * 8, FlatIndex::kAbsent);
  std::vector<std::size_t> touched;
  std::vector<double> values(grid.brickCornerCount());
  const double* v = values.data();
  for (std::uint64_t brick : bricks) {
    grid.evaluateBrick(brick, evaluator, values);
    grid.crossedNeighbours(brick, v, out.neighbours);
    const std::uint64_t origin = grid.brickOrigin(brick);
    for (std::uint32_t z = 0; z < b; ++z) {
      for (std::uint32_t y = 0; y < b; ++y) {
        for (std::uint32_t x = 0; x < b; ++x) {
          const std::size_t base = x + y * stride[1] + z * stride[2];
          int neg = 0;
          for (int c = 0; c < 8; ++c) neg |= int(v[base + cornerAt[std::size_t(c)]] < 0) << c;
          if (neg == 0 || neg == 0xff) continue;
          ++out.cells;
          const std::uint64_t cell = origin + packKey(x, y, z);
          std::array<std::uint32_t, kCellEdges> local{};
          for (int e = 0; e < kCellEdges; ++e) {
            const CellEdge ce = edges[std::size_t(e)];
            const bool loNeg = (neg >> ce.lo) & 1, hiNeg = (neg >> ce.hi) & 1;
            if (loNeg == hiNeg) continue;
            const int axes = ce.lo ^ ce.hi;
            const std::size_t at = (base + cornerAt[ce.lo]) * 8 + std::size_t(axes);
            std::uint32_t& slot = seen[at];
            if (slot == FlatIndex::kAbsent) {
              slot = std::uint32_t(out.edges.size());
              touched.push_back(at);
              const int n = loNeg ? ce.lo : ce.hi, p = loNeg ? ce.hi : ce.lo;
              out.edges.push_back({cell + cornerOffset(n), cell + cornerOffset(p),
                                   v[base + cornerAt[std::size_t(n)]],
                                   v[base + cornerAt[std::size_t(p)]]});
              // On a brick face: it stays in a plane x_a = 0 or b of the brick.
              const std::uint32_t lo[3] = {x + (ce.lo & 1), y + ((ce.lo >> 1) & 1),
                                           z + ((ce.lo >> 2) & 1)};
              bool onFace = false;
              for (int a = 0; a < 3; ++a)
                onFace |= !((axes >> a) & 1) && (lo[a] == 0 || lo[a] == b);
              out.faceKeys.push_back(onFace ? edgeKeyAt(cell + cornerOffset(ce.lo), axes)
                                            : Chunk::kInside);
            }
            local[std::size_t(e)] = slot;
          }
          for (int t = 0; t < 6; ++t) {
            const TetPiece& piece = tetPiece(t, neg);
            if (piece.count == 3) {
              out.triangles.push_back(
                  {local[piece.edges[0]], local[piece.edges[1]], local[piece.edges[2]]});
            } else if (piece.count == 4) {
              out.quads.push_back({local[piece.edges[0]], local[piece.edges[1]],
                                   local[piece.edges[2]], local[piece.edges[3]]});
            }
          }
        }
      }
    }
    for (std::size_t at : touched) seen[at] = FlatIndex::kAbsent;  // ready for the next brick
    touched.clear();
  }
}

// Appends a chunk: its face edges join the ones other bricks already numbered.
void merge(const Chunk& chunk, Marched& m) {
  std::vector<std::uint32_t> global(chunk.edges.size());
  for (std::size_t e = 0; e < chunk.edges.size(); ++e) {
    bool inserted = true;
    const std::uint32_t next = std::uint32_t(m.edges.size());
    global[e] = chunk.faceKeys[e] == Chunk::kInside
                    ? next
                    : m.edgeIndex.insert(chunk.faceKeys[e], next, inserted);
    if (inserted) m.edges.push_back(chunk.edges[e]);
  }
  for (const auto& t : chunk.triangles)
    m.triangles.push_back({global[t[0]], global[t[1]], global[t[2]]});
  for (const auto& q : chunk.quads)
    m.quads.push_back({global[q[0]], global[q[1]], global[q[2]], global[q[3]]});
  m.cells += chunk.cells;
}

}  // namespace

Marched marchBricks(const Grid& grid, std::vector<std::uint64_t> seeds,
                    std::span<FieldEvaluator> evaluators) {
  Marched m;
  FlatIndex taken(seeds.size());
  std::vector<std::uint64_t> wave;
  for (std::uint64_t k : seeds) {
    bool inserted;
    taken.insert(k, 0, inserted);
    if (inserted) wave.push_back(k);
  }
  // A wave is marched a group of chunks at a time, the group merged (in order) before the
  // next: the chunks' buffers are reused rather than allocated for every brick at once.
  constexpr std::size_t kGroupChunks = 32;
  std::vector<Chunk> group(kGroupChunks);
  std::vector<std::uint64_t> nextWave;
  while (!wave.empty()) {
    for (std::size_t groupStart = 0; groupStart < wave.size();
         groupStart += kGroupChunks * kChunkBricks) {
      const std::size_t bricks = std::min(kGroupChunks * kChunkBricks, wave.size() - groupStart);
      const std::size_t chunks = (bricks + kChunkBricks - 1) / kChunkBricks;
      parallelFor(chunks, evaluators.size(), [&](std::size_t c, std::size_t worker) {
        const std::size_t first = groupStart + c * kChunkBricks;
        group[c].clear();
        marchChunk(
            grid,
            std::span(wave).subspan(first, std::min(kChunkBricks, groupStart + bricks - first)),
            evaluators[worker], group[c]);
      });
      if (m.bricks == 0) {
        // Room for all the seeds' edges and faces at this group's rate, in advised storage.
        std::size_t edges = 0, triangles = 0, quads = 0;
        for (std::size_t c = 0; c < chunks; ++c)
          edges += group[c].edges.size(), triangles += group[c].triangles.size(),
              quads += group[c].quads.size();
        const double scale = 1.1 * double(wave.size()) / double(bricks);
        reserveHuge(m.edges, std::size_t(scale * double(edges)));
        reserveHuge(m.triangles, std::size_t(scale * double(triangles)));
        reserveHuge(m.quads, std::size_t(scale * double(quads)));
        m.edgeIndex.reserve(std::size_t(scale * double(edges)) / 2);
      }
      m.bricks += bricks;
      for (std::size_t c = 0; c < chunks; ++c) {
        merge(group[c], m);
        for (std::uint64_t k : group[c].neighbours) {
          bool inserted;
          taken.insert(k, 0, inserted);
          if (inserted) nextWave.push_back(k);
        }
      }
    }
    wave.swap(nextWave);
    nextWave.clear();
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
  reserveHuge(mesh.positions, n);
  reserveHuge(mesh.normals, n);
  reserveHuge(mesh.kinds, n);
  mesh.positions.resize(n);
  mesh.normals.resize(n);
  mesh.kinds.resize(n);
  // Work in blocks, so that the threads share it evenly and write disjoint parts.
  constexpr std::size_t kBlock = 4096;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  const std::size_t workers = workerCount(blocks, evaluators.size());
  std::vector<double> worst(workers, 0.0);
  struct Scratch {  // per worker, reused from block to block
    std::vector<FieldEvaluator::Edge> queries;
    std::vector<FieldEvaluator::Root> roots;
  };
  std::vector<Scratch> scratch(workers);
  parallelFor(blocks, workers, [&](std::size_t block, std::size_t worker) {
    auto& [queries, roots] = scratch[worker];
    const std::size_t first = block * kBlock, last = std::min(n, first + kBlock);
    queries.clear();
    for (std::size_t i = first; i < last; ++i) {
      const GridEdge& e = marched.edges[i];
      queries.push_back({grid.position(e.negativeKey), grid.position(e.positiveKey),
                         e.negativeValue, e.positiveValue});
    }
    roots.assign(queries.size(), {});
    evaluators[worker].rootsOnEdges(queries, roots);
    for (std::size_t i = first; i < last; ++i) {
      const FieldEvaluator::Edge& q = queries[i - first];
      const FieldEvaluator::Root& r = roots[i - first];
      mesh.positions[i] = r.position;
      // Where the gradient vanishes or is undefined, the edge's direction (negative to
      // positive) still points out of the solid.
      const std::array<float, 3> along =
          unit({q.b[0] - q.a[0], q.b[1] - q.a[1], q.b[2] - q.a[2]}, {0, 0, 1});
      mesh.normals[i] = unit(r.gradient, along);
      mesh.kinds[i] =
          r.onBall ? VertexKind::Cap : (r.pole ? VertexKind::Pole : VertexKind::Surface);
      if (mesh.kinds[i] == VertexKind::Surface) worst[worker] = std::max(worst[worker], r.residual);
    }
  });
  double w = 0;
  for (double x : worst) w = std::max(w, x);
  return w;
}

void addTriangles(const Marched& marched, Mesh& mesh) {
  reserveHuge(mesh.triangles,
              mesh.triangles.size() + marched.triangles.size() + 2 * marched.quads.size());
  mesh.triangles.insert(mesh.triangles.end(), marched.triangles.begin(), marched.triangles.end());
  for (const auto& q : marched.quads) {
    // Either diagonal keeps both triangles inside the tetrahedron; the shorter one gives
    // better-shaped triangles.
    if (dist2(mesh.positions[q[0]], mesh.positions[q[2]]) <=
        dist2(mesh.positions[q[1]], mesh.positions[q[3]])) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      mesh.triangles.push_back({q[0], q[1], q[3]});
      mesh.triangles.push_back({q[1], q[2], q[3]});
    }
  }
}

void dropPoleTriangles(Mesh& mesh) {
  std::erase_if(mesh.triangles, [&](const std::array<std::uint32_t, 3>& t) {
    return mesh.kinds[t[0]] == VertexKind::Pole || mesh.kinds[t[1]] == VertexKind::Pole ||
           mesh.kinds[t[2]] == VertexKind::Pole;
  });
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
