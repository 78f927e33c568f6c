#pragma once
// `zeroset bench --typing FORMULA`: replays typing FORMULA one character at a time, as the
// viewer handles a keystroke, and times each keystroke to its first picture (the tape
// interpreter's, src/interpreter, at half to an eighth of the size each way as the viewer
// picks it: interact/trace_budget.hpp) and to its final picture (the
// formula's own shader, compiled and warmed on a worker thread with a context of its own,
// then drawn at full size). The next key is typed after the final picture, so each
// keystroke's numbers are its own. Headless, on the backend of the options.
#include <string>
#include <vector>

#include "app/bench/bench_plan.hpp"
#include "scene/scene.hpp"

namespace zs::bench {

struct Keystroke {
  std::string text;    // the formula typed so far
  bool drawn = false;  // false: the text does not parse yet (the viewer keeps its picture)
  double firstMs = 0, finalMs = 0;
  double quickCpuMs = 0;                // of firstMs: the tape and the shallow hierarchy on the CPU
  int firstWidth = 0, firstHeight = 0;  // the first picture's size
  std::string note;                     // why it was not drawn, or what went wrong
};

struct TypingResults {
  std::vector<Keystroke> keys;
  int width = 0, height = 0;
  double interpreterMs = 0;  // compiling and warming the interpreter once, before typing
  std::string error;         // non-empty: nothing was measured
};

// The scene's settings and domain, with its formula replaced by each prefix of `formula`.
TypingResults runTypingBench(const Scene& scene, const std::string& formula,
                             const BenchOptions& options);

// Markdown: one row per keystroke, then `typing: first picture median N ms, max N ms` and
// `typing: final picture median N ms, max N ms` over the keystrokes drawn.
std::string typingReport(const TypingResults& results);

}  // namespace zs::bench
