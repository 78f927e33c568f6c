// Which tiles tile skipping marks off after a beam pass (render/beam_tiles.hpp); no GL.
#include "render/beam_tiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace zs {
namespace {

constexpr float kClear = std::numeric_limits<float>::max();

// tilesX x tilesY texels of (start, segment), bottom row first; '#' clear, '.' open.
std::vector<float> beamOf(const std::vector<const char*>& rowsTopFirst) {
  std::vector<float> beam;
  for (auto row = rowsTopFirst.rbegin(); row != rowsTopFirst.rend(); ++row)
    for (const char* c = *row; *c; ++c) {
      beam.push_back(*c == '#' ? kClear : 1.5f);
      beam.push_back(0.25f);
    }
  return beam;
}

// The pixels (column, row from the bottom) the rectangles cover, by their pixel centers.
std::vector<std::vector<int>> coverage(const std::vector<float>& runs, int width, int height) {
  std::vector<std::vector<int>> covered(height, std::vector<int>(width, 0));
  for (std::size_t r = 0; r + 12 <= runs.size(); r += 12) {
    // Each run is the rectangle spanned by its first triangle's corners (l, b) and (r, t).
    const double l = (runs[r] + 1) / 2 * width, b = (runs[r + 1] + 1) / 2 * height;
    const double rt = (runs[r + 4] + 1) / 2 * width, t = (runs[r + 5] + 1) / 2 * height;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        covered[y][x] += x + 0.5 > l && x + 0.5 < rt && y + 0.5 > b && y + 0.5 < t;
  }
  return covered;
}

TEST(BeamTiles, ClearMeansTheLargestFloat) {
  EXPECT_TRUE(beamTileIsClear(kClear));
  EXPECT_FALSE(beamTileIsClear(3.0e38f));
  EXPECT_FALSE(beamTileIsClear(0.0f));
  EXPECT_FALSE(beamTileIsClear(std::nanf("")));  // unknown: shaded
}

TEST(BeamTiles, RunsCoverExactlyTheClearTiles) {
  const std::vector<const char*> rows = {"##..#", ".###.", "....."};
  const int tile = 4, width = 20, height = 12;
  const std::vector<float> runs = clearTileRuns(beamOf(rows), 5, 3, tile, width, height);
  EXPECT_EQ(runs.size(), 3u * 12);  // one run per row with clear tiles, two in the top row
  const auto covered = coverage(runs, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool clear = rows[2 - y / tile][x / tile] == '#';
      EXPECT_EQ(covered[y][x], clear ? 1 : 0) << "pixel " << x << ", " << y;
    }
}

TEST(BeamTiles, PartialTilesStopAtThePicturesEdge) {
  // 10 x 6 pixels in tiles of 4: the last column and row of tiles are partial.
  const std::vector<float> runs = clearTileRuns(beamOf({"###", "###"}), 3, 2, 4, 10, 6);
  ASSERT_EQ(runs.size(), 2u * 12);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    EXPECT_GE(runs[k], -1.0f);
    EXPECT_LE(runs[k], 1.0f);
  }
  const auto covered = coverage(runs, 10, 6);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 10; ++x) EXPECT_EQ(covered[y][x], 1);
}

TEST(BeamTiles, NothingToMarkWhenNothingIsClearOrTheSizesDisagree) {
  EXPECT_TRUE(clearTileRuns(beamOf({"...", "..."}), 3, 2, 4, 12, 8).empty());
  EXPECT_TRUE(clearTileRuns(beamOf({"###"}), 3, 2, 4, 12, 8).empty());  // one row short
  EXPECT_TRUE(clearTileRuns(beamOf({"###"}), 3, 1, 0, 12, 8).empty());
  EXPECT_TRUE(clearTileRuns({}, 0, 0, 4, 12, 8).empty());
}

}  // namespace
}  // namespace zs
