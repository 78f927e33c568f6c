// RayTracer: the passes of a frame (curvature probe, beam, tile mask, the frame itself) and
// the tiled render with its read-back; the programs live in program_cache.hpp, the offscreen
// framebuffer in offscreen_target.hpp, the uniform values in ray_tracer_uniforms.cpp.
#include "render/ray_tracer.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstring>
#include <utility>
#include <limits>

#include "render/beam_tiles.hpp"
#include "render/shading_defines.hpp"

namespace zs {

RayTracer::RayTracer() : preferred_(ProgramVariant::of(RenderSettings{})) {
  glGenVertexArrays(1, &vao_);
}

namespace {
// Tile skipping marks the beam's clear tiles only where at least 1 in kSkipShare is clear.
constexpr std::size_t kSkipShare = 16;
}  // namespace

RayTracer::~RayTracer() {
  if (tileBuffer_) glDeleteBuffers(1, &tileBuffer_);
  releaseBeam();
  if (nodeTexture_) glDeleteTextures(1, &nodeTexture_);
  if (nodeBuffer_) glDeleteBuffers(1, &nodeBuffer_);
  glDeleteVertexArrays(1, &vao_);
}

bool RayTracer::build(std::string_view vertexSource, std::string_view fragmentSource,
                      std::string& log) {
  // The same text again (a parameter or level change) keeps the programs: llvmpipe's JIT of
  // a new one costs a visible pause.
  if (program_ && programs_.holds(vertexSource, fragmentSource)) return true;
  const unsigned first = programs_.rebuild(vertexSource, fragmentSource, preferred_, log);
  if (!first) return false;  // the programs built before stay
  program_ = first;
  return true;
}

std::string RayTracer::setHierarchy(std::span<const float> packed) {
  GpuHierarchy gpu;
  if (std::string error = toGpuHierarchy(packed, gpu); !error.empty()) return error;
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  if (gpu.count > maxTexels)
    return "hierarchy: " + std::to_string(gpu.count) + " nodes exceed GL_MAX_TEXTURE_BUFFER_SIZE (" +
           std::to_string(maxTexels) + ")";
  if (!nodeBuffer_) glGenBuffers(1, &nodeBuffer_);
  if (!nodeTexture_) glGenTextures(1, &nodeTexture_);
  glBindBuffer(GL_TEXTURE_BUFFER, nodeBuffer_);
  // A zero-size buffer store is not a valid texture-buffer source: keep one dummy texel.
  static const std::uint32_t dummy[4] = {};
  const void* data = gpu.texels.empty() ? static_cast<const void*>(dummy) : gpu.texels.data();
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(std::max<std::size_t>(gpu.texels.size(), 4) * 4),
               data, GL_STATIC_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, nodeTexture_);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, nodeBuffer_);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
  hierarchy_ = std::move(gpu);
  return {};
}

void RayTracer::setParams(std::span<const float> params) {
  params_.assign(params.begin(), params.end());
}

void RayTracer::releaseBeam() {
  if (beamFbo_) glDeleteFramebuffers(1, &beamFbo_);
  if (beamTex_) glDeleteTextures(1, &beamTex_);
  beamFbo_ = beamTex_ = 0;
  beamWidth_ = beamHeight_ = 0;
}

bool RayTracer::drawBeam(const RenderSettings& settings, const Domain& domain, int width,
                         int height) {
  if (!programs_.hasBeam() || !beamPass_) return false;
  ProgramVariant v = preferred_;
  v.beam = true;
  std::string log;
  const unsigned beam = programs_.get(v, log);
  if (!beam) return false;  // the pixels then walk on their own (the picture is the same)
  const int w = (width + kBeamTile - 1) / kBeamTile, h = (height + kBeamTile - 1) / kBeamTile;
  if (!beamFbo_ || w != beamWidth_ || h != beamHeight_) {
    releaseBeam();
    glGenTextures(1, &beamTex_);
    glBindTexture(GL_TEXTURE_2D, beamTex_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, w, h, 0, GL_RG, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &beamFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, beamFbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, beamTex_, 0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      releaseBeam();
      return false;
    }
    beamWidth_ = w;
    beamHeight_ = h;
  }
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  glUseProgram(beam);
  glBindFramebuffer(GL_FRAMEBUFFER, beamFbo_);
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &buffer);
  // The full picture's uniforms: the beam shader finds each tile's rays from rt.resolution.
  const int vertices = setUniforms(beam, settings, domain, width, height);
  setDrawState(w, h);
  // Tiles no fragment covers say nothing: start at 0 with no first segment hint.
  glDisable(GL_SCISSOR_TEST);
  const float none[4] = {0.0f, std::numeric_limits<float>::max(), 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, none);
  if (vertices > 0) glDrawArrays(GL_TRIANGLES, 0, vertices);
  glUseProgram(program_);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(bound));
  return true;
}

