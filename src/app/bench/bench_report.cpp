#include "app/bench/bench_report.hpp"

#include <algorithm>
#include <array>
#include <cstdarg>
#include <cstdio>

#include "app/bench/thesis_data.hpp"

namespace zs::bench {

namespace {

constexpr double kGoalFps = 60;             // goal: every thesis configuration
constexpr double kGoalFirstFrameMs = 150;   // goal: typed formula to first frame
constexpr double kIssueFirstFrameMs = 300;  // issue 7: every thesis surface

std::string format(const char* fmt, ...) {
  char buffer[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

std::string fpsCell(const ConfigResult* r) {
  if (!r) return "-";
  if (!r->error.empty()) return "failed";
  // Below 10 fps a whole number hides differences of 30% and more.
  return format(r->stats.fps() < 10 ? "%.1f" : "%.0f", r->stats.fps());
}

// One thesis table: rows surface x level, per column our fps then the thesis' fps.
template <typename Column>
std::string thesisTable(const BenchResults& results, const char* title,
                        const std::array<std::string, 3>& labels, const Column& columnConfig,
                        const int (&published)[7][3][3]) {
  std::string md = format("## %s\n\n| Surface | Level |", title);
  for (const std::string& label : labels) md += format(" %s: ours | thesis |", label.c_str());
  md += "\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const ThesisSurface& s : kThesisSurfaces) {
    for (int level : kThesisLevels) {
      md += level == 0 ? format("| %d | %d |", s.number, level) : format("| | %d |", level);
      for (int c = 0; c < 3; ++c) {
        const ConfigResult* r = findConfig(results, columnConfig(s.number, level, c));
        md += format(" %s | %d |", fpsCell(r).c_str(), published[s.number - 1][level][c]);
      }
      md += "\n";
    }
  }
  return md + "\n";
}

struct GoalTally {
  int measured = 0, atGoal = 0, atThesis = 0;
  double worstFps = 1e300, worstRatio = 1e300;
  std::string worstName, worstRatioName;
};

void tallyThesisConfigs(const BenchResults& results, GoalTally& t) {
  for (const ConfigResult& r : results.configs) {
    const BenchConfig& c = r.config;
    if (c.method != TracingMethod::Sampling) continue;  // the thesis' tables time its method
    const auto a = table52Fps(c.surface, c.level, c.intervals, c.epsilon);
    const auto b = table53Fps(c.surface, c.level, c.intervals, c.epsilon);
    if ((!a && !b) || !r.error.empty()) continue;
    const double thesis = std::max(a.value_or(0), b.value_or(0));  // the harder of the two
    const double fps = r.stats.fps();
    const std::string name = format("surface %d, level %d, %d intervals, epsilon %s", c.surface,
                                    c.level, c.intervals, formatEpsilon(c.epsilon).c_str());
    ++t.measured;
    t.atGoal += fps >= kGoalFps;
    t.atThesis += fps >= thesis;
    if (fps < t.worstFps) t.worstFps = fps, t.worstName = name;
    if (fps / thesis < t.worstRatio) t.worstRatio = fps / thesis, t.worstRatioName = name;
  }
}

const char* verdict(bool met) {
  return met ? "**met**" : "**not met**";
}

std::string goals(const BenchResults& results) {
  GoalTally t;
  tallyThesisConfigs(results, t);
  std::string md = "## Goals\n\n";
  if (t.measured == 0) return md + "No thesis configuration was measured.\n\n";
  md += format(
      "- Thesis configurations at >= %.0f fps (goal): %d of %d - %s. "
      "Slowest: %s at %.1f fps.\n",
      kGoalFps, t.atGoal, t.measured, verdict(t.atGoal == t.measured), t.worstName.c_str(),
      t.worstFps);
  md += format(
      "- At least the thesis' fps (issue 7): %d of %d - %s. Smallest ratio ours / "
      "thesis: %.2fx (%s).\n",
      t.atThesis, t.measured, verdict(t.atThesis == t.measured), t.worstRatio,
      t.worstRatioName.c_str());
  // Issue 10's goals are the exact method's, with the scene defaults (level 1).
  int exact = 0, exactAtGoal = 0;
  double exactWorst = 0;
  for (const ThesisSurface& s : kThesisSurfaces) {
    const ConfigResult* r = findConfig(results, {s.number, 1, 10, 0.001, TracingMethod::Bernstein});
    if (!r || !r->error.empty()) continue;
    ++exact;
    exactAtGoal += r->stats.fps() >= kGoalFps;
    exactWorst = std::max(exactWorst, r->stats.medianMs);
  }
  if (exact > 0) {
    md += format(
        "- Default method (bernstein), level 1, at >= %.0f fps (issue 10): %d of %d - "
        "%s. Slowest frame: %.1f ms.\n",
        kGoalFps, exactAtGoal, exact, verdict(exactAtGoal == exact), exactWorst);
  }
  int ok = 0, fast = 0, total = 0;
  double worst = 0;
  for (const FirstFrame& f : results.firstFrames) {
    // What a user waits for is the default method's first frame.
    if (!f.error.empty() || f.method != TracingMethod::Bernstein) continue;
    ++total;
    ok += f.totalMs <= kIssueFirstFrameMs;
    fast += f.totalMs <= kGoalFirstFrameMs;
    worst = std::max(worst, f.totalMs);
  }
  md += format(
      "- First frame <= %.0f ms (issue 7): %d of %d surfaces - %s; <= %.0f ms "
      "(goal): %d of %d - %s. Slowest: %.0f ms.\n",
      kIssueFirstFrameMs, ok, total, verdict(ok == total && total > 0), kGoalFirstFrameMs, fast,
      total, verdict(fast == total && total > 0), worst);
  return md + "\n";
}

std::string deepLevels(const BenchResults& results) {
  std::string md = format("## Octree level 0..%d, both methods (10 intervals, epsilon 0.001)\n\n",
                          results.options.maxLevel);
  md +=
      "| Surface | Level | Leaves | Nodes | Octree + hierarchy ms | sampling ms | fps | "
      "bernstein ms | fps | bernstein speed-up |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto ms = [](const ConfigResult* r) {
    return r && r->error.empty() ? format("%.2f", r->stats.medianMs) : std::string("-");
  };
  for (const ThesisSurface& s : kThesisSurfaces) {
    for (int level = 0; level <= results.options.maxLevel; ++level) {
      const ConfigResult* r = findConfig(results, {s.number, level, 10, 0.001});
      const ConfigResult* b =
          findConfig(results, {s.number, level, 10, 0.001, TracingMethod::Bernstein});
      const ConfigResult* any = r ? r : b;
      if (!any) continue;
      const bool both = r && b && r->error.empty() && b->error.empty() && b->stats.medianMs > 0;
      md += format("| %s | %d | %zu | %zu | %.2f | %s | %s | %s | %s | %s |\n",
                   level == 0 ? std::to_string(s.number).c_str() : "", level, any->leaves,
                   any->nodes, any->octreeMs, ms(r).c_str(), fpsCell(r).c_str(), ms(b).c_str(),
                   fpsCell(b).c_str(),
                   both ? format("%.2fx", r->stats.medianMs / b->stats.medianMs).c_str() : "-");
    }
  }
  return md + "\n";
}

std::string firstFrames(const BenchResults& results) {
  std::string md =
      "## Time to first frame (level 1, 10 intervals, epsilon 0.001)\n\n"
      "Milliseconds. JIT estimate = first draw - the median frame of the same settings.\n\n"
      "| Surface | Method | Parse + gradient | Octree + hierarchy | Codegen | glslang | GL compile "
      "+ link | First draw | Total ms | JIT estimate |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const FirstFrame& f : results.firstFrames) {
    if (!f.error.empty()) {
      md += format("| %d | %s | failed | | | | | | | |\n", f.surface, tracingMethodName(f.method));
      continue;
    }
    // The first draw is llvmpipe's JIT of the fragment shader plus one ordinary frame;
    // the same configuration's median frame time separates the two.
    const ConfigResult* same = findConfig(results, {f.surface, 1, 10, 0.001, f.method});
    const std::string jit = same && same->error.empty()
                                ? format("%.0f", f.firstDrawMs - same->stats.medianMs)
                                : std::string("-");
    md += format("| %d | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f | %.0f | %s |\n", f.surface,
                 tracingMethodName(f.method), f.cpu.parseMs, f.cpu.octreeMs, f.cpu.codegenMs,
                 f.cpu.validateMs, f.glCompileMs, f.firstDrawMs, f.totalMs, jit.c_str());
  }
  return md + "\n";
}

}  // namespace

