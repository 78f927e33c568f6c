#include "interval/surface_bounds.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "expr/tape.hpp"
#include "interval/tape_eval.hpp"

namespace zs {

namespace {

// Tape instructions one face's search may run: 2^20, about 5 ms of interval arithmetic.
constexpr std::size_t kWorkPerFace = std::size_t(1) << 20;

struct Candidate {
  double reach;  // how far the cell extends in the searched direction
  int level;
  std::array<std::uint32_t, 3> cell;
};

// Furthest reach first; among equals the deeper cell, so the search dives to the finest
// level instead of widening over a whole face layer of equal cells.
struct Later {
  bool operator()(const Candidate& a, const Candidate& b) const {
    return a.reach != b.reach ? a.reach < b.reach : a.level < b.level;
  }
};

// The extent reached along `axis` (upper face when `up`, else the negated lower face) by
// the furthest cell at settings.level that may hold F = 0; -infinity when none can.
double faceBound(IntervalEvaluator& eval, std::span<const double> params, const Box& domain,
                 const std::optional<Ball>& ball, const SurfaceBoundsSettings& settings,
                 std::size_t axis, bool up) {
  auto reachOf = [&](const Box& b) { return up ? b.max[axis] : -b.min[axis]; };
  std::priority_queue<Candidate, std::vector<Candidate>, Later> queue;
  queue.push({reachOf(domain), 0, {0, 0, 0}});
  std::size_t evaluations = 0;
  while (!queue.empty()) {
    const Candidate top = queue.top();
    // Out of budget: no cell still queued reaches further than this one.
    if (evaluations == settings.faceBudget) return top.reach;
    queue.pop();
    const Box box = cellBox(domain, top.cell, top.level);
    if (ball && boxOutsideBall(box, *ball)) continue;
    ++evaluations;
    const Interval f = eval.eval1(box, params);
    if (f.isEmpty() || !f.containsZero()) continue;  // as the octree decides
    if (top.level == settings.level) return top.reach;
    for (std::uint32_t child = 0; child < 8; ++child) {
      Candidate c{0.0, top.level + 1, {}};
      for (std::size_t a = 0; a < 3; ++a) c.cell[a] = 2 * top.cell[a] + ((child >> a) & 1u);
      c.reach = reachOf(cellBox(domain, c.cell, c.level));
      queue.push(c);
    }
  }
  return -std::numeric_limits<double>::infinity();
}

}  // namespace

Box surfaceBounds(const Formula& formula, std::span<const double> params, const Box& domain,
                  const std::optional<Ball>& ball, const SurfaceBoundsSettings& settings) {
  const Tape tape = compileTape(formula.graph, {formula.root});
  IntervalEvaluator eval(tape);
  SurfaceBoundsSettings s = settings;
  s.level = std::clamp(s.level, 0, kMaxOctreeLevel);
  // A huge formula gets fewer evaluations, so the search stays within a few tens of
  // milliseconds before the first frame; the bounds are only looser then.
  const std::size_t perFace = kWorkPerFace / std::max<std::size_t>(tape.code.size(), 1);
  s.faceBudget = std::clamp<std::size_t>(perFace, 1, std::max<std::size_t>(s.faceBudget, 1));
  Box out;
  for (std::size_t a = 0; a < 3; ++a) {
    out.max[a] = faceBound(eval, params, domain, ball, s, a, true);
    out.min[a] = -faceBound(eval, params, domain, ball, s, a, false);
  }
  if (isEmpty(out)) {  // one face found nothing: then no face can
    out.min = {1.0, 1.0, 1.0};
    out.max = {0.0, 0.0, 0.0};
  }
  return out;
}

}  // namespace zs
