#pragma once
// The GPU ray tracer of thesis chapter 4.4. Takes finished shader text (vertex + the
// fragment shader spliced from the prelude, the generated formula and
// raytrace_main.frag.glsl), the packed box hierarchy (interval/hierarchy.hpp), the
// formula's parameter values and the RenderSettings; puts out frames (RGBA8 + per-pixel
// depth) rendered offscreen in tiles, or draws into the current framebuffer for the viewer.
// Needs a current GL 3.3+ core context (gl_context.hpp) for its whole life; all GL objects
// belong to that context. Never aborts on bad input: errors come back as strings. It orders a
// frame's passes; each part has its own file and keeps the GL state it does not own as it
// found it: programs (program_cache.hpp), offscreen target (offscreen_target.hpp), beam pass
// and tile skipping (beam_pass.hpp), curvature probe and read-back (frame_readback.hpp),
// uniform values (frame_uniforms.hpp).
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "render/beam_pass.hpp"
#include "render/frame_uniforms.hpp"
#include "render/hierarchy_gpu.hpp"
#include "render/image.hpp"
#include "render/offscreen_target.hpp"
#include "render/program_cache.hpp"
#include "render/settings.hpp"

namespace zs {

struct Frame {
  Image color;     // RGBA8, top row first
  DepthMap depth;  // distance along the unit ray from its origin to the first hit; +inf if none
  // Curvature colorings only (shading.color "gauss" or "mean"): the curvature at the first
  // hit of each pixel-center ray, NaN where nothing was hit; empty otherwise.
  DepthMap value;
  double curvatureRange = 0;  // the range the color map used (automatic or the scene's)
  std::string error;          // non-empty: nothing was rendered
};

// Called after each tile; return false to stop (the frame then reports "cancelled").
using ProgressFn = std::function<bool(int tilesDone, int tilesTotal)>;

class RayTracer {
 public:
  // Needs a current GL context: the frame's parameters travel as its driver wants them
  // (frameStorageFor(GL_RENDERER)), or as `storage` says.
  RayTracer();
  explicit RayTracer(FrameStorage storage);
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  // Compiles and links the variant of `drawnWith` (the settings the next frame is drawn
  // with: a shader built for them may lack what another variant calls, e.g. the Hessian a
  // curvature coloring needs); on failure returns false and `log` holds a short message
  // (shader_program.hpp). A failed build keeps the previous program, if any; the same
  // sources as the current program's are not compiled again.
  bool build(std::string_view vertexSource, std::string_view fragmentSource,
             const RenderSettings& drawnWith, std::string& log);
  bool ready() const { return program_ != 0; }
  FrameStorage frameStorage() const { return programs_.frameStorage(); }

  // The 12-float-per-node hierarchy; "" on success, else why it was rejected (the previous
  // hierarchy stays). Nothing is hit until a hierarchy is set.
  std::string setHierarchy(std::span<const float> packed);
  // The tape a tape interpreter's shader runs (interpreter/gpu_tape.hpp): its texels, read
  // as `zs_tape` on texture unit 2; "" on success. Ignored by a formula's own shader.
  std::string setTape(std::span<const std::uint32_t> texels);
  // Values of `uniform float zs_params[K]`, in declaration order; ignored when the formula
  // has no parameters (the driver then reports no such uniform).
  void setParams(std::span<const float> params);

  // Offscreen render in tiles of at most tileSize x tileSize pixels, each its own draw call
  // followed by glFinish, so no single draw runs for seconds and progress can be shown.
  Frame render(const RenderSettings& settings, const Domain& domain, int width, int height,
               const ProgressFn& progress = {}, int tileSize = 256);
  // Rows [top, top + rows) of the width x height picture render() would make, pixel for
  // pixel, in a target of only those rows: a picture taller than a framebuffer, in bands on
  // one machine or many (zeroset render --tile). The band's bottom edge must lie on the beam
  // pass's tile grid counted from the picture's bottom ((height - top - rows) a multiple of
  // kBeamTile); otherwise, or for an empty band, the frame reports why.
  Frame renderBand(const RenderSettings& settings, const Domain& domain, int width, int height,
                   int top, int rows, const ProgressFn& progress = {});
  // One draw call of the whole frame into the internal offscreen target, no read-back:
  // what frame-time measurements time (with glFinish). "" on success.
  std::string drawOffscreen(const RenderSettings& settings, const Domain& domain, int width,
                            int height);
  // Draws into the framebuffer bound now (the viewer's window), viewport (0, 0, w, h).
  void draw(const RenderSettings& settings, const Domain& domain, int width, int height);

