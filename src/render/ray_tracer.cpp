// RayTracer: GL objects (program, node texture, offscreen target) and the tiled render.
// Uniform values come from ray_tracer_uniforms.cpp.
#include "render/ray_tracer.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstring>
#include <utility>
#include <limits>

#include "render/beam_tiles.hpp"
#include "render/shader_program.hpp"
#include "render/shading_defines.hpp"

namespace zs {

RayTracer::RayTracer() : preferred_(variantFor(RenderSettings{})) { glGenVertexArrays(1, &vao_); }

namespace {
// Pixels per side of a beam pass tile: 8 x 8 rays share one walk through empty space. Smaller
// tiles enclose tighter but cost more beam fragments; 8 measured best (docs/renderer.md).
constexpr int kBeamTile = 8;
// Tile skipping marks the beam's clear tiles only where at least 1 in kSkipShare is clear.
constexpr std::size_t kSkipShare = 16;
}  // namespace

RayTracer::~RayTracer() {
  if (tileBuffer_) glDeleteBuffers(1, &tileBuffer_);
  releaseBeam();
  releaseTarget();
  deletePrograms();
  if (nodeTexture_) glDeleteTextures(1, &nodeTexture_);
  if (nodeBuffer_) glDeleteBuffers(1, &nodeBuffer_);
  glDeleteVertexArrays(1, &vao_);
}

bool RayTracer::build(std::string_view vertexSource, std::string_view fragmentSource,
                      std::string& log) {
  // The same text again (a parameter or level change) keeps the programs: llvmpipe's JIT of
  // a new one costs a visible pause.
  if (program_ && vertexSource == vertexSource_ && fragmentSource == fragmentSource_) return true;
  // The default variant is compiled now, so a broken shader is reported here, not mid-frame.
  std::map<Variant, unsigned> previous;
  std::swap(previous, programs_);
  const std::string oldVertex = std::exchange(vertexSource_, std::string(vertexSource));
  const std::string oldFragment = std::exchange(fragmentSource_, std::string(fragmentSource));
  const unsigned first = program(preferred_, log);
  if (!first) {  // keep what worked before
    deletePrograms();
    programs_ = std::move(previous);
    vertexSource_ = oldVertex;
    fragmentSource_ = oldFragment;
    return false;
  }
  for (auto& [variant, old] : previous) dropProgram(old);
  program_ = first;
  // shader_assembly.cpp's kHasBeamDefine: the interval method's shaders have a beam pass.
  hasBeam_ = fragmentSource_.find("\n#define RT_HAS_BEAM\n") != std::string::npos;
  return true;
}

RayTracer::Variant RayTracer::variantFor(const RenderSettings& s) {
  Variant v;
  v.samples = std::clamp(s.samples, 1, 16);
  v.maxHits = s.opacity < 1.0 ? std::clamp(s.tracing.hits, 1, 8) : 1;
  v.reflection = s.reflection.enabled;
  v.shading = shadingDefines(s);
  return v;
}

unsigned RayTracer::program(const Variant& v, std::string& log) {
  if (auto it = programs_.find(v); it != programs_.end()) return it->second;
  // The defines go right after #version, which must stay the first line.
  std::string source = fragmentSource_;
  const std::size_t eol = source.find('\n');
  const std::string defines = "#define RT_SAMPLES " + std::to_string(v.samples) +
                              "\n#define RT_MAX_HITS " + std::to_string(v.maxHits) +
                              "\n#define RT_REFLECTION " + (v.reflection ? "1" : "0") +
                              "\n#define RT_BEAM_TILE " + std::to_string(kBeamTile) + "\n" +
                              (v.beam ? "#define RT_BEAM\n" : "") +
                              (v.tileMask ? "#define RT_TILE_MASK\n" : "") + v.shading +
                              "#line 2 0\n";
  source.insert(eol == std::string::npos ? source.size() : eol + 1, defines);
  const unsigned p = compileProgram(vertexSource_, source, log);
  if (!p) return 0;  // the variants that work stay, so going back to them still works
  // Editing a light makes a new variant each time: keep only the current lighting's.
  for (auto it = programs_.begin(); it != programs_.end();) {
    if (it->first.shading == v.shading) {
      ++it;
      continue;
    }
    if (it->second == program_) program_ = 0;
    dropProgram(it->second);
    it = programs_.erase(it);
  }
  programs_.emplace(v, p);
  return p;
}

void RayTracer::deletePrograms() {
  for (auto& [variant, p] : programs_) dropProgram(p);
  programs_.clear();
  program_ = 0;
}

void RayTracer::dropProgram(unsigned p) {
  glDeleteProgram(p);
  locations_.erase(p);  // GL may hand the id out again
}

int RayTracer::uniform(const char* name) {
  auto& cache = locations_[program_];
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, glGetUniformLocation(program_, name)).first;
  return it->second;
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
  if (!hasBeam_ || !beamPass_) return false;
  Variant v = preferred_;
  v.beam = true;
  std::string log;
  const unsigned beam = program(v, log);
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
  const unsigned main = program_;
  program_ = beam;
  glUseProgram(beam);
  glBindFramebuffer(GL_FRAMEBUFFER, beamFbo_);
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &buffer);
  // The full picture's uniforms: the beam shader finds each tile's rays from rt.resolution.
  const int vertices = setUniforms(settings, domain, width, height);
  setDrawState(w, h);
  // Tiles no fragment covers say nothing: start at 0 with no first segment hint.
  glDisable(GL_SCISSOR_TEST);
  const float none[4] = {0.0f, std::numeric_limits<float>::max(), 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, none);
  if (vertices > 0) glDrawArrays(GL_TRIANGLES, 0, vertices);
  program_ = main;
  glUseProgram(main);
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
  Variant v = preferred_;
  v.tileMask = true;
  std::string log;
  const unsigned mask = program(v, log);
  if (!mask) return;  // every tile is shaded (the picture is the same)
  if (!tileBuffer_) glGenBuffers(1, &tileBuffer_);
  glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(runs.size() * sizeof(float)), runs.data(),
               GL_STREAM_DRAW);
  glBindVertexArray(vao_);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const unsigned main = program_;
  program_ = mask;
  glUseProgram(mask);
  glUniform1i(uniform("rtProxy"), 2);  // the rectangles (fullscreen.vert.glsl)
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
  program_ = main;
  glUseProgram(main);
}

