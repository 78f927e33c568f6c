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

std::string stackPngs(const std::vector<std::string>& parts, const std::string& path) {
  if (parts.empty()) return "nothing to stack: no PNG given";
  // The sizes first, from the headers: the output's header holds the total height.
  std::uint32_t width = 0, height = 0;
  for (const std::string& part : parts) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, part.c_str()))
      return "cannot read " + part + ": " + png.message;
    const std::uint32_t w = png.width, h = png.height;
    png_image_free(&png);
    if (width != 0 && w != width)
      return part + " is " + std::to_string(w) + " pixels wide, the parts before it " +
             std::to_string(width) + ": the parts of one picture have one width";
    width = w;
    if (height + std::uint64_t(h) > 0x7fffffffu) return "the stacked picture would be too tall";
    height += h;
  }
  FilePtr file = open(path, "wb");
  if (!file) return "cannot open " + path + " for writing: " + std::strerror(errno);
  png_structp writer = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = writer ? png_create_info_struct(writer) : nullptr;
  if (!info) {
    png_destroy_write_struct(&writer, nullptr);
    return "cannot write " + path + ": libpng could not start";
  }
  if (setjmp(png_jmpbuf(writer))) {  // libpng's errors land here
    png_destroy_write_struct(&writer, &info);
    return "cannot write " + path + ": libpng failed";
  }
  png_init_io(writer, file.get());
  png_set_IHDR(writer, info, width, height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(writer, info);
  for (const std::string& part : parts) {
    Image image;
    if (std::string err = readPng(part, image); !err.empty()) {
      png_destroy_write_struct(&writer, &info);
      return err;
    }
    for (int y = 0; y < image.height; ++y) png_write_row(writer, image.pixel(0, y));
  }
  png_write_end(writer, nullptr);
  png_destroy_write_struct(&writer, &info);
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
