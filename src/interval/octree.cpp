// The octree build. The top levels run on one thread and hand out the boxes at level
// kSplitLevel as tasks; worker threads take tasks from a shared counter (parallelFor) and
// walk each subtree depth-first with an explicit stack. Task results are joined in task order, so
// the leaves come out in the same pre-order whatever the thread count or timing.
#include "interval/octree.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "interval/parallel.hpp"
#include "interval/tape_eval.hpp"

namespace zs {

namespace {

constexpr int kSplitLevel = 2;              // 64 tasks: enough to keep 2..16 cores busy
constexpr std::size_t kBudgetBatch = 1024;  // tested boxes counted locally before sharing

struct Cell {
  int level = 0;
  std::array<std::uint32_t, 3> c{};
};

enum class Decision { Discard, Leaf, Subdivide };

struct Shared {
  const Tape& tape;
  std::span<const double> params;
  const Box& domain;
  const OctreeSettings& settings;
  std::optional<Ball> ball;
  std::atomic<std::size_t> tested{0};
  std::atomic<bool> overBudget{false};
};

// One thread's evaluator, statistics and budget share.
class Walker {
 public:
  explicit Walker(Shared& s) : s_(s), eval_(s.tape), stats_(std::size_t(s.settings.level) + 1) {}

  Decision decide(const Cell& cell) {
    LevelStats& st = stats_[std::size_t(cell.level)];
    ++st.tested;
    if (++unshared_ == kBudgetBatch) flushBudget();
    const Box box = cellBox(s_.domain, cell.c, cell.level);
    if (s_.ball && boxOutsideBall(box, *s_.ball)) return Decision::Discard;
    const Interval f = eval_.evalFirst(box, s_.params);
    // Empty: F is defined nowhere in the box, so no surface point lies in it.
    if (f.isEmpty() || !f.containsZero()) return Decision::Discard;
    ++st.kept;
    Decision d = Decision::Subdivide;
    if (cell.level == s_.settings.level) {
      d = Decision::Leaf;
    } else if (s_.settings.criteria == Criteria::Thesis) {
      std::array<Interval, 4> out;
      eval_.evalRest(s_.params, out);
      // An undefined gradient component proves nothing, so it does not stop subdivision.
      for (int k = 1; k < 4; ++k)
        if (!out[std::size_t(k)].isEmpty() && !out[std::size_t(k)].containsZero())
          d = Decision::Leaf;
    }
    if (d == Decision::Leaf) ++st.leaves;
    return d;
  }

  // Depth-first from `root`; appends the kept leaves in pre-order.
  void walk(const Cell& root, std::vector<OctreeLeaf>& leaves, int stopLevel,
            std::vector<Cell>* tasks) {
    std::vector<Cell> stack{root};
    while (!stack.empty() && !s_.overBudget.load(std::memory_order_relaxed)) {
      const Cell cell = stack.back();
      stack.pop_back();
      if (tasks && cell.level == stopLevel) {
        tasks->push_back(cell);
        // A placeholder (level -1, cell[0] = task index) keeps the task's place in pre-order.
        leaves.push_back({{}, -1, {std::uint32_t(tasks->size() - 1), 0, 0}});
        continue;
      }
      const Decision d = decide(cell);
      if (d == Decision::Leaf)
        leaves.push_back({cellBox(s_.domain, cell.c, cell.level), cell.level, cell.c});
      if (d != Decision::Subdivide) continue;
      for (int child = 7; child >= 0; --child) {  // reversed, so child 0 is walked first
        Cell ch{cell.level + 1, {}};
        for (int axis = 0; axis < 3; ++axis)
          ch.c[std::size_t(axis)] =
              2 * cell.c[std::size_t(axis)] + std::uint32_t((child >> axis) & 1);
        stack.push_back(ch);
      }
    }
  }

  void flushBudget() {
    const std::size_t total = s_.tested.fetch_add(unshared_) + unshared_;
    unshared_ = 0;
    if (total > s_.settings.nodeBudget) s_.overBudget = true;
  }

  const std::vector<LevelStats>& stats() const { return stats_; }

 private:
  Shared& s_;
  IntervalEvaluator eval_;
  std::vector<LevelStats> stats_;
  std::size_t unshared_ = 0;
};

std::string checkInput(const Formula& formula, std::span<const double> params, const Box& domain,
                       const OctreeSettings& settings) {
  if (settings.level < 0 || settings.level > kMaxOctreeLevel)
    return "octree level must be between 0 and " + std::to_string(kMaxOctreeLevel) + ", got " +
           std::to_string(settings.level);
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = domain.min[std::size_t(axis)], hi = domain.max[std::size_t(axis)];
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
      return std::string("domain ") + "xyz"[axis] + " range must be finite with min < max";
  }
  if (params.size() < formula.graph.params().size())
    return "the formula has " + std::to_string(formula.graph.params().size()) +
           " parameters but only " + std::to_string(params.size()) + " values were given";
  if (formula.root == kNoNode) return "the formula is empty";
  return {};
}

}  // namespace