void RayTracer::drawFrame() {
  if (vertices_ > 0) glDrawArrays(GL_TRIANGLES, 0, vertices_);
  glDisable(GL_STENCIL_TEST);
}

void RayTracer::releaseTarget() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (colorTex_) glDeleteTextures(1, &colorTex_);
  if (depthTex_) glDeleteTextures(1, &depthTex_);
  if (valueTex_) glDeleteTextures(1, &valueTex_);
  if (stencil_) glDeleteRenderbuffers(1, &stencil_);
  fbo_ = colorTex_ = depthTex_ = valueTex_ = stencil_ = 0;
  targetWidth_ = targetHeight_ = 0;
}

std::string RayTracer::ensureTarget(int width, int height) {
  if (fbo_ && width == targetWidth_ && height == targetHeight_) return {};
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
    return "image size " + std::to_string(width) + "x" + std::to_string(height) +
           " is outside 1.." + std::to_string(maxSize);
  releaseTarget();
  auto makeTexture = [&](GLenum internal, GLenum format, GLenum type) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return tex;
  };
  colorTex_ = makeTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
  depthTex_ = makeTexture(GL_R32F, GL_RED, GL_FLOAT);  // distance to the first hit
  valueTex_ = makeTexture(GL_R32F, GL_RED, GL_FLOAT);  // curvature colorings: the curvature
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colorTex_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, depthTex_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, valueTex_, 0);
  // For tile skipping (markClearTiles); depth and stencil come in one format everywhere.
  glGenRenderbuffers(1, &stencil_);
  glBindRenderbuffer(GL_RENDERBUFFER, stencil_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    releaseTarget();
    return "offscreen framebuffer incomplete (status " + std::to_string(status) + ")";
  }
  targetWidth_ = width;
  targetHeight_ = height;
  return {};
}

std::string RayTracer::prepare(const RenderSettings& settings, const Domain& domain, int width,
                               int height, bool offscreen) {
  if (!program_) return "the ray tracer has no shader program (build() first)";
  if (width <= 0 || height <= 0) return "image size must be positive";
  std::string log;
  preferred_ = variantFor(settings);
  const unsigned variant = program(preferred_, log);
  if (!variant) return "the shader variant for these settings does not compile:\n" + log;
  program_ = variant;
  if (offscreen) {
    if (std::string error = ensureTarget(width, height); !error.empty()) return error;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(3, buffers);
  }
  glUseProgram(program_);
  glDisable(GL_STENCIL_TEST);  // the curvature probe and the beam shade every pixel
  curvatureRange_ = needsCurvature(settings.shading.color)
                        ? resolveCurvatureRange(settings, domain, width, height)
                        : 0;
  const bool beam = drawBeam(settings, domain, width, height);
  if (offscreen) glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  vertices_ = setUniforms(settings, domain, width, height);
  setDrawState(width, height);
  clearBackground(settings, offscreen);
  if (beam && tileSkipping_ && vertices_ > 0) markClearTiles(width, height);
  if (beam) {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, beamTex_);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(uniform("rtBeamOn"), 1);  // its unit, 1, is set with the other uniforms
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
  if (!ensureTarget(std::max(width, 1), std::max(height, 1)).empty()) return 1;
  const int w = std::max(width / 4, 1), h = std::max(height / 4, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(3, buffers);
  RenderSettings probe = settings;
  probe.shading.curvatureRange = 1;
  const int vertices = setUniforms(probe, domain, w, h);
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