  // Sampling also looks for tangent roots (local minima of |F| between sign samples, see
  // docs/renderer.md). On by default; off only to measure what the fix costs.
  void setTangentRoots(bool on) { tangentRoots_ = on; }
  void setProxy(Proxy proxy) { proxy_ = proxy; }
  // The interval method's beam pass (raytrace_beam.frag.glsl), with the tile mask after it;
  // on by default. The picture keeps its guarantee either way: off to measure what it gains,
  // to compare, or while its programs are not compiled yet (app/shader_warmer.hpp).
  void setBeamPass(bool on) { beamPass_ = on; }
  // Whether the program loaded has a beam pass (the interval method's).
  bool hasBeamPass() const { return programs_.hasBeam(); }
  // After a beam pass, shade only the tiles where it left some ray that may still hit
  // something: the others are marked off in the stencil buffer and never started
  // (render/beam_tiles.hpp). On by default; needs a stencil buffer in the framebuffer drawn
  // to (the offscreen target has one; without one every tile is shaded).
  // The picture is the same either way: off only to measure what it gains or to compare.
  void setTileSkipping(bool on) { tileSkipping_ = on; }
  // The curvature range of the last frame drawn (the viewer's legend); 0 before any.
  double curvatureRange() const { return curvatureRange_; }

 private:
  std::string prepare(const RenderSettings& settings, const Domain& domain, int width, int height,
                      bool offscreen);
  // Sets every uniform of `program` (in use) from frame_uniforms.hpp; returns the number of
  // vertices to draw (0: nothing can be hit).
  int setUniforms(unsigned program, const RenderSettings& settings, const Domain& domain, int width,
                  int height);
  // Everything a draw needs besides the program, its uniforms and the cleared target: the
  // hierarchy texture, the proxy's vertex array and culling, the viewport.
  void setDrawState(int width, int height);
  void clearBackground(const RenderSettings& settings, bool offscreen);
  // The interval method's beam pass (beam_pass.hpp) for this frame; false where the shader
  // has none or it could not run.
  bool drawBeam(const RenderSettings& settings, const Domain& domain, int width, int height);
  // The frame's draw call, with the stencil test turned off after it.
  void drawFrame();

  // shading.curvature_range, or for 0 the range measured on a picture a quarter the size
  // (frame_readback.hpp); needs the current program in use.
  double resolveCurvatureRange(const RenderSettings& settings, const Domain& domain, int width,
                               int height);

  ProgramCache programs_;
  unsigned program_ = 0, vao_ = 0;  // program_: the frame's, in use while a frame is drawn
  unsigned nodeBuffer_ = 0, nodeTexture_ = 0;
  unsigned tapeBuffer_ = 0, tapeTexture_ = 0;
  ProgramVariant preferred_;  // what build() compiles first: the variant of the last frame
  double curvatureRange_ = 0;
  OffscreenTarget target_;
  BeamPass beam_;
  bool beamPass_ = true;
  bool tileSkipping_ = true;
  GpuHierarchy hierarchy_;
  std::vector<float> params_;
  bool tangentRoots_ = true;
  Proxy proxy_ = Proxy::Box;
  int vertices_ = 6;  // of the current frame
  // renderBand's: the full picture's height and the band (bandRows_ 0: no band).
  int fullHeight_ = 0, bandTop_ = 0, bandRows_ = 0;
};

}  // namespace zs
