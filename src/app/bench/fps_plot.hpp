#pragma once
// The picture of `zeroset bench`: takes BenchResults, puts out a PNG-ready Image of median
// fps (log scale) against octree level, one colored line per thesis surface (legend: the
// surface's thesis number), at 10 intervals and epsilon 0.001, with the 60 fps goal drawn
// dashed. Drawn with canvas.hpp; configurations that failed are left out of their line.
#include "app/bench/bench_runner.hpp"
#include "render/image.hpp"

namespace zs::bench {

Image fpsByLevelPlot(const BenchResults& results, int width = 720, int height = 480);

}  // namespace zs::bench
