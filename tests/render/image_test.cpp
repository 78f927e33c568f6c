// PNG/PFM round trips, the PFM byte layout the CLI promises, and the diff metric.
#include "render/image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace zs {
namespace {

Image gradientImage(int w, int h) {
  Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = std::uint8_t(x * 255 / (w - 1));
      p[1] = std::uint8_t(y * 255 / (h - 1));
      p[2] = std::uint8_t((x + y) % 256);
      p[3] = 255;
    }
  return image;
}

TEST(Image, PngRoundTripIsExact) {
  const Image image = gradientImage(17, 9);
  const std::string path = ::testing::TempDir() + "zs_roundtrip.png";
  ASSERT_EQ(writePng(path, image), "");
  Image back;
  ASSERT_EQ(readPng(path, back), "");
  EXPECT_EQ(back.width, 17);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.rgba, image.rgba);
}

TEST(Image, PngErrorsAreMessagesNotCrashes) {
  Image out;
  EXPECT_NE(readPng("/nonexistent/zs.png", out), "");
  const std::string garbage = ::testing::TempDir() + "zs_garbage.png";
  std::ofstream(garbage) << "not a png at all";
  EXPECT_NE(readPng(garbage, out), "");
  EXPECT_NE(writePng(::testing::TempDir() + "zs_empty.png", Image{}), "");
  EXPECT_NE(writePng("/nonexistent/dir/zs.png", gradientImage(4, 4)), "");
}

TEST(Image, PfmHeaderAndBottomUpLittleEndianRows) {
  const float inf = std::numeric_limits<float>::infinity();
  DepthMap depth{2, 2, {1.5f, inf, 3.0f, 4.25f}};  // top row (1.5, inf), bottom (3, 4.25)
  const std::string path = ::testing::TempDir() + "zs_depth.pfm";
  ASSERT_EQ(writePfm(path, depth), "");
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string data = bytes.str();
  const std::string header = "Pf\n2 2\n-1\n";
  ASSERT_EQ(data.size(), header.size() + 16);
  EXPECT_EQ(data.substr(0, header.size()), header);
  float raster[4];
  std::memcpy(raster, data.data() + header.size(), 16);  // this machine is little-endian
  EXPECT_EQ(raster[0], 3.0f);                            // the file starts with the bottom row
  EXPECT_EQ(raster[1], 4.25f);
  EXPECT_EQ(raster[2], 1.5f);
  EXPECT_TRUE(std::isinf(raster[3]));

  DepthMap back;
  ASSERT_EQ(readPfm(path, back), "");
  EXPECT_EQ(back.width, 2);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.at(0, 0), 1.5f);
  EXPECT_TRUE(std::isinf(back.at(1, 0)));
  EXPECT_EQ(back.at(1, 1), 4.25f);
}

TEST(Image, PfmRejectsOtherFormats) {
  const std::string path = ::testing::TempDir() + "zs_color.pfm";
  std::ofstream(path) << "PF\n1 1\n-1\n............";
  DepthMap out;
  EXPECT_NE(readPfm(path, out), "");
  std::ofstream(path) << "Pf\n4 4\n-1\n";  // truncated raster
  EXPECT_NE(readPfm(path, out), "");
}

TEST(Image, DiffMetricCountsPixelsOverThreshold) {
  const Image a = gradientImage(10, 10);
  ImageDiff same = compareImages(a, a);
  EXPECT_TRUE(same.sameSize);
  EXPECT_EQ(same.fractionOver, 0.0);
  EXPECT_EQ(same.rmse, 0.0);
  EXPECT_TRUE(withinTolerance(same));

  Image b = a;
  b.pixel(3, 4)[1] = std::uint8_t(b.pixel(3, 4)[1] ^ 0x80);  // one pixel, far off
  b.pixel(5, 5)[0] = std::uint8_t(b.pixel(5, 5)[0] < 250 ? b.pixel(5, 5)[0] + 5 : 0);  // small
  const ImageDiff diff = compareImages(a, b);
  EXPECT_DOUBLE_EQ(diff.fractionOver, 0.01);  // only the far pixel counts
  EXPECT_EQ(diff.maxDifference, 128);
  EXPECT_GT(diff.rmse, 0.0);
  EXPECT_FALSE(withinTolerance(diff, 0.0));
  EXPECT_TRUE(withinTolerance(diff, 0.02, 0.05));

  EXPECT_FALSE(compareImages(a, gradientImage(10, 11)).sameSize);
  EXPECT_FALSE(withinTolerance(compareImages(a, gradientImage(10, 11))));
}

}  // namespace
}  // namespace zs
