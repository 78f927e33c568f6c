// What a hover read-out costs: `SceneProbe::pixel` (src/probe), which the viewer and the web
// page call under the pointer and `zeroset probe` once, on the seven thesis scenes
// (examples/thesis/N.surf, their own domain and camera) at 800 x 600. The argument is the
// surface (1..7). BM_ProbePixel cycles through the pixels of a 16 x 12 grid over the
// picture, so hits, misses and silhouettes all count; BM_ProbePrepare is the one-time
// setup (parse, gradient, Hessian, tapes) when a scene is loaded.
// Run: build/bench/zs_bench_probe [--benchmark_filter=Pixel].
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <variant>

#include "probe/probe.hpp"
#include "scene/scene_io.hpp"

namespace {

constexpr int kWidth = 800, kHeight = 600, kColumns = 16, kRows = 12;

zs::Scene thesisScene(std::int64_t index) {
  const std::filesystem::path dir = std::filesystem::path(ZS_SOURCE_DIR) / "examples" / "thesis";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(std::to_string(index) + "-", 0) != 0) continue;
    zs::SceneResult r = zs::loadScene(entry.path());
    if (auto* scene = std::get_if<zs::Scene>(&r)) return std::move(*scene);
    break;
  }
  std::fprintf(stderr, "no thesis scene %lld in %s\n", static_cast<long long>(index), dir.c_str());
  std::abort();
}

void BM_ProbePrepare(benchmark::State& state) {
  const zs::Scene scene = thesisScene(state.range(0));
  for (auto _ : state) {
    zs::SceneProbe probe(scene);
    benchmark::DoNotOptimize(probe.error());
  }
  state.SetLabel(scene.formula);
}

void BM_ProbePixel(benchmark::State& state) {
  const zs::Scene scene = thesisScene(state.range(0));
  zs::SceneProbe probe(scene);
  if (!probe.error().empty()) {
    state.SkipWithError(probe.error().c_str());
    return;
  }
  int k = 0, hits = 0, probes = 0;
  for (auto _ : state) {
    const int x = (k % kColumns) * kWidth / kColumns + kWidth / (2 * kColumns);
    const int y = (k / kColumns % kRows) * kHeight / kRows + kHeight / (2 * kRows);
    auto r = probe.pixel(scene, kWidth, kHeight, x, y);
    if (auto* result = std::get_if<zs::ProbeResult>(&r)) hits += result->hit;
    ++probes;
    ++k;
  }
  state.counters["hit share"] = probes ? double(hits) / probes : 0.0;
  state.SetLabel(scene.formula);
}

BENCHMARK(BM_ProbePrepare)->DenseRange(1, 7)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProbePixel)->DenseRange(1, 7)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
