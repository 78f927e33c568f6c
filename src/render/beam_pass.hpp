#pragma once
// The interval method's beam pass (raytrace_beam.frag.glsl) and tile skipping: takes the
// beam program and a way to set a program's uniforms for the frame, puts out, per tile of
// kBeamTile x kBeamTile pixels, where the tile's rays may first meet the surface (a texture
// the frame's shader reads), and marks in the stencil buffer the tiles no ray of which can
// hit anything (beam_tiles.hpp), so that the frame's draw never starts them. Owns its
// texture, framebuffer and the tiles' rectangles. Each call leaves the framebuffer binding
// and the program in use as it found them; only markClearTiles leaves state behind, and
// says which.
#include <functional>

namespace zs {

class BeamPass {
 public:
  BeamPass() = default;
  ~BeamPass();
  BeamPass(const BeamPass&) = delete;
  BeamPass& operator=(const BeamPass&) = delete;

  // Sets `program`'s uniforms for the whole picture and the draw state (hierarchy texture,
  // vertex array, culling) for a target of targetWidth x targetHeight; returns the vertex
  // count to draw (0: nothing can be hit).
  using FrameSetup = std::function<int(unsigned program, int targetWidth, int targetHeight)>;

  // Draws `beam` for a picture of width x height into the pass's own target, one texel per
  // tile. False where that target cannot be made (the frame is then drawn without it).
  bool draw(unsigned beam, const FrameSetup& setup, int width, int height);

  // Reads the tiles back and, where enough of them are clear to pay for it, marks them in the
  // stencil buffer of the framebuffer bound now with `mask()` (the tile-mask program, asked
  // for only then; 0 when it does not compile), using vertex array `vao`. Leaves the stencil
  // test on (pass where 0) after marking, off otherwise; restores the program in use.
  void markClearTiles(const std::function<unsigned()>& mask, unsigned vao, int width, int height);

  // Binds the result to texture unit 1, where the frame's shader reads it (rtBeam).
  void bindResult() const;

 private:
  void release();

  unsigned fbo_ = 0, texture_ = 0, tileBuffer_ = 0;
  int tilesX_ = 0, tilesY_ = 0;
};

}  // namespace zs
