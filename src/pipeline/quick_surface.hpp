#pragma once
// The first picture of a formula: takes a Scene, puts out what the tape interpreter
// (src/interpreter) needs to draw it with a program compiled once — the formula's tape, a
// shallow box hierarchy and the parameter values — in a millisecond or two, while the full
// pipeline (pipeline.hpp) and the formula's own shader follow. The picture is exact (the
// interval method for Bernstein and interval scenes, the thesis' sampling for sampling);
// curvature colorings and singular-point markers wait for the formula's own shader. No GL.
#include <string>
#include <variant>
#include <vector>

#include "interpreter/gpu_tape.hpp"
#include "interval/hierarchy.hpp"
#include "scene/scene.hpp"

namespace zs {

// The deepest octree level the first picture subdivides to: deeper scenes get theirs from
// the full pipeline.
inline constexpr int kQuickOctreeLevel = 3;

struct QuickSurface {
  GpuTape tape;
  BoxHierarchy hierarchy;
  std::vector<double> params;  // graph.params() order
  bool sampling = false;       // which interpreter draws it (interpreterFragmentShader)
  double prepareMs = 0;
};

// Error text is ready to print: the parse error with its caret, or why the interpreter
// cannot draw this scene (then only the full pipeline can).
std::variant<QuickSurface, std::string> prepareQuickSurface(const Scene& scene);

// How a first picture is drawn, and its interpreters warmed: one ray per pixel and no
// reflection ray. It is a preview that the formula's own picture replaces within a fraction
// of a second, and where the surface fills it the reflection ray costs about as much again
// as the primary ray (docs/interpreter.md).
inline RenderSettings firstPictureSettings(RenderSettings settings) {
  settings.samples = 1;
  settings.reflection.enabled = false;
  return settings;
}

}  // namespace zs
