#include "render/image.hpp"

#include <png.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace zs {
namespace {

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

FilePtr open(const std::string& path, const char* mode) {
  return FilePtr(std::fopen(path.c_str(), mode), &std::fclose);
}

}  // namespace

std::string writePng(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t(image.width) * image.height * 4)
    return "cannot write " + path + ": image has no pixels or a wrong buffer size";
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = image.width;
  png.height = image.height;
  png.format = PNG_FORMAT_RGBA;
  if (!png_image_write_to_file(&png, path.c_str(), 0, image.rgba.data(), 0, nullptr)) {
    std::string message = "cannot write " + path + ": " + png.message;
    png_image_free(&png);
    return message;
  }
  return {};
}

std::string readPng(const std::string& path, Image& out) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    return "cannot read " + path + ": " + png.message;
  png.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr)) {
    std::string message = "cannot read " + path + ": " + png.message;
    png_image_free(&png);
    return message;
  }
  out.width = int(png.width);
  out.height = int(png.height);
  out.rgba = std::move(pixels);
  return {};
}

std::string writePfm(const std::string& path, const DepthMap& depth) {
  if (depth.width <= 0 || depth.height <= 0 ||
      depth.values.size() != std::size_t(depth.width) * depth.height)
    return "cannot write " + path + ": depth map has no pixels or a wrong buffer size";
  FilePtr file = open(path, "wb");
  if (!file) return "cannot open " + path + " for writing: " + std::strerror(errno);
  std::fprintf(file.get(), "Pf\n%d %d\n-1\n", depth.width, depth.height);
  std::vector<std::uint32_t> row(depth.width);
  for (int y = depth.height - 1; y >= 0; --y) {  // PFM stores the bottom row first
    for (int x = 0; x < depth.width; ++x) {
      std::uint32_t bits = std::bit_cast<std::uint32_t>(depth.at(x, y));
      if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
      row[x] = bits;
    }
    if (std::fwrite(row.data(), 4, row.size(), file.get()) != row.size())
      return "cannot write " + path + ": short write";
  }
  return {};
}

std::string readPfm(const std::string& path, DepthMap& out) {
  FilePtr file = open(path, "rb");
  if (!file) return "cannot open " + path + ": " + std::strerror(errno);
  char magic[3] = {};
  int width = 0, height = 0;
  double scale = 0;
  // The header is three whitespace-separated tokens and exactly one whitespace byte
  // before the raster.
  if (std::fscanf(file.get(), "%2s %d %d %lf", magic, &width, &height, &scale) != 4 ||
      std::strcmp(magic, "Pf") != 0 || width <= 0 || height <= 0 || scale == 0 ||
      std::fgetc(file.get()) == EOF)
    return "cannot read " + path + ": not a grayscale PFM (\"Pf\") file";
  if (std::size_t(width) * std::size_t(height) > (std::size_t(1) << 30))
    return "cannot read " + path + ": implausible size";
  const bool little = scale < 0;
  const bool swap = little != (std::endian::native == std::endian::little);
  out.width = width;
  out.height = height;
  out.values.assign(std::size_t(width) * height, 0.0f);
  std::vector<std::uint32_t> row(width);
  for (int y = height - 1; y >= 0; --y) {
    if (std::fread(row.data(), 4, row.size(), file.get()) != row.size())
      return "cannot read " + path + ": truncated raster";
    for (int x = 0; x < width; ++x)
      out.values[std::size_t(y) * width + x] =
          std::bit_cast<float>(swap ? __builtin_bswap32(row[x]) : row[x]);
  }
  return {};
}

ImageDiff compareImages(const Image& a, const Image& b, int threshold) {
  ImageDiff diff;
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size() ||
      a.rgba.empty())
    return diff;
  diff.sameSize = true;
  std::size_t over = 0;
  double sumSquares = 0;
  int worst = 0;
  const std::size_t pixels = a.rgba.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    int pixelWorst = 0;
    for (int c = 0; c < 4; ++c) {
      const int d = std::abs(int(a.rgba[p * 4 + c]) - int(b.rgba[p * 4 + c]));
      pixelWorst = std::max(pixelWorst, d);
      sumSquares += double(d) * d;
    }
    worst = std::max(worst, pixelWorst);
    if (pixelWorst > threshold) ++over;
  }
  diff.fractionOver = double(over) / double(pixels);
  diff.rmse = std::sqrt(sumSquares / double(a.rgba.size())) / 255.0;
  diff.maxDifference = worst;
  return diff;
}

bool withinTolerance(const ImageDiff& diff, double maxFraction, double maxRmse) {
  return diff.sameSize && diff.fractionOver <= maxFraction && diff.rmse <= maxRmse;
}

}  // namespace zs