const ConfigResult* findConfig(const BenchResults& results, const BenchConfig& config) {
  for (const ConfigResult& r : results.configs)
    if (r.config == config) return &r;
  return nullptr;
}

std::string markdownReport(const BenchResults& results) {
  const BenchOptions& o = results.options;
  std::string md = "# zeroset bench\n\n";
  md += format("- Device: %s, %u CPU threads%s\n", results.device.c_str(), results.cpuThreads,
               o.quick ? " (quick mode: not comparable with the thesis)" : "");
  md += format(
      "- Frames: %dx%d, one ray per pixel, median of %d glFinish-timed full-frame "
      "draws after %d warm-up draws; fps = 1000 / median ms\n",
      o.width, o.height, o.frames, o.warmup);
  md += "- Scene: default camera and lights, domain [-1.5, 1.5]^3, thesis octree criteria\n";
  md += format(
      "- MESA_SHADER_CACHE_DISABLE=%s during the run; GL context creation (%.0f ms) "
      "is not part of any first frame\n- Thesis: Intel HD Graphics 3000, resolution "
      "not stated\n\n",
      results.shaderCache.c_str(), results.contextMs);
  md += goals(results);
  md += thesisTable(
      results, "Table 5.2: fps by intervals and octree level (epsilon 0.001)",
      {"10 intervals", "15 intervals", "20 intervals"},
      [](int s, int level, int c) {
        return BenchConfig{s, level, kTable52Intervals[c], kTable52Epsilon};
      },
      kTable52Fps);
  md += thesisTable(
      results, "Table 5.3: fps by epsilon and octree level (10 intervals)",
      {"epsilon 0.01", "epsilon 0.001", "epsilon 0.0001"},
      [](int s, int level, int c) {
        return BenchConfig{s, level, kTable53Intervals, kTable53Epsilons[c]};
      },
      kTable53Fps);
  return md + deepLevels(results) + firstFrames(results);
}