void RayTracer::markClearTiles(int width, int height) {
  // The beam's result: on llvmpipe reading it back costs no wait the main pass would not
  // have had anyway (it samples the beam's texture).
  std::vector<float> beam(std::size_t(beamWidth_) * beamHeight_ * 2);
  GLint bound = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bound);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, beamFbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, beamWidth_, beamHeight_, GL_RG, GL_FLOAT, beam.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(bound));
  // Marking and the stencil test have a cost of their own (docs/renderer.md, "The interval
  // method", 7.): worth it only where the tiles skipped save more, which takes a share of
  // clear tiles.
  std::size_t clear = 0;
  for (std::size_t k = 0; k < beam.size(); k += 2) clear += beamTileIsClear(beam[k]);
  if (clear * kSkipShare < beam.size() / 2) return;  // no stencil test either
  const std::vector<float> runs =
      clearTileRuns(beam, beamWidth_, beamHeight_, kBeamTile, width, height);
  if (runs.empty()) return;
  ProgramVariant v = preferred_;
  v.tileMask = true;
  std::string log;
  const unsigned mask = programs_.get(v, log);
  if (!mask) return;  // every tile is shaded (the picture is the same)
  if (!tileBuffer_) glGenBuffers(1, &tileBuffer_);
  glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(runs.size() * sizeof(float)), runs.data(),
               GL_STREAM_DRAW);
  glBindVertexArray(vao_);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glUseProgram(mask);
  glUniform1i(programs_.uniform(mask, "rtProxy"), 2);  // the rectangles (fullscreen.vert.glsl)
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
  glUseProgram(program_);
}

void RayTracer::drawFrame() {
  if (vertices_ > 0) glDrawArrays(GL_TRIANGLES, 0, vertices_);
  glDisable(GL_STENCIL_TEST);
}

std::string RayTracer::prepare(const RenderSettings& settings, const Domain& domain, int width,
                               int height, bool offscreen) {
  if (!program_) return "the ray tracer has no shader program (build() first)";
  if (width <= 0 || height <= 0) return "image size must be positive";
  std::string log;
  preferred_ = ProgramVariant::of(settings);
  const unsigned variant = programs_.get(preferred_, log);
  if (!variant) return "the shader variant for these settings does not compile:\n" + log;
  program_ = variant;
  if (offscreen) {
    if (std::string error = target_.ensure(width, height); !error.empty()) return error;
    target_.bind();
  }
  glUseProgram(program_);
  glDisable(GL_STENCIL_TEST);  // the curvature probe and the beam shade every pixel
  curvatureRange_ = needsCurvature(settings.shading.color)
                        ? resolveCurvatureRange(settings, domain, width, height)
                        : 0;
  const bool beam = drawBeam(settings, domain, width, height);
  if (offscreen) target_.bind();
  vertices_ = setUniforms(program_, settings, domain, width, height);
  setDrawState(width, height);
  clearBackground(settings, offscreen);
  if (beam && tileSkipping_ && vertices_ > 0) markClearTiles(width, height);
  if (beam) {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, beamTex_);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(programs_.uniform(program_, "rtBeamOn"), 1);  // its unit, 1: setUniforms
  }
  return {};
}

void RayTracer::setDrawState(int width, int height) {
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, nodeTexture_);
  glBindVertexArray(vao_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  // The box proxy keeps its back faces: one fragment per pixel. The two full-screen
  // triangles are front-facing and must not be culled.
  if (proxy_ == Proxy::Box) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CCW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  glViewport(0, 0, width, height);
}

