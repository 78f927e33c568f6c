#include "render/image_formats.hpp"

#include <jpeglib.h>
#include <unistd.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace zs {

namespace {

std::vector<unsigned char> rgbRows(const Image& image) {
  std::vector<unsigned char> rgb(std::size_t(image.width) * image.height * 3);
  for (std::size_t i = 0, n = std::size_t(image.width) * image.height; i < n; ++i)
    std::memcpy(&rgb[i * 3], &image.rgba[i * 4], 3);
  return rgb;
}

bool writeAll(std::FILE* f, const void* data, std::size_t size) {
  return std::fwrite(data, 1, size, f) == size;
}

std::string writePpm(std::FILE* f, const Image& image) {
  const std::string header =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  const auto rgb = rgbRows(image);
  if (!writeAll(f, header.data(), header.size()) || !writeAll(f, rgb.data(), rgb.size()))
    return std::strerror(errno);
  return {};
}

void bigEndian(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<unsigned char>(v >> shift));
}

// Sun raster, RT_STANDARD, 24 bits: pixels in B, G, R order, rows padded to 16 bits.
std::string writeSun(std::FILE* f, const Image& image) {
  const std::size_t rowBytes = (std::size_t(image.width) * 3 + 1) & ~std::size_t(1);
  std::vector<unsigned char> out;
  out.reserve(32 + rowBytes * image.height);
  for (std::uint32_t v : {0x59a66a95u, std::uint32_t(image.width), std::uint32_t(image.height), 24u,
                          std::uint32_t(rowBytes * image.height), 1u, 0u, 0u})
    bigEndian(out, v);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      out.insert(out.end(), {p[2], p[1], p[0]});
    }
    if (rowBytes > std::size_t(image.width) * 3) out.push_back(0);
  }
  if (!writeAll(f, out.data(), out.size())) return std::strerror(errno);
  return {};
}

struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void onJpegError(j_common_ptr info) {
  auto* e = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, e->message);
  std::longjmp(e->jump, 1);
}

std::string writeJpeg(std::FILE* f, const Image& image) {
  const auto rgb = rgbRows(image);
  jpeg_compress_struct info{};
  JpegError error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = onJpegError;
  if (setjmp(error.jump)) {
    jpeg_destroy_compress(&info);
    return error.message;
  }
  jpeg_create_compress(&info);
  jpeg_stdio_dest(&info, f);
  info.image_width = JDIMENSION(image.width);
  info.image_height = JDIMENSION(image.height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 90, TRUE);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(&rgb[std::size_t(info.next_scanline) * image.width * 3]);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  return {};
}

}  // namespace

std::string writePicture(const std::string& path, const Image& image, PictureFormat format) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t(image.width) * image.height * 4)
    return "cannot write " + path + ": image has no pixels or a wrong buffer size";
  const std::string temporary = path + ".zeroset-" + std::to_string(getpid()) + ".tmp";
  std::string err;
  if (format == PictureFormat::Png) {
    err = writePng(temporary, image);
  } else {
    std::FILE* f = std::fopen(temporary.c_str(), "wb");
    if (!f) return "cannot write " + path + ": " + std::strerror(errno);
    err = format == PictureFormat::Jpeg  ? writeJpeg(f, image)
          : format == PictureFormat::Ppm ? writePpm(f, image)
                                         : writeSun(f, image);
    if (std::fclose(f) != 0 && err.empty()) err = std::strerror(errno);
    if (!err.empty()) err = "cannot write " + path + ": " + err;
  }
  std::error_code ec;
  if (err.empty()) {
    std::filesystem::rename(temporary, path, ec);
    if (ec) err = "cannot write " + path + ": " + ec.message();
  }
  if (!err.empty()) std::filesystem::remove(temporary, ec);
  return err;
}

}  // namespace zs