std::string configCsv(const BenchResults& results) {
  std::string csv =
      "surface,method,level,intervals,epsilon,width,height,frames,median_ms,min_ms,max_ms,fps,"
      "octree_ms,leaves,nodes,thesis_table52_fps,thesis_table53_fps,error\n";
  const auto opt = [](std::optional<int> v) { return v ? std::to_string(*v) : std::string(); };
  for (const ConfigResult& r : results.configs) {
    const BenchConfig& c = r.config;
    std::string error = r.error.substr(0, r.error.find('\n'));
    std::replace(error.begin(), error.end(), ',', ';');
    const bool thesis = c.method == TracingMethod::Sampling;
    csv +=
        format("%d,%s,%d,%d,%s,%d,%d,%d,%.3f,%.3f,%.3f,%.2f,%.3f,%zu,%zu,%s,%s,%s\n", c.surface,
               tracingMethodName(c.method), c.level, c.intervals, formatEpsilon(c.epsilon).c_str(),
               results.options.width, results.options.height, r.stats.frames, r.stats.medianMs,
               r.stats.minMs, r.stats.maxMs, r.stats.fps(), r.octreeMs, r.leaves, r.nodes,
               thesis ? opt(table52Fps(c.surface, c.level, c.intervals, c.epsilon)).c_str() : "",
               thesis ? opt(table53Fps(c.surface, c.level, c.intervals, c.epsilon)).c_str() : "",
               error.c_str());
  }
  return csv;
}

