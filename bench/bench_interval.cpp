// Interval evaluations per second for the seven thesis surfaces (F alone, and F with its
// gradient in one pass), octree build times at levels 2, 4, 6, 8 with both criteria, and the
// surface's bounds (the exact tracers' ray clip) for surfaces that fill their domain or not.
// Results and the machine they ran on: docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <string_view>
#include <variant>

#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "interval/octree.hpp"
#include "interval/surface_bounds.hpp"
#include "interval/tape_eval.hpp"
#include "parser/parser.hpp"

namespace zs {
namespace {

constexpr std::array<std::string_view, 7> kSurfaces = {
    "x^2+z^2-y",
    "x^2*y+x^2*z+y^2*x+y^2*z+z^2*y+z^2*x-(2/5)*(x*y+x*z+y*z)",
    "x^4+y^4+z^4-1",
    "x^2+y^3+z^5-1",
    "x^3*y+y^3*z+z^3*x",
    "x^4-z^4-y",
    "x^2*y^2+y^2*z^2+z^2*x^2-1",
};

const Box kDomain{{-2, -2, -2}, {2, 2, 2}};

Formula parse(std::string_view text) {
  return std::get<Formula>(parseFormula(text));
}

// Boxes the size of octree cells at levels 3..8 inside the domain, as the build sees them.
std::vector<Box> randomBoxes(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 4.0 / double(1 << (3 + i % 6));
    for (std::size_t a = 0; a < 3; ++a) {
      boxes[i].min[a] = u(rng);
      boxes[i].max[a] = boxes[i].min[a] + w;
    }
  }
  return boxes;
}

void intervalEval(benchmark::State& state, bool withGradient) {
  Formula f = parse(kSurfaces[std::size_t(state.range(0))]);
  std::vector<NodeId> roots{f.root};
  if (withGradient) {
    const auto g = gradient(f.graph, f.root);
    roots.insert(roots.end(), g.begin(), g.end());
  }
  const Tape tape = compileTape(f.graph, roots);
  IntervalEvaluator ev(tape);
  const std::vector<Box> boxes = randomBoxes(4096);
  std::array<Interval, 4> out;
  std::size_t i = 0;
  for (auto _ : state) {
    ev.eval(boxes[i++ % boxes.size()], {}, std::span(out.data(), roots.size()));
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()));
  state.counters["tape"] = double(tape.code.size());
}

void BM_IntervalF(benchmark::State& state) {
  intervalEval(state, false);
}
void BM_IntervalFAndGradient(benchmark::State& state) {
  intervalEval(state, true);
}
BENCHMARK(BM_IntervalF)->DenseRange(0, 6);
BENCHMARK(BM_IntervalFAndGradient)->DenseRange(0, 6);

// Args: surface, level, criteria (0 thesis, 1 uniform). Both cores (threads = 0).
void BM_Octree(benchmark::State& state) {
  const Formula f = parse(kSurfaces[std::size_t(state.range(0))]);
  OctreeSettings st;
  st.level = int(state.range(1));
  st.criteria = state.range(2) == 0 ? Criteria::Thesis : Criteria::Uniform;
  std::size_t leaves = 0, tested = 0;
  for (auto _ : state) {
    OctreeResult r = buildOctree(f, {}, kDomain, st);
    const Octree& t = std::get<Octree>(r);
    leaves = t.leaves.size();
    tested = t.testedCount();
  }
  state.counters["leaves"] = double(leaves);
  state.counters["tested"] = double(tested);
}
BENCHMARK(BM_Octree)
    ->ArgsProduct({benchmark::CreateDenseRange(0, 6, 1), {2, 4, 6, 8}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();  // the CPU column then counts both worker threads

// The unit sphere with the uniform criterion: leaves should grow ~4x per level (area).
void BM_UniformSphere(benchmark::State& state) {
  const Formula f = parse("x^2+y^2+z^2-1");
  OctreeSettings st;
  st.level = int(state.range(0));
  st.criteria = Criteria::Uniform;
  std::size_t leaves = 0;
  for (auto _ : state) leaves = std::get<Octree>(buildOctree(f, {}, kDomain, st)).leaves.size();
  state.counters["leaves"] = double(leaves);
}
BENCHMARK(BM_UniformSphere)
    ->DenseRange(2, 10)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// The surface's bounds at their default level and budget. Args: index into the list below.
// The worst case is a face of the surface parallel to the domain's, flat like z = 0.3: a
// whole layer of cells below it is evaluated before the bound moves past it.
constexpr std::array<std::string_view, 6> kBoundsSurfaces = {
    "x^4+y^4+z^4-1",
    "x^2*y^2+y^2*z^2+z^2*x^2-1",
    "sqrt(x^2+y^2+z^2)-1-0.08*sin(10*x)*sin(10*y)*sin(10*z)",
    "exp(-4*((x-0.5)^2+y^2+z^2))+exp(-4*((x+0.5)^2+y^2+z^2))+exp(-4*(x^2+(y-0.7)^2+z^2))-0.6",
    "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)",
    "z-0.3",
};
void BM_SurfaceBounds(benchmark::State& state) {
  const Formula f = parse(kBoundsSurfaces[std::size_t(state.range(0))]);
  Box b;
  for (auto _ : state) {
    b = surfaceBounds(f, {}, kDomain, std::nullopt);
    benchmark::DoNotOptimize(b);
  }
  state.counters["xmax"] = b.max[0];
}
BENCHMARK(BM_SurfaceBounds)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace zs
