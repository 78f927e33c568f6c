#include "app/bench/bench_plan.hpp"

#include <algorithm>
#include <cstdio>
#include <tuple>

#include "app/bench/thesis_data.hpp"

namespace zs::bench {

BenchOptions quickOptions(BenchOptions base) {
  base.width = 160;
  base.height = 120;
  base.frames = 3;
  base.warmup = 1;
  base.maxLevel = 2;
  base.quick = true;
  base.levelsOnly = true;
  return base;
}

std::vector<BenchConfig> benchPlan(const BenchOptions& options) {
  std::vector<BenchConfig> plan;
  for (const ThesisSurface& s : kThesisSurfaces) {
    if (options.levelsOnly) {
      for (int level = 0; level <= options.maxLevel; ++level)
        plan.push_back({s.number, level, kTable53Intervals, kTable52Epsilon});
      continue;
    }
    for (int level : kThesisLevels) {
      if (level > options.maxLevel) continue;
      for (int intervals : kTable52Intervals)
        plan.push_back({s.number, level, intervals, kTable52Epsilon});
      for (double epsilon : kTable53Epsilons)
        plan.push_back({s.number, level, kTable53Intervals, epsilon});
    }
    for (int level = 3; level <= options.maxLevel; ++level)
      plan.push_back({s.number, level, kTable53Intervals, kTable52Epsilon});
  }
  // The exact method beside it (intervals and epsilon are the sampling method's knobs; epsilon
  // also ends bernstein's refinement, so it stays the thesis' recommended 0.001).
  for (const ThesisSurface& s : kThesisSurfaces)
    for (int level = 0; level <= options.maxLevel; ++level)
      plan.push_back(
          {s.number, level, kTable53Intervals, kTable52Epsilon, TracingMethod::Bernstein});
  const auto key = [](const BenchConfig& c) {
    // Larger epsilon first: the order the thesis' Table 5.3 lists its columns.
    return std::make_tuple(c.surface, int(c.method), c.level, c.intervals, -c.epsilon);
  };
  std::sort(plan.begin(), plan.end(),
            [&](const BenchConfig& a, const BenchConfig& b) { return key(a) < key(b); });
  plan.erase(std::unique(plan.begin(), plan.end()), plan.end());
  return plan;
}

std::string formatEpsilon(double epsilon) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", epsilon);
  std::string s = text;
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

}  // namespace zs::bench