std::string firstFrameCsv(const BenchResults& results) {
  std::string csv =
      "surface,method,parse_ms,octree_ms,codegen_ms,glslang_ms,gl_compile_ms,"
      "first_draw_ms,total_ms,error\n";
  for (const FirstFrame& f : results.firstFrames)
    csv += format("%d,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%s\n", f.surface,
                  tracingMethodName(f.method), f.cpu.parseMs, f.cpu.octreeMs, f.cpu.codegenMs,
                  f.cpu.validateMs, f.glCompileMs, f.firstDrawMs, f.totalMs,
                  f.error.empty() ? "" : "failed");
  return csv;
}

std::string inputMarkdownReport(const InputBenchResults& results) {
  const BenchOptions& o = results.options;
  const Scene& scene = results.scene;
  std::string md = "# zeroset bench: " + scene.formula + "\n\n";
  md += format("- Device: %s, %u CPU threads\n", results.device.c_str(), results.cpuThreads);
  md += format(
      "- Frames: %dx%d, median of %d glFinish-timed full-frame draws after %d warm-up "
      "draws; fps = 1000 / median ms\n",
      o.width, o.height, o.frames, o.warmup);
  md += format(
      "- Scene: octree level %d, reflection %s, %d x %d rays per pixel, epsilon %s "
      "(sampling: %d intervals)\n",
      scene.octree.level, scene.render.reflection.enabled ? "on" : "off", scene.render.samples,
      scene.render.samples, formatEpsilon(scene.render.tracing.epsilon).c_str(),
      scene.render.tracing.intervals);
  md += format(
      "- First frame: parse to the first frame's pixels, shader cache %s "
      "(MESA_SHADER_CACHE_DISABLE=%s)\n\n",
      results.shaderCache == "true" ? "cold" : "as configured", results.shaderCache.c_str());
  md +=
      "| Method | Median ms | fps | Min ms | Max ms | First frame ms | of which first draw "
      "| Leaves |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  const MethodResult* sampled = nullptr;
  for (const MethodResult& r : results.methods) {
    const char* name = tracingMethodName(r.method);
    if (!r.error.empty()) {
      md += format("| %s | failed | | | | | | |\n", name);
    } else if (!r.skipped.empty()) {
      md += format("| %s | not used: see below | | | | | | |\n", name);
    } else {
      md += format("| %s | %.2f | %.1f | %.2f | %.2f | %.0f | %.0f | %zu |\n", name,
                   r.stats.medianMs, r.stats.fps(), r.stats.minMs, r.stats.maxMs, r.first.totalMs,
                   r.first.firstDrawMs, r.leaves);
      if (r.method == TracingMethod::Sampling) sampled = &r;
    }
  }
  md += "\n";
  for (const MethodResult& r : results.methods) {
    if (!sampled || &r == sampled || !r.error.empty() || !r.skipped.empty()) continue;
    if (r.stats.medianMs > 0)
      md += format("%s is %.2fx the speed of sampling on this scene.\n",
                   tracingMethodName(r.method), sampled->stats.medianMs / r.stats.medianMs);
  }
  for (const MethodResult& r : results.methods) {
    if (!r.skipped.empty()) md += r.skipped + "\n";
    if (!r.error.empty())
      md += format("%s failed: %s\n", tracingMethodName(r.method), r.error.c_str());
  }
  return md;
}

}  // namespace zs::bench
