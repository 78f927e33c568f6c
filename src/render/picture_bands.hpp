#pragma once
// A picture cut into horizontal bands for RayTracer::renderBand (zeroset render --tile):
// takes the picture's height and the number of bands, puts out band i's rows. The cuts lie
// on the beam pass's tile grid counted from the picture's bottom (kBeamTile rows), so every
// band traces exactly the rays of the whole picture; the bands are as even as that allows,
// the top one taking the partial tile row. GL-free.
#include <cstdint>
#include <optional>

#include "render/program_variant.hpp"

namespace zs {

struct PictureBand {
  int top = 0, rows = 0;  // rows [top, top + rows) from the picture's top
};

// Band `index` (0 = top) of `count`; nothing when count < 1, index is out of range or the
// picture has fewer tile rows than bands.
inline std::optional<PictureBand> pictureBand(int height, int index, int count) {
  const int tileRows = height / kBeamTile;  // whole tile rows, counted from the bottom
  if (count < 1 || index < 0 || index >= count || tileRows < count) return std::nullopt;
  // Distance of cut j from the bottom: the top edge (j = 0) is the picture's, the others
  // whole tile rows.
  auto fromBottom = [&](int j) {
    return j == 0 ? height : kBeamTile * int(std::int64_t(tileRows) * (count - j) / count);
  };
  const int top = height - fromBottom(index), bottom = height - fromBottom(index + 1);
  return PictureBand{top, bottom - top};
}

}  // namespace zs
