#include "app/viewer/gallery_thumbnails.hpp"

#include <glad/gl.h>

#include <algorithm>

#include "render/image.hpp"

namespace zs::app {
namespace {

constexpr int kThumbWidth = 96;

// Box filter: each thumbnail pixel averages the source pixels it covers, so thin curves
// of the picture stay visible instead of aliasing away.
Image shrink(const Image& src, int width) {
  Image out;
  out.width = std::min(width, src.width);
  out.height = std::max(1, src.height * out.width / std::max(1, src.width));
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y) {
    const int y0 = y * src.height / out.height,
              y1 = std::max(y0 + 1, (y + 1) * src.height / out.height);
    for (int x = 0; x < out.width; ++x) {
      const int x0 = x * src.width / out.width,
                x1 = std::max(x0 + 1, (x + 1) * src.width / out.width);
      unsigned sum[4] = {0, 0, 0, 0};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += src.pixel(sx, sy)[c];
      const unsigned n = unsigned((y1 - y0) * (x1 - x0));
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = std::uint8_t(sum[c] / n);
    }
  }
  return out;
}

}  // namespace

GalleryThumbnails::~GalleryThumbnails() {
  for (auto& [path, entry] : cache_) {
    if (entry.texture != 0) glDeleteTextures(1, &entry.texture);
  }
}

std::uint32_t GalleryThumbnails::texture(const std::filesystem::path& png, float& aspect) {
  auto [it, fresh] = cache_.try_emplace(png);
  Entry& e = it->second;
  if (fresh) {
    Image full;
    if (readPng(png.string(), full).empty() && full.width > 0 && full.height > 0) {
      const Image small = shrink(full, kThumbWidth);
      GLuint tex = 0;
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, small.width, small.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, small.rgba.data());
      glBindTexture(GL_TEXTURE_2D, 0);
      e.texture = tex;
      e.aspect = float(small.width) / float(small.height);
    }
  }
  aspect = e.aspect;
  return e.texture;
}

}  // namespace zs::app
