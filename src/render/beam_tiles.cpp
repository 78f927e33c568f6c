// The clear tiles of a beam pass as runs of rectangles (beam_tiles.hpp).
#include "render/beam_tiles.hpp"

#include <algorithm>
#include <limits>

namespace zs {

bool beamTileIsClear(float start) {
  return start >= std::numeric_limits<float>::max();
}

std::vector<float> clearTileRuns(std::span<const float> beam, int tilesX, int tilesY, int tile,
                                 int width, int height) {
  std::vector<float> runs;
  if (tilesX <= 0 || tilesY <= 0 || tile <= 0 || width <= 0 || height <= 0 ||
      beam.size() != std::size_t(tilesX) * std::size_t(tilesY) * 2)
    return runs;
  // A pixel edge p of a picture `size` pixels across, in clip space.
  auto clip = [](int p, int size) { return 2.0f * float(p) / float(size) - 1.0f; };
  // Pixel columns x0..x1 and rows y0..y1 (bottom-up) as two counter-clockwise triangles.
  auto addRectangle = [&](int x0, int x1, int y0, int y1) {
    const float l = clip(x0, width), r = clip(x1, width);
    const float b = clip(y0, height), t = clip(y1, height);
    const float corners[12] = {l, b, r, b, r, t, l, b, r, t, l, t};
    for (float c : corners) runs.push_back(c);
  };
  for (int j = 0; j < tilesY && j * tile < height; ++j) {
    int first = -1;  // where the current run of clear tiles began
    for (int i = 0; i <= tilesX; ++i) {
      const bool clear = i < tilesX && i * tile < width &&
                         beamTileIsClear(beam[(std::size_t(j) * tilesX + i) * 2]);
      if (clear && first < 0) first = i;
      if (!clear && first >= 0) {
        addRectangle(first * tile, std::min(i * tile, width), j * tile,
                     std::min((j + 1) * tile, height));
        first = -1;
      }
    }
  }
  return runs;
}

}  // namespace zs
