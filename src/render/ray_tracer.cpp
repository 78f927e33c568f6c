// RayTracer: the order of a frame's passes (curvature probe, beam and tile mask, the frame
// itself) and the tiled render. The parts live beside it: the programs in program_cache.hpp,
// the offscreen framebuffer in offscreen_target.hpp, the beam pass and tile skipping in
// beam_pass.hpp, the probe and the read-back in frame_readback.hpp, the uniform values in
// frame_uniforms.hpp (applied by ray_tracer_uniforms.cpp).
#include "render/ray_tracer.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "render/frame_readback.hpp"

namespace zs {
namespace {

// `texels` (4 words each) into `buffer`, viewed by `texture` as an RGBA32UI buffer texture
// (both made at the first call), padded with zeros to a power of two of texels. Software
// rasterizers key their compiled shaders on whether a texture's size is a power of two
// (llvmpipe does): a hierarchy or tape of another size would otherwise make the same
// program compile again, a pause of up to a second. Also never a zero-size store, which is
// not a valid texture-buffer source.
void fillTextureBuffer(unsigned& buffer, unsigned& texture, std::span<const std::uint32_t> texels) {
  if (!buffer) glGenBuffers(1, &buffer);
  if (!texture) glGenTextures(1, &texture);
  std::size_t count = 1;
  while (count < texels.size() / 4) count *= 2;
  std::vector<std::uint32_t> padded(count * 4, 0);
  std::copy(texels.begin(), texels.end(), padded.begin());
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(padded.size() * 4), padded.data(), GL_STATIC_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, texture);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, buffer);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

// GL_RENDERER of the current context ("" if the driver gives none).
std::string_view rendererName() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "";
}

}  // namespace

RayTracer::RayTracer() : RayTracer(frameStorageFor(rendererName())) {}

RayTracer::RayTracer(FrameStorage storage) : preferred_(ProgramVariant::of(RenderSettings{})) {
  programs_.setFrameStorage(storage);
  glGenVertexArrays(1, &vao_);
}

RayTracer::~RayTracer() {
  if (nodeTexture_) glDeleteTextures(1, &nodeTexture_);
  if (nodeBuffer_) glDeleteBuffers(1, &nodeBuffer_);
  if (tapeTexture_) glDeleteTextures(1, &tapeTexture_);
  if (tapeBuffer_) glDeleteBuffers(1, &tapeBuffer_);
  glDeleteVertexArrays(1, &vao_);
}

bool RayTracer::build(std::string_view vertexSource, std::string_view fragmentSource,
                      const RenderSettings& drawnWith, std::string& log) {
  // The same text again (a parameter or level change) keeps the programs: llvmpipe's JIT of
  // a new one costs a visible pause.
  if (program_ && programs_.holds(vertexSource, fragmentSource)) return true;
  // Not the last frame's variant: a new surface's shader may not have what that one calls.
  const ProgramVariant first = ProgramVariant::of(drawnWith);
  const unsigned program = programs_.rebuild(vertexSource, fragmentSource, first, log);
  if (!program) return false;  // the programs built before stay
  program_ = program;
  preferred_ = first;
  return true;
}

std::string RayTracer::setHierarchy(std::span<const float> packed) {
  GpuHierarchy gpu;
  if (std::string error = toGpuHierarchy(packed, gpu); !error.empty()) return error;
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  if (gpu.count > maxTexels)
    return "hierarchy: " + std::to_string(gpu.count) +
           " nodes exceed GL_MAX_TEXTURE_BUFFER_SIZE (" + std::to_string(maxTexels) + ")";
  fillTextureBuffer(nodeBuffer_, nodeTexture_, gpu.texels);
  hierarchy_ = std::move(gpu);
  return {};
}

std::string RayTracer::setTape(std::span<const std::uint32_t> texels) {
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  if (texels.empty() || texels.size() % 4 != 0 || GLint(texels.size() / 4) > maxTexels)
    return "tape: " + std::to_string(texels.size() / 4) + " texels do not fit a buffer texture";
  fillTextureBuffer(tapeBuffer_, tapeTexture_, texels);
  return {};
}

void RayTracer::setParams(std::span<const float> params) {
  params_.assign(params.begin(), params.end());
}

bool RayTracer::drawBeam(const RenderSettings& settings, const Domain& domain, int width,
                         int height) {
  if (!programs_.hasBeam() || !beamPass_ || preferred_.volume) return false;  // no walk
  ProgramVariant v = preferred_;
  v.beam = true;
  std::string log;
  const unsigned beam = programs_.get(v, log);
  if (!beam) return false;  // the pixels then walk on their own (the picture is the same)
  return beam_.draw(
      beam,
      [&](unsigned program, int w, int h) {
        const int vertices = setUniforms(program, settings, domain, width, height);
        setDrawState(w, h);
        return vertices;
      },
      width, height);
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
  curvatureRange_ = needsCurvature(settings.shading.color) && settings.mode == RenderMode::Surface
                        ? resolveCurvatureRange(settings, domain, width, height)
                        : 0;
  const bool beam = drawBeam(settings, domain, width, height);
  if (offscreen) target_.bind();
  vertices_ = setUniforms(program_, settings, domain, width, height);
  setDrawState(width, height);
  clearBackground(settings, offscreen);
  if (beam && tileSkipping_ && vertices_ > 0) {
    auto mask = [&] {
      ProgramVariant v = preferred_;
      v.tileMask = true;
      std::string log;
      return programs_.get(v, log);
    };
    beam_.markClearTiles(mask, vao_, width, height);
  }
  if (beam) {
    beam_.bindResult();
    glUniform1i(programs_.uniform(program_, "rtBeamOn"), 1);  // its unit, 1: frame_uniforms
  }
  return {};
}

void RayTracer::setDrawState(int width, int height) {
  if (tapeTexture_) {
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_BUFFER, tapeTexture_);
  }
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
  RenderSettings probe = settings;
  probe.shading.curvatureRange = 1;
  // A band's colors are the whole picture's: the range is measured on the whole view.
  if (bandRows_ > 0) height = fullHeight_;
  const int band = std::exchange(bandRows_, 0);
  const double range =
      probeCurvatureRange(target_, settings, domain, width, height, [&](int w, int h) {
        const int vertices = setUniforms(program_, probe, domain, w, h);
        setDrawState(w, h);
        clearBackground(settings, true);
        if (vertices > 0) glDrawArrays(GL_TRIANGLES, 0, vertices);
      });
  bandRows_ = band;
  return range;
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

Frame RayTracer::renderBand(const RenderSettings& settings, const Domain& domain, int width,
                            int height, int top, int rows, const ProgressFn& progress) {
  if (rows <= 0 || top < 0 || top + rows > height || (height - top - rows) % kBeamTile != 0) {
    Frame frame;
    frame.error = "band of rows " + std::to_string(top) + " to " + std::to_string(top + rows) +
                  " of " + std::to_string(height) + ": its bottom edge must lie on the " +
                  std::to_string(kBeamTile) + "-pixel grid counted from the picture's bottom";
    return frame;
  }
  fullHeight_ = height;
  bandTop_ = top;
  bandRows_ = rows == height ? 0 : rows;
  Frame frame = render(settings, domain, width, rows, progress);
  bandRows_ = 0;
  return frame;
}

Frame RayTracer::render(const RenderSettings& settings, const Domain& domain, int width, int height,
                        const ProgressFn& progress, int tileSize) {
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

  frame = readFrame(target_, width, height, needsCurvature(settings.shading.color));
  frame.curvatureRange = curvatureRange_;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return frame;
}

}  // namespace zs
