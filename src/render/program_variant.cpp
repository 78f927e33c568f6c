#include "render/program_variant.hpp"

#include <algorithm>

#include "render/shading_defines.hpp"

namespace zs {

ProgramVariant ProgramVariant::of(const RenderSettings& s) {
  ProgramVariant v;
  v.samples = std::clamp(s.samples, 1, 16);
  v.maxHits = s.opacity < 1.0 ? std::clamp(s.tracing.hits, 1, 8) : 1;
  v.reflection = s.reflection.enabled;
  v.shading = shadingDefines(s);
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
      v.shading + "#line 2 0\n";
  source.insert(eol == std::string::npos ? source.size() : eol + 1, defines);
  return source;
}

}  // namespace zs
