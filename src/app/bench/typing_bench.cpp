#include "app/bench/typing_bench.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include "app/bench/bench_runner.hpp"
#include "app/shader_warmer.hpp"
#include "interact/trace_budget.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/quick_surface.hpp"
#include "render/gl_context.hpp"
#include "render/ray_tracer.hpp"
#include "render/view_target.hpp"
#include "session/session.hpp"
#include "session/surface_worker.hpp"

namespace zs::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

TypingResults runTypingBench(const Scene& base, const std::string& formula,
                             const BenchOptions& options) {
  TypingResults out;
  out.width = options.width;
  out.height = options.height;
  ContextResult ctx = createHeadlessContext(options.backend);
  if (!ctx.context) {
    out.error = ctx.error;
    return out;
  }
  // First pictures in a context of their own, as the viewer draws them (app/viewer/
  // surface_view.hpp says why).
  ContextResult first = createHeadlessContext(options.backend);
  if (!first.context) {
    out.error = first.error;
    return out;
  }
  // What a front end does once at start: the interpreters of the scene's method compiled
  // and drawn.
  const bool sampling = base.render.tracing.method == TracingMethod::Sampling;
  TapeInterpreters interpreters;
  ViewTarget firstTarget, warmTarget;
  // The interpreters' GL objects go while their context is current.
  struct FirstCurrentAtEnd {
    GlContext& context;
    ~FirstCurrentAtEnd() { context.makeCurrent(); }
  } firstCurrentAtEnd{*first.context};
  std::vector<unsigned char> pixels;
  auto start = Clock::now();
  Scene single = base;
  single.render = firstPictureSettings(base.render);
  const auto draw = [&](RayTracer& tracer, const Scene& scene) {
    app::drawInterpreterWarmUp(tracer, warmTarget, scene, out.width, out.height);  // as the viewer
  };
  // Both parts of the viewer's warm-up (the second runs in its background).
  std::string warmError = interpreters.warm(sampling, single, draw);
  if (warmError.empty()) warmError = interpreters.warmFilledPictures(sampling, single, draw);
  if (!warmError.empty()) {
    out.error = "the tape interpreter cannot draw this scene: " + warmError;
    return out;
  }
  out.interpreterMs = msSince(start);

  ctx.context->makeCurrent();
  RayTracer own;
  // The worker compiles and draws each formula's own shader in a context of its own first.
  app::ShaderWarmer warmer(app::ShaderWarmer::Target::Offscreen, options.backend);
  // The keystrokes go to a session, as the viewer's do: its first pictures' sizes, its build
  // requests (on the viewer's worker, with the viewer's warm-up).
  session::Session session;
  session.loadScene(base);
  session::SurfaceWorker worker(
      session.prepareOptions(), {},
      [&warmer](const Scene& s, const PreparedSurface& p) { warmer.warm(s, p); },
      [&warmer] { warmer.stop(); }, [&warmer](const Scene& s) { warmer.warmPasses(s); });
  ctx.context->makeCurrent();  // the worker's context loads its own entry points
  for (std::size_t n = 1; n <= formula.size(); ++n) {
    Keystroke key;
    key.text = formula.substr(0, n);
    start = Clock::now();
    if (std::string err = session.prepareQuick(key.text); !err.empty()) {
      key.note = err.substr(0, err.find('\n'));
      out.keys.push_back(key);
      continue;
    }
    const QuickSurface& surface = *session.quickSurface();
    key.quickCpuMs = surface.prepareMs;
    const int scale = session.quickScale(out.width, out.height);
    key.firstWidth = std::max(1, out.width / scale);
    key.firstHeight = std::max(1, out.height / scale);
    std::string error;
    first.context->makeCurrent();
    const auto drawStart = Clock::now();
    if (RayTracer* interpreter = interpreters.load(surface, error);
        interpreter && firstTarget.ensure(key.firstWidth, key.firstHeight)) {
      glBindFramebuffer(GL_FRAMEBUFFER, firstTarget.framebuffer());
      interpreter->draw(single.render, base.domain, key.firstWidth, key.firstHeight);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      firstTarget.readPixels(pixels);  // as the viewer does, to show it in the window's context
    }
    session.quickDrawn(msSince(drawStart), double(key.firstWidth) * key.firstHeight);
    key.firstMs = msSince(start);
    std::string buildError = session.setFormula(key.text);
    if (buildError.empty()) {
      if (std::optional<session::BuildRequest> request = session.takeBuildRequest()) {
        const std::uint64_t id = request->id;
        worker.submit(std::move(*request));
        std::optional<session::SurfaceWorker::Result> result;
        while (!(result = worker.take()) || result->build.id != id)
          std::this_thread::sleep_for(std::chrono::microseconds(200));
        buildError = session.finishBuild(std::move(result->build));
      }
    }
    if (!buildError.empty()) {
      key.note = buildError.substr(0, buildError.find('\n'));
      out.keys.push_back(key);
      continue;
    }
    const Scene& scene = session.scene();
    ctx.context->makeCurrent();
    const PreparedSurface& built = *session.surface();
    if (error.empty()) error = loadSurface(own, built, scene.render);
    own.setBeamPass(warmer.passesWarm(app::ShaderWarmer::programKey(built.fragmentShader)));
    if (error.empty()) error = own.drawOffscreen(scene.render, scene.domain, out.width, out.height);
    glFinish();
    key.finalMs = msSince(start);
    key.drawn = error.empty();
    key.note = error.substr(0, error.find('\n'));
    out.keys.push_back(key);
  }
  ctx.context->makeCurrent();  // the own tracer's GL objects go with their context
  return out;
}

std::string typingReport(const TypingResults& r) {
  std::string s;
  char line[512];
  std::snprintf(line, sizeof line,
                "Typing, one character at a time: first picture by the tape interpreter at half "
                "to an eighth of the size each way (as the viewer picks it from the first "
                "pictures' costs), final picture by the formula's own shader at %dx%d (compiled "
                "and warmed on a worker thread). The interpreters (polynomial and every "
                "operation) were compiled once before typing: %.0f ms.\n\n",
                r.width, r.height, r.interpreterMs);
  s += line;
  s += "| Typed | First picture ms | its size | of which CPU ms | Final picture ms | Note |\n"
       "|---|---:|---:|---:|---:|---|\n";
  std::vector<double> first, final;
  for (const Keystroke& k : r.keys) {
    if (k.drawn) {
      first.push_back(k.firstMs);
      final.push_back(k.finalMs);
      std::snprintf(line, sizeof line, "| `%s` | %.1f | %dx%d | %.1f | %.1f | %s |\n",
                    k.text.c_str(), k.firstMs, k.firstWidth, k.firstHeight, k.quickCpuMs, k.finalMs,
                    k.note.c_str());
    } else {
      std::snprintf(line, sizeof line, "| `%s` | | | | | not drawn: %s |\n", k.text.c_str(),
                    k.note.c_str());
    }
    s += line;
  }
  auto maxOf = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  };
  std::snprintf(
      line, sizeof line,
      "\n%zu of %zu keystrokes drawn.\n\ntyping: first picture median %.0f ms, max %.0f ms\n"
      "typing: final picture median %.0f ms, max %.0f ms\n",
      first.size(), r.keys.size(), median(first), maxOf(first), median(final), maxOf(final));
  return s + line;
}

}  // namespace zs::bench