void RayTracer::clearBackground(const RenderSettings& settings, bool offscreen) {
  // Pixels no ray starts in keep these: the background color and +inf depth.
  glDisable(GL_SCISSOR_TEST);
  const float color[4] = {float(settings.background[0]), float(settings.background[1]),
                          float(settings.background[2]), 1.0f};
  if (!offscreen) {
    glClearColor(color[0], color[1], color[2], color[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  const float depth[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  const float value[4] = {std::numeric_limits<float>::quiet_NaN(), 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, color);
  glClearBufferfv(GL_COLOR, 1, depth);
  glClearBufferfv(GL_COLOR, 2, value);
}

double RayTracer::resolveCurvatureRange(const RenderSettings& settings, const Domain& domain,
                                        int width, int height) {
  if (settings.shading.curvatureRange > 0) return settings.shading.curvatureRange;
  // A picture a quarter the size, drawn into the corner of the offscreen target (the shader
  // derives its rays from rt.resolution and the pixel, so a smaller resolution is a smaller
  // picture of the same view), then its value attachment read back.
  GLint bound = 0;  // the viewer traces into its own framebuffer: put it back afterwards
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  if (!target_.ensure(std::max(width, 1), std::max(height, 1)).empty()) return 1;
  const int w = std::max(width / 4, 1), h = std::max(height / 4, 1);
  target_.bind();
  RenderSettings probe = settings;
  probe.shading.curvatureRange = 1;
  const int vertices = setUniforms(program_, probe, domain, w, h);
  setDrawState(w, h);
  clearBackground(settings, true);
  if (vertices > 0) glDrawArrays(GL_TRIANGLES, 0, vertices);
  std::vector<float> values(std::size_t(w) * h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT2);
  glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, values.data());
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(bound));
  // Noise floor: 1e-3 of the curvature of a sphere as large as the domain.
  const Domain box = boundingBox(domain);
  const double half = 0.5 * std::hypot(box.max[0] - box.min[0], box.max[1] - box.min[1],
                                       box.max[2] - box.min[2]);
  const double floor = settings.shading.color == ColorMode::Gauss ? 1e-3 / (half * half) : 1e-3 / half;
  return curvatureRangeOf(std::move(values), floor);
}

std::string RayTracer::drawOffscreen(const RenderSettings& settings, const Domain& domain,
                                     int width, int height) {
  if (std::string error = prepare(settings, domain, width, height, true); !error.empty())
    return error;
  drawFrame();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return {};
}

void RayTracer::draw(const RenderSettings& settings, const Domain& domain, int width, int height) {
  if (!prepare(settings, domain, width, height, false).empty()) return;
  drawFrame();
}

Frame RayTracer::render(const RenderSettings& settings, const Domain& domain, int width,
                        int height, const ProgressFn& progress, int tileSize) {
  Frame frame;
  if (std::string error = prepare(settings, domain, width, height, true); !error.empty()) {
    frame.error = error;
    return frame;
  }
  tileSize = std::max(tileSize, 16);
  const int tilesX = (width + tileSize - 1) / tileSize, tilesY = (height + tileSize - 1) / tileSize;
  glEnable(GL_SCISSOR_TEST);  // the full-viewport triangles only shade the scissored tile
  int done = 0;
  for (int ty = 0; ty < tilesY; ++ty) {
    for (int tx = 0; tx < tilesX; ++tx) {
      glScissor(tx * tileSize, ty * tileSize, tileSize, tileSize);
      if (vertices_ > 0) glDrawArrays(GL_TRIANGLES, 0, vertices_);
      glFinish();
      if (progress && !progress(++done, tilesX * tilesY)) {
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_STENCIL_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        frame.error = "cancelled";
        return frame;
      }
    }
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);

  // Read back; GL rows come bottom-up, frames are top-down.
  frame.color = {width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  frame.depth = {width, height, std::vector<float>(std::size_t(width) * height)};
  std::vector<std::uint8_t> rgba(frame.color.rgba.size());
  std::vector<float> depth(frame.depth.values.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, depth.data());
  const bool curvature = needsCurvature(settings.shading.color);
  std::vector<float> value(curvature ? depth.size() : 0);
  if (curvature) {
    glReadBuffer(GL_COLOR_ATTACHMENT2);
    glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, value.data());
    frame.value = {width, height, std::vector<float>(value.size())};
  }
  frame.curvatureRange = curvatureRange_;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  for (int y = 0; y < height; ++y) {
    const std::size_t src = std::size_t(height - 1 - y) * width, dst = std::size_t(y) * width;
    std::memcpy(&frame.color.rgba[dst * 4], &rgba[src * 4], std::size_t(width) * 4);
    std::memcpy(&frame.depth.values[dst], &depth[src], std::size_t(width) * sizeof(float));
    if (curvature)
      std::memcpy(&frame.value.values[dst], &value[src], std::size_t(width) * sizeof(float));
  }
  return frame;
}

}  // namespace zs
