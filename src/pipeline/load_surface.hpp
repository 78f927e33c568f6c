#pragma once
// The hand-over from the CPU half to the GPU half: takes a PreparedSurface and a RayTracer
// on a current context, puts the program (rebuilt only when the shader text changed), the
// packed box hierarchy and the parameter values into the tracer.
#include <array>
#include <functional>
#include <memory>
#include <string>

#include "pipeline/pipeline.hpp"
#include "pipeline/quick_surface.hpp"
#include "render/gl_context.hpp"
#include "render/ray_tracer.hpp"

namespace zs {

// "" on success; otherwise text ready to print (the driver's log, or "error: ...").
std::string loadSurface(RayTracer& tracer, const PreparedSurface& surface,
                        const RenderSettings& drawnWith);

// A tracer running the tape interpreter's program for `sampling` and `polynomialOnly`
// (interpreter_glsl.hpp; compiled on the first call, then kept: every formula after it draws
// without a compile). "" on success.
std::string buildInterpreter(RayTracer& tracer, bool sampling, bool polynomialOnly);
// Puts a quick surface's tape, hierarchy and parameter values into a tracer built by
// buildInterpreter. "" on success.
std::string loadQuickSurface(RayTracer& tracer, const QuickSurface& surface);

// The tape interpreters a front end keeps, one per method kind and dispatch, each a tracer
// on the context current when it was made.
class TapeInterpreters {
 public:
  using Draw = std::function<void(RayTracer&, const Scene&)>;
  // Compiles both interpreters for `sampling` (a software rasterizer JITs a program at its
  // first draw) and draws each through `draw` with the pictures that select every program
  // variant a first picture uses: a surface, and a view that shows none. `base` gives the
  // settings. What a front end does once, before the first keystroke. "" on success.
  std::string warm(bool sampling, const Scene& base, const Draw& draw);
  // After warm: the variant of a picture that its surface fills. A frame skips its clear
  // tiles with a stencil test only where enough tiles are clear (render/beam_pass.hpp), and
  // a software rasterizer compiles a program again for each such state, so the warm-up also
  // draws its spheres from the domain's centre, where no tile is clear. A front end that
  // warms on a background thread does this after saying that first pictures are ready.
  std::string warmFilledPictures(bool sampling, const Scene& base, const Draw& draw);
  bool warmed(bool sampling) const { return warmed_[sampling]; }
  // The warmed interpreter that runs `surface`, loaded with it; null with `error` set when
  // none is warmed for it or the load failed.
  RayTracer* load(const QuickSurface& surface, std::string& error);

 private:
  std::array<std::array<std::unique_ptr<RayTracer>, 2>, 2> tracers_;  // [sampling][polynomial]
  std::array<bool, 2> warmed_{};
};

// A headless context, current, and a tracer made on it with a surface loaded: what the
// commands that write pictures start from. The tracer is declared last, so it goes first,
// while its context still exists.
struct HeadlessTracer {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<RayTracer> tracer;
};

// For one picture of `rays` rays (width x rows x samples^2), before the first context: on
// llvmpipe the JIT compile of the shader costs more than the frame unless the picture is
// large. Without LLVM's optimization passes the JIT takes about half as long and the frame a
// fifth longer, so below some 8 million rays the picture is ready sooner that way
// (docs/renderer.md has the measurement). Mesa reads this once, when the driver starts; a
// value the user set is kept; other drivers ignore it.
void preferQuickShaderCompile(double rays);

// Null members after printing why (and a hint) to stderr.
HeadlessTracer openHeadlessTracer(Backend backend, const PreparedSurface& surface,
                                  const RenderSettings& drawnWith);

}  // namespace zs
