#include "render/beam_pass.hpp"

#include <glad/gl.h>

#include <limits>
#include <string>
#include <vector>

#include "render/beam_tiles.hpp"
#include "render/framebuffer_parts.hpp"
#include "render/program_variant.hpp"

namespace zs {
namespace {
// Tile skipping marks the beam's clear tiles only where at least 1 in kSkipShare is clear.
constexpr std::size_t kSkipShare = 16;

// The bindings a pass changes, put back when it ends.
struct SavedBindings {
  GLint drawFramebuffer = 0, readFramebuffer = 0, program = 0;
  SavedBindings() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  }
  ~SavedBindings() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer));
    glUseProgram(GLuint(program));
  }
};

// The size of a texture that holds n texels in a row and has no power of two for its size:
// llvmpipe compiles a shader anew for each combination of "is a power of two" of the sizes
// of the textures it reads (its sampler key), so a picture whose tiles came to 8 or 16 across
// recompiled the whole ray tracer (a second or more). The texels past n are never read.
int notPowerOfTwo(int n) {
  const auto power = [](int k) { return k > 0 && (k & (k - 1)) == 0; };
  while (power(n)) ++n;
  return n;
}
}  // namespace

BeamPass::~BeamPass() {
  release();
  if (tileBuffer_) glDeleteBuffers(1, &tileBuffer_);
}

void BeamPass::release() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (texture_) glDeleteTextures(1, &texture_);
  fbo_ = texture_ = 0;
  tilesX_ = tilesY_ = 0;
}

bool BeamPass::draw(unsigned beam, const FrameSetup& setup, int width, int height) {
  const SavedBindings saved;
  const int w = (width + kBeamTile - 1) / kBeamTile, h = (height + kBeamTile - 1) / kBeamTile;
  if (!fbo_ || w != tilesX_ || h != tilesY_) {
    release();
    texture_ = newTexture2D(GL_RG32F, GL_RG, GL_FLOAT, notPowerOfTwo(w), notPowerOfTwo(h));
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      release();
      return false;
    }
    tilesX_ = w;
    tilesY_ = h;
  }
  glUseProgram(beam);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &buffer);
  // The full picture's uniforms: the beam shader finds each tile's rays from rt.resolution.
  const int vertices = setup(beam, w, h);
  // Tiles no fragment covers say nothing: start at 0 with no first segment hint.
  glDisable(GL_SCISSOR_TEST);
  const float none[4] = {0.0f, std::numeric_limits<float>::max(), 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, none);
  if (vertices > 0) glDrawArrays(GL_TRIANGLES, 0, vertices);
  return true;
}

void BeamPass::markClearTiles(const std::function<unsigned()>& mask, unsigned vao, int width,
                              int height) {
  // The beam's result: on llvmpipe reading it back costs no wait the main pass would not
  // have had anyway (it samples the beam's texture).
  std::vector<float> beam(std::size_t(tilesX_) * tilesY_ * 2);
  {
    const SavedBindings saved;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, tilesX_, tilesY_, GL_RG, GL_FLOAT, beam.data());
  }
  // Marking and the stencil test have a cost of their own (docs/renderer.md, "The interval
  // method", 7.): worth it only where the tiles skipped save more, which takes a share of
  // clear tiles.
  std::size_t clear = 0;
  for (std::size_t k = 0; k < beam.size(); k += 2) clear += beamTileIsClear(beam[k]);
  if (clear * kSkipShare < beam.size() / 2) return;  // no stencil test either
  const std::vector<float> runs = clearTileRuns(beam, tilesX_, tilesY_, kBeamTile, width, height);
  if (runs.empty()) return;
  const unsigned program = mask();
  if (!program) return;  // every tile is shaded (the picture is the same)
  GLint previous = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
  if (!tileBuffer_) glGenBuffers(1, &tileBuffer_);
  glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(runs.size() * sizeof(float)), runs.data(),
               GL_STREAM_DRAW);
  glBindVertexArray(vao);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "rtProxy"),
              2);  // the rectangles (fullscreen.vert.glsl)
  const GLboolean culling = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glStencilMask(0xFF);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(runs.size() / 2));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisableVertexAttribArray(0);
  if (culling) glEnable(GL_CULL_FACE);
  // The main pass: only where unmarked. A fragment that fails the stencil test before its
  // shader runs (it neither discards nor writes depth) is never shaded.
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glUseProgram(GLuint(previous));
}

void BeamPass::bindResult() const {
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace zs
