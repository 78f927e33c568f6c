// buildMesh: the octree's leaves seed the sparse grid, the grid is closed and marched, the
// vertices go onto their edges' roots, then the domain's boundary is capped or cut.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "expr/derivative.hpp"
#include "mesh/march.hpp"

namespace zs {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// The bricks (of b^3 cells) holding the grid cells the sphere passes through (a capped
// ball's cap lies there), column by column, each brick once, in the order first met:
// generous by a cell on each side, which only costs a few evaluations.
std::vector<std::uint64_t> bricksOnSphere(const Box& box, int level, std::uint32_t b,
                                          const Ball& ball) {
  const std::uint32_t n = 1u << level;
  std::array<double, 3> h{};
  for (std::size_t a = 0; a < 3; ++a) h[a] = (box.max[a] - box.min[a]) / n;
  auto nearest = [](double lo, double hi, double c) {
    return c < lo ? lo - c : (c > hi ? c - hi : 0.0);
  };
  auto farthest = [](double lo, double hi, double c) {
    return std::max(std::abs(lo - c), std::abs(hi - c));
  };
  std::vector<std::uint64_t> bricks;
  mesh::FlatIndex seen(1 << 12);
  const double r2 = ball.radius * ball.radius;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double x0 = box.min[0] + h[0] * i, x1 = x0 + h[0];
    for (std::uint32_t j = 0; j < n; ++j) {
      const double y0 = box.min[1] + h[1] * j, y1 = y0 + h[1];
      const double near2 = std::pow(nearest(x0, x1, ball.center[0]), 2) +
                           std::pow(nearest(y0, y1, ball.center[1]), 2);
      const double far2 = std::pow(farthest(x0, x1, ball.center[0]), 2) +
                          std::pow(farthest(y0, y1, ball.center[1]), 2);
      if (near2 > r2 * (1 + 1e-9)) continue;
      // z cells with some point within r, minus those wholly inside the ball.
      const double reach = std::sqrt(r2 - std::min(near2, r2));
      const double zc = (ball.center[2] - box.min[2]) / h[2];
      const long k0 = std::max(0L, long(std::floor(zc - reach / h[2])) - 1);
      const long k1 = std::min(long(n) - 1, long(std::floor(zc + reach / h[2])) + 1);
      for (long k = k0; k <= k1; ++k) {
        const double z0 = box.min[2] + h[2] * double(k), z1 = z0 + h[2];
        if (far2 + std::pow(farthest(z0, z1, ball.center[2]), 2) < r2 * (1 - 1e-9)) continue;
        const std::uint64_t brick = mesh::packKey(i / b, j / b, std::uint64_t(k) / b);
        bool inserted;
        seen.insert(brick, 0, inserted);
        if (inserted) bricks.push_back(brick);
      }
    }
  }
  return bricks;
}

}  // namespace