bool boxOutsideBall(const Box& box, const Ball& ball) {
  double d2 = 0;  // squared distance from the center to the box's nearest point
  for (std::size_t a = 0; a < 3; ++a) {
    const double c = ball.center[a];
    const double gap = c < box.min[a] ? box.min[a] - c : (c > box.max[a] ? c - box.max[a] : 0.0);
    d2 += gap * gap;
  }
  return d2 > ball.radius * ball.radius * (1 + 1e-12);
}

std::size_t Octree::testedCount() const {
  std::size_t n = 0;
  for (const LevelStats& l : levels) n += l.tested;
  return n;
}

double cellCoordinate(const Box& domain, int axis, std::uint64_t k, int level) {
  const double lo = domain.min[std::size_t(axis)], hi = domain.max[std::size_t(axis)];
  const std::uint64_t n = std::uint64_t(1) << level;
  if (k == 0) return lo;
  if (k == n) return hi;  // exact far face, whatever rounding lo + w * t would do
  return lo + (hi - lo) * std::ldexp(double(k), -level);
}

Box cellBox(const Box& domain, const std::array<std::uint32_t, 3>& cell, int level) {
  Box b;
  for (int axis = 0; axis < 3; ++axis) {
    b.min[std::size_t(axis)] = cellCoordinate(domain, axis, cell[std::size_t(axis)], level);
    b.max[std::size_t(axis)] = cellCoordinate(domain, axis, cell[std::size_t(axis)] + 1u, level);
  }
  return b;
}

OctreeResult buildOctree(const Formula& formula, std::span<const double> params, const Box& domain,
                         const OctreeSettings& settings, std::optional<Ball> ball) {
  if (std::string err = checkInput(formula, params, domain, settings); !err.empty())
    return OctreeError{std::move(err)};
  if (ball && !(std::isfinite(ball->radius) && ball->radius > 0))
    return OctreeError{"the clipping sphere's radius must be a positive number"};
  const auto start = std::chrono::steady_clock::now();

  Graph graph = formula.graph;  // the gradient's nodes go into a private copy
  std::vector<NodeId> roots{formula.root};
  if (settings.criteria == Criteria::Thesis) {
    const std::array<NodeId, 3> g = gradient(graph, formula.root);
    roots.insert(roots.end(), g.begin(), g.end());
  }
  const Tape tape = compileTape(graph, roots);
  Shared shared{tape, params, domain, settings, ball};

  // Top levels on this thread; boxes reaching kSplitLevel become tasks (marked in `top`).
  const int split = std::min(kSplitLevel, settings.level);
  std::vector<OctreeLeaf> top;
  std::vector<Cell> tasks;
  Walker topWalker(shared);
  topWalker.walk(Cell{}, top, split, split < settings.level ? &tasks : nullptr);

#ifdef __EMSCRIPTEN__
  unsigned threads = 1;  // the web build has no threads (no SharedArrayBuffer without COOP/COEP)
#else
  unsigned threads = settings.threads ? settings.threads : std::thread::hardware_concurrency();
#endif
  threads = unsigned(workerCount(tasks.size(), threads));
  std::vector<std::vector<OctreeLeaf>> results(tasks.size());
  std::vector<Walker> walkers;  // one per worker: its own evaluator, statistics and budget share
  walkers.reserve(threads);
  for (unsigned t = 0; t < threads; ++t) walkers.emplace_back(shared);
  parallelFor(tasks.size(), threads, [&](std::size_t task, std::size_t worker) {
    walkers[worker].walk(tasks[task], results[task], 0, nullptr);
  });
  for (Walker& w : walkers) w.flushBudget();
  topWalker.flushBudget();
  if (shared.overBudget)
    return OctreeError{"octree build stopped: more than " + std::to_string(settings.nodeBudget) +
                       " boxes tested (the node budget) before reaching level " +
                       std::to_string(settings.level) +
                       "; lower the level, shrink the domain or raise the node budget"};

  Octree tree;
  tree.domain = domain;
  tree.ball = ball;
  tree.settings = settings;
  tree.threads = threads;
  tree.levels = topWalker.stats();
  for (const Walker& w : walkers) {
    const std::vector<LevelStats>& s = w.stats();
    for (std::size_t l = 0; l < s.size(); ++l) {
      tree.levels[l].tested += s[l].tested;
      tree.levels[l].kept += s[l].kept;
      tree.levels[l].leaves += s[l].leaves;
    }
  }
  for (const OctreeLeaf& leaf : top) {
    if (leaf.level >= 0) {
      tree.leaves.push_back(leaf);
    } else {
      auto& sub = results[leaf.cell[0]];
      tree.leaves.insert(tree.leaves.end(), sub.begin(), sub.end());
      std::vector<OctreeLeaf>().swap(sub);  // release as we go: the leaves can be large
    }
  }
  tree.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return tree;
}

}  // namespace zs
