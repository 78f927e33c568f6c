#include "render/program_variant.hpp"

#include <algorithm>
#include <cstdlib>

#include "render/shading_defines.hpp"

namespace zs {

ProgramVariant ProgramVariant::of(const RenderSettings& s) {
  ProgramVariant v;
  v.samples = std::clamp(s.samples, 1, 16);
  v.maxHits = s.opacity < 1.0 ? std::clamp(s.tracing.hits, 1, 8) : 1;
  v.reflection = s.reflection.enabled;
  v.shading = shadingDefines(s);
  v.volume = s.mode == RenderMode::Volume;
  v.clipPlanes = int(cuttingPlanes(s.clipPlanes).size());
  return v;
}

std::string withVariantDefines(std::string_view fragment, const ProgramVariant& v) {
  // The defines go right after #version, which must stay the first line.
  std::string source(fragment);
  const std::size_t eol = source.find('\n');
  const std::string defines =
      "#define RT_SAMPLES " + std::to_string(v.samples) + "\n#define RT_MAX_HITS " +
      std::to_string(v.maxHits) + "\n#define RT_REFLECTION " + (v.reflection ? "1" : "0") +
      "\n#define RT_BEAM_TILE " + std::to_string(kBeamTile) + "\n" +
      (v.beam ? "#define RT_BEAM\n" : "") + (v.tileMask ? "#define RT_TILE_MASK\n" : "") +
      (v.volume ? "#define RT_VOLUME\n" : "") +
      (v.clipPlanes > 0 ? "#define RT_CLIP_PLANES " + std::to_string(v.clipPlanes) + "\n" : "") +
      v.shading + "#line 2 0\n";
  source.insert(eol == std::string::npos ? source.size() : eol + 1, defines);
  return source;
}

FrameStorage frameStorageFor(std::string_view renderer) {
  if (const char* forced = std::getenv("ZS_FRAME_STORAGE"); forced && *forced) {
    const std::string_view f = forced;
    if (f == "varyings") return FrameStorage::FlatVaryings;
    if (f == "uniforms") return FrameStorage::Uniforms;
  }
  const bool software = renderer.find("llvmpipe") != std::string_view::npos ||
                        renderer.find("softpipe") != std::string_view::npos;
  return software ? FrameStorage::FlatVaryings : FrameStorage::Uniforms;
}

std::string withFrameStorage(std::string_view source, FrameStorage storage) {
  std::string out(source);
  if (storage == FrameStorage::FlatVaryings) return out;
  const std::size_t eol = out.find('\n');
  out.insert(eol == std::string::npos ? out.size() : eol + 1,
             "#define RT_FRAME_UNIFORMS\n#line 2 0\n");
  return out;
}

}  // namespace zs