std::variant<MeshResult, std::string> buildMesh(const Formula& formula,
                                                std::span<const double> params, const Box& box,
                                                std::optional<Ball> ball,
                                                const MeshSettings& settings,
                                                const MeshProgress& progress) {
  if (settings.level < 1 || settings.level > kMaxMeshLevel)
    return "mesh level must be between 1 and " + std::to_string(kMaxMeshLevel) + ", got " +
           std::to_string(settings.level);
  if (formula.root == kNoNode) return std::string("the formula is empty");
  auto say = [&](const std::string& line) {
    if (progress) progress(line);
  };
  const auto start = Clock::now();
  MeshResult result;
  MeshStats& stats = result.stats;
  const unsigned threads = std::max(1u, settings.threads);

  // The octree stops two levels above the grid: its boxes there are the grid's bricks.
  OctreeSettings os;
  os.level = mesh::brickLevel(settings.level);
  os.criteria = Criteria::Uniform;
  os.nodeBudget = settings.nodeBudget;
  os.threads = threads;
  OctreeResult built = buildOctree(formula, params, box, os, ball);
  if (auto* err = std::get_if<OctreeError>(&built)) return err->message;
  const Octree& tree = std::get<Octree>(built);
  stats.octreeSeconds = tree.buildSeconds;
  const std::uint32_t n = 1u << settings.level;
  stats.cellSize = std::min({(box.max[0] - box.min[0]) / n, (box.max[1] - box.min[1]) / n,
                             (box.max[2] - box.min[2]) / n});
  say(format("octree: level %d, %zu boxes may hold the surface (%.3f s)", os.level,
             tree.leaves.size(), tree.buildSeconds));

  Graph graph = formula.graph;
  const std::array<NodeId, 3> grad = gradient(graph, formula.root);
  const Tape valueTape = compileTape(graph, {formula.root});
  const Tape gradientTape = compileTape(graph, {formula.root, grad[0], grad[1], grad[2]});
  const std::optional<Ball> capBall = settings.cap ? ball : std::nullopt;
  std::vector<mesh::FieldEvaluator> evaluators;
  for (unsigned t = 0; t < threads; ++t)
    evaluators.emplace_back(valueTape, gradientTape, params, capBall);

  auto t0 = Clock::now();
  const mesh::Grid grid(box, settings.level);
  std::vector<std::uint64_t> seeds;
  seeds.reserve(tree.leaves.size());
  for (const OctreeLeaf& leaf : tree.leaves)
    seeds.push_back(mesh::packKey(leaf.cell[0], leaf.cell[1], leaf.cell[2]));
  const bool capBoxFaces = settings.cap && !ball;
  if (capBall) {
    const auto onSphere = bricksOnSphere(box, settings.level, grid.brickCells(), *ball);
    seeds.insert(seeds.end(), onSphere.begin(), onSphere.end());
  }
  std::optional<mesh::BoxFaces> boxFaces;
  if (capBoxFaces) {
    boxFaces.emplace(grid, evaluators.front());
    const auto beside = boxFaces->bricksBesideCrossedSquares();
    seeds.insert(seeds.end(), beside.begin(), beside.end());
  }
  const mesh::Marched marched = mesh::marchBricks(grid, std::move(seeds), evaluators);
  stats.gridValues = marched.bricks * grid.brickCornerCount();
  stats.cells = marched.cells;
  stats.gridSeconds = since(t0);
  say(
      format("grid: %zu bricks of %u^3 cells, F at %zu corners, %zu cells and %zu edges cross the "
             "surface (%.3f s)",
             marched.bricks, grid.brickCells(), stats.gridValues, stats.cells, marched.edges.size(),
             stats.gridSeconds));

  t0 = Clock::now();
  Mesh& out = result.mesh;
  stats.maxResidual = mesh::placeRoots(grid, marched, evaluators, out);
  mesh::addTriangles(marched, out);
  if (boxFaces) mesh::capBox(grid, *boxFaces, marched, out);
  // Sign changes without a root bound the capped solid; they are not part of F = 0.
  stats.poleVertices =
      std::size_t(std::count(out.kinds.begin(), out.kinds.end(), VertexKind::Pole));
  if (!settings.cap) mesh::dropPoleTriangles(out);
  // Without a cap the evaluators' field is F itself.
  if (ball && !settings.cap) mesh::clipBall(*ball, stats.cellSize, evaluators.front(), out);
  mesh::dropUnusedVertices(out);
  stats.rootSeconds = since(t0);
  stats.totalSeconds = since(start);
  say(format("surface: %zu vertices on their edges' roots, %zu triangles (%.3f s)",
             out.positions.size(), out.triangles.size(), stats.rootSeconds));
  if (stats.poleVertices > 0)
    say(format(
        "%zu grid edges change sign without a root (a pole, a jump or the edge of F's domain): %s",
        stats.poleVertices,
        settings.cap ? "they bound the capped solid" : "not part of the surface, left out"));
  return result;
}

}  // namespace zs
