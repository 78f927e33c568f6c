// `zeroset bench [--quick] [--plan full|levels] [--size WxH] [--frames N] [--max-level N]
// [--out DIR] [--backend egl|osmesa]`:
// reproduces the thesis' Tables 5.2 and 5.3 (and deeper octree levels) headless with the
// thesis' method, the exact method beside it, and the time from a typed formula to its
// first frame. Writes DIR/bench.md, DIR/bench.csv, DIR/first_frame.csv and
// DIR/fps_by_level.png; progress goes to stderr. Exits 1 when any surface or configuration
// failed, so CI notices a benchmark that no longer runs.
// `zeroset bench INPUT [--set KEY=VALUE]... [--size WxH] [--frames N]`: one formula or
// scene, both methods side by side, a Markdown table on stdout.
// `zeroset bench --typing FORMULA [INPUT] [--size WxH]`: typing latency (typing_bench.hpp).
#include <filesystem>
#include <iostream>

#include "app/bench/bench_report.hpp"
#include "app/bench/fps_plot.hpp"
#include "app/bench/typing_bench.hpp"
#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "app/text_output.hpp"

namespace zs::app {

namespace {

struct BenchArgs {
  SceneArgs scene;  // INPUT: empty for the thesis plan
  bool quick = false;
  std::string size;
  int frames = 0;  // 0: the mode's default
  int maxLevel = -1;
  std::string plan = "full";
  std::string out = "bench-results";
  std::string backend = "egl";
  std::string typing;  // --typing FORMULA
};

int runInput(const BenchArgs& args, const bench::BenchOptions& options) {
  std::optional<Scene> scene = loadSceneArgs(args.scene);
  if (!scene) return 1;
  const bench::InputBenchResults results = bench::runInputBench(*scene, options);
  if (!results.error.empty()) {
    std::cerr << "error: " << results.error << "\n"
              << (options.backend == Backend::Egl ? "hint: try --backend osmesa\n" : "");
    return 1;
  }
  std::cout << bench::inputMarkdownReport(results);
  bool failed = false;
  for (const auto& m : results.methods) failed |= !m.error.empty();
  return failed ? 1 : 0;
}

int runBench(const BenchArgs& args) {
  bench::BenchOptions options;
  if (args.quick) options = bench::quickOptions(options);
  if (!args.size.empty()) {
    char x = 0, rest = 0;
    if (std::sscanf(args.size.c_str(), "%d%c%d%c", &options.width, &x, &options.height, &rest) !=
            3 ||
        (x != 'x' && x != 'X') || options.width <= 0 || options.height <= 0 ||
        options.width > 16384 || options.height > 16384) {
      std::cerr << "error: --size '" << args.size << "' is not WIDTHxHEIGHT\n"
                << "hint: e.g. --size 800x600 (1 to 16384 pixels each way)\n";
      return 1;
    }
  }
  if (args.frames > 0) options.frames = args.frames;
  if (args.maxLevel >= 0) options.maxLevel = args.maxLevel;
  if (args.plan == "levels") options.levelsOnly = true;
  if (!parseBackend(args.backend, options.backend)) {
    std::cerr << "error: unknown backend '" << args.backend << "'\nhint: egl or osmesa\n";
    return 1;
  }
  if (!args.typing.empty()) {
    // The scene's settings (INPUT, or the defaults) with the formula typed into it.
    std::optional<Scene> scene = Scene{};
    if (!args.scene.input.empty()) scene = loadSceneArgs(args.scene);
    if (!scene) return 1;
    scene->width = options.width;
    scene->height = options.height;
    const bench::TypingResults results = bench::runTypingBench(*scene, args.typing, options);
    if (!results.error.empty()) {
      std::cerr << "error: " << results.error << "\n";
      return 1;
    }
    std::cout << bench::typingReport(results);
    return 0;
  }
  if (!args.scene.input.empty()) return runInput(args, options);
  options.outDir = args.out;
  std::error_code ec;
  std::filesystem::create_directories(options.outDir, ec);
  if (ec) {
    std::cerr << "error: cannot create " << options.outDir << ": " << ec.message() << "\n";
    return 1;
  }

  const bench::BenchResults results = bench::runBench(options, bench::benchPlan(options));
  if (!results.error.empty()) {
    std::cerr << "error: " << results.error << "\n"
              << (options.backend == Backend::Egl ? "hint: try --backend osmesa\n" : "");
    return 1;
  }
  const std::filesystem::path dir = options.outDir;
  const std::string markdown = bench::markdownReport(results);
  bool ok = writeTextFile(dir / "bench.md", markdown) &&
            writeTextFile(dir / "bench.csv", bench::configCsv(results)) &&
            writeTextFile(dir / "first_frame.csv", bench::firstFrameCsv(results));
  if (std::string err =
          writePng((dir / "fps_by_level.png").string(), bench::fpsByLevelPlot(results));
      !err.empty()) {
    std::cerr << "error: " << err << "\n";
    ok = false;
  }
  std::cout << markdown;
  std::cerr << "wrote bench.md, bench.csv, first_frame.csv, fps_by_level.png to " << dir.string()
            << "\n";
  bool failed = false;
  for (const auto& f : results.firstFrames) failed |= !f.error.empty();
  for (const auto& c : results.configs) failed |= !c.error.empty();
  if (failed) std::cerr << "error: some configurations failed (see above)\n";
  return ok && !failed ? 0 : 1;
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "bench",
      "Time the thesis' surfaces and settings headless (Tables 5.2 and 5.3), or with INPUT "
      "one formula or scene, both tracing methods side by side");
  auto args = std::make_shared<BenchArgs>();
  addSceneOptions(*cmd, args->scene, /*inputRequired=*/false);
  cmd->add_flag("--quick", args->quick,
                "CI mode: 160x120, 3 frames, levels 0-2 at 10 intervals / epsilon 0.001");
  cmd->add_option("--size", args->size, "frame size WIDTHxHEIGHT (default 800x600)");
  cmd->add_option("--frames", args->frames, "timed frames per configuration (default 20)")
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--max-level", args->maxLevel, "deepest octree level timed (default 6)")
      ->check(CLI::Range(0, 10));
  cmd->add_option("--plan", args->plan,
                  "full: the thesis' Tables 5.2/5.3 grid plus deeper levels (default); levels: "
                  "levels 0..max at 10 intervals / epsilon 0.001 only")
      ->check(CLI::IsMember({"full", "levels"}));
  cmd->add_option("--out", args->out,
                  "directory for the thesis plan's reports (default bench-results); with INPUT "
                  "the table goes to stdout");
  cmd->add_option("--typing", args->typing,
                  "replay typing FORMULA one character at a time: per keystroke, the time to "
                  "the first picture (tape interpreter) and to the final one (the formula's own "
                  "shader); INPUT, if given, supplies the scene's other settings");
  cmd->add_option("--backend", args->backend, "egl (default) or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}));
  cmd->callback([args] { std::exit(runBench(*args)); });
}

}  // namespace zs::app
