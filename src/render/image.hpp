#pragma once
// Images in and out of files: takes RGBA8 color images and float depth maps (both stored
// top row first), puts out PNG (libpng) and PFM files and reads them back; plus the
// tolerance metric the render tests compare against reference images with (never byte
// equality: llvmpipe versions and float rounding move pixels slightly).
#include <cstdint>
#include <string>
#include <vector>

namespace zs {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width*height*4, top row first

  std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

struct DepthMap {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // width*height, top row first; +inf where nothing was hit

  float at(int x, int y) const { return values[std::size_t(y) * width + x]; }
};

// All return an empty string on success, else a message naming the file.
std::string writePng(const std::string& path, const Image& image);
std::string readPng(const std::string& path, Image& out);  // any PNG, converted to RGBA8
// The PNGs `parts` (equal widths) one under the other into one RGBA8 PNG at `path`, holding
// one part in memory at a time (a poster of 20000 x 20000 pixels is 1.6 GB as one image).
// "" on success, else why not (the file may then be incomplete).
std::string stackPngs(const std::vector<std::string>& parts, const std::string& path);
// PFM: grayscale "Pf", scale -1 (little-endian), rows stored bottom to top as the format
// says; the in-memory map stays top-down.
std::string writePfm(const std::string& path, const DepthMap& depth);
std::string readPfm(const std::string& path, DepthMap& out);  // "Pf" only, either endianness

struct ImageDiff {
  bool sameSize = false;
  double fractionOver = 1;  // pixels whose largest channel difference exceeds the threshold
  double rmse = 1;          // over all channels, in [0, 1]
  int maxDifference = 255;  // largest channel difference, 0..255
};

ImageDiff compareImages(const Image& a, const Image& b, int threshold = 8);

// True when sizes agree, fractionOver <= maxFraction and rmse <= maxRmse.
bool withinTolerance(const ImageDiff& diff, double maxFraction = 0.01, double maxRmse = 0.02);

}  // namespace zs
