// The surface worker's later step (session/surface_worker.hpp) and the shader warmer's two
// phases (app/shader_warmer.hpp): a new program's beam pass and tile mask are left out of the
// warm-up that the front end's first picture waits for, and compiled after a pause.
#include "session/surface_worker.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <variant>

#include "app/shader_warmer.hpp"
#include "pipeline/pipeline.hpp"

namespace zs::app {
namespace {

using namespace std::chrono_literals;

Scene sceneOf(const std::string& formula) {
  Scene s;
  s.formula = formula;
  s.width = 64;
  s.height = 48;
  return s;
}

using session::BuildRequest;
using session::SurfaceWorker;

// Submits a fresh build of `scene` and waits for its result.
SurfaceWorker::Result buildOn(SurfaceWorker& worker, const Scene& scene) {
  static std::uint64_t nextId = 1;
  const std::uint64_t id = nextId++;
  worker.submit(BuildRequest{id, scene, invalidates::Surface, nullptr});
  for (;;) {
    if (auto r = worker.take(); r && r->build.id == id) return std::move(*r);
    std::this_thread::sleep_for(1ms);
  }
}

TEST(SurfaceWorker, TheLaterStepRunsAfterAPauseInTheRequestsAndOnlyForABuild) {
  std::atomic<int> later{0};
  std::string formula;
  SurfaceWorker worker({}, {}, {}, {}, [&](const Scene& s) {
    formula = s.formula;
    ++later;
  });
  // A build, then at once another: only the second gets the later step, after the pause.
  const auto start = std::chrono::steady_clock::now();
  buildOn(worker, sceneOf("x^2 + y^2 + z^2 - 1"));
  buildOn(worker, sceneOf("x^2 + y^2 - z"));
  EXPECT_EQ(later.load(), 0);
  while (later.load() == 0 && std::chrono::steady_clock::now() - start < 10s)
    std::this_thread::sleep_for(1ms);
  EXPECT_GE(std::chrono::steady_clock::now() - start, SurfaceWorker::kLaterDelay);
  EXPECT_EQ(later.load(), 1);
  EXPECT_EQ(formula, "x^2 + y^2 - z");
  // A build that fails has nothing to warm.
  const SurfaceWorker::Result failed = buildOn(worker, sceneOf("x^2 +"));
  EXPECT_TRUE(std::holds_alternative<std::string>(failed.build.surface));
  std::this_thread::sleep_for(SurfaceWorker::kLaterDelay + 250ms);
  EXPECT_EQ(later.load(), 1);
}

TEST(ShaderWarmer, ANewBeamProgramsPassesWaitForWarmPasses) {
  ShaderWarmer warmer(ShaderWarmer::Target::Offscreen, Backend::Egl);
  const Scene interval = sceneOf("sin(3*x) + y^2 + z^2 - 1");  // not a polynomial: a beam
  auto prepared = prepareSurface(interval);
  ASSERT_TRUE(std::holds_alternative<PreparedSurface>(prepared)) << std::get<std::string>(prepared);
  const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
  ASSERT_EQ(surface.method, TracingMethod::Interval);
  warmer.warm(interval, surface);
  EXPECT_FALSE(warmer.passesWarm(ShaderWarmer::programKey(surface.fragmentShader)));
  warmer.warmPasses(interval);
  EXPECT_TRUE(warmer.passesWarm(ShaderWarmer::programKey(surface.fragmentShader)));
  // The same program again (a new parameter value, octree level): its passes stay warm.
  warmer.warm(interval, surface);
  EXPECT_TRUE(warmer.passesWarm(ShaderWarmer::programKey(surface.fragmentShader)));
  // A polynomial's Bernstein program has no beam: nothing to wait for.
  const Scene polynomial = sceneOf("x^2 + y^2 + z^2 - 1");
  auto bernstein = prepareSurface(polynomial);
  ASSERT_TRUE(std::holds_alternative<PreparedSurface>(bernstein));
  warmer.warm(polynomial, std::get<PreparedSurface>(bernstein));
  EXPECT_TRUE(warmer.passesWarm(
      ShaderWarmer::programKey(std::get<PreparedSurface>(bernstein).fragmentShader)));
  warmer.stop();
}

}  // namespace
}  // namespace zs::app
