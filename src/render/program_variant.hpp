#pragma once
// The compile-time features of a frame's fragment shader (supersampling, kept hits,
// reflection, lights and coloring, the beam pass and its tile mask): takes the
// RenderSettings, puts out the variant and the #define lines that select it, inserted
// right after #version. GL-free: the desktop's program cache (program_cache.hpp) and the web
// page (src/web) compile the same variants from the same text.
#include <string>
#include <string_view>
#include <tuple>

#include "render/settings.hpp"

namespace zs {

// Pixels per side of a beam pass tile (raytrace_beam.frag.glsl): the tile's rays share one
// walk through empty space. Smaller tiles enclose tighter but cost more beam fragments; 8
// measured best (docs/renderer.md).
inline constexpr int kBeamTile = 8;

struct ProgramVariant {
  int samples = 1, maxHits = 1;
  bool reflection = true;
  std::string shading;    // lights and coloring (render/shading_defines.hpp)
  bool beam = false;      // the beam pass's program (raytrace_beam.frag.glsl)
  bool tileMask = false;  // its tile mask's (the same file)
  bool volume = false;    // render.mode "volume" (raytrace_volume.frag.glsl)
  // Cutting clip planes (cuttingPlanes): a frame without any pays nothing for them; their
  // places are frame parameters, so moving one compiles nothing.
  int clipPlanes = 0;
  bool operator<(const ProgramVariant& o) const {
    return std::tie(samples, maxHits, reflection, shading, beam, tileMask, volume, clipPlanes) <
           std::tie(o.samples, o.maxHits, o.reflection, o.shading, o.beam, o.tileMask, o.volume,
                    o.clipPlanes);
  }
  // The frame's program for these settings.
  static ProgramVariant of(const RenderSettings& settings);
};

// `fragment` (whose first line is #version) with the variant's #define lines after that line.
std::string withVariantDefines(std::string_view fragment, const ProgramVariant& variant);

// How a desktop program's stages pass the frame's parameters (shader_assembly.hpp).
// FlatVaryings: the vertex stage reads the uniforms and hands them on as flat varyings,
// because llvmpipe gathers a uniform at every use in the fragment shader, while it reads a
// flat input once per group of pixels. The block needs more varying components (105) than
// GL 3.3 promises (60), and more than NVIDIA's linker places. Uniforms: the fragment stage reads
// them itself, as on WebGL2; for every other driver, where a uniform read costs no more than a
// varying.
enum class FrameStorage { FlatVaryings, Uniforms };

// FlatVaryings for Mesa's software rasterizers (GL_RENDERER names llvmpipe or softpipe),
// Uniforms for everything else; ZS_FRAME_STORAGE=varyings|uniforms in the environment
// overrides the choice (to compare the two on one driver).
FrameStorage frameStorageFor(std::string_view renderer);

// `source` (whose first line is #version) with the define that selects `storage`.
std::string withFrameStorage(std::string_view source, FrameStorage storage);

}  // namespace zs
