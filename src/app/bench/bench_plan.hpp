#pragma once
// What `zeroset bench` measures: takes the options from the command line, puts out the
// list of configurations (surface, octree level, intervals, epsilon) to time, ordered so
// each surface's shader is compiled once and each octree level is built once. The full
// plan is the union of the thesis' Table 5.2 grid (levels 0-2 x 10/15/20 intervals at
// epsilon 0.001), its Table 5.3 grid (levels 0-2 x epsilon 0.01/0.001/0.0001 at 10
// intervals) and deeper levels 3..maxLevel at the thesis' recommended 10 intervals and
// epsilon 0.001. The levels plan keeps only that last series, levels 0..maxLevel at 10
// intervals / epsilon 0.001 (quick mode for CI uses it with levels 0-2): on a software
// rasterizer a full frame can take a second, and the full plan is ~20 frames x 133 cells.
// The thesis' cells are timed with the thesis' method (sampling); both plans add the levels
// series once more with the exact method (bernstein, the default for polynomials), so the
// two stand side by side.
#include <string>
#include <vector>

#include "render/gl_context.hpp"
#include "render/settings.hpp"

namespace zs::bench {

struct BenchOptions {
  int width = 800;
  int height = 600;
  int frames = 20;          // timed frames per configuration (the median is reported)
  int warmup = 3;           // untimed frames first: first use of a hierarchy, caches, clocks
  int maxLevel = 6;         // deepest octree level timed
  bool quick = false;       // the CI settings (quickOptions)
  bool levelsOnly = false;  // the levels plan instead of the full one
  Backend backend = Backend::Egl;
  std::string outDir = "bench-results";
};

// The CI settings: small frames, few of them, the small plan.
BenchOptions quickOptions(BenchOptions base);

struct BenchConfig {
  int surface = 1;  // thesis numbering, 1..7
  int level = 0;
  int intervals = 10;
  double epsilon = 0.001;
  TracingMethod method = TracingMethod::Sampling;  // the thesis' tables are sampling's

  bool operator==(const BenchConfig&) const = default;
};

// Sorted by surface, then method, then level, then intervals, then epsilon; no duplicates (the cell
// "10 intervals, epsilon 0.001" is in both thesis tables and is timed once).
std::vector<BenchConfig> benchPlan(const BenchOptions& options);

// "0.001" rather than "1e-03": epsilons as the thesis prints them.
std::string formatEpsilon(double epsilon);

}  // namespace zs::bench
