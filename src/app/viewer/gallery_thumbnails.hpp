#pragma once
// Thumbnails for the gallery window: the gallery's PNG of each example, read on first use,
// shrunk on the CPU and kept as small GL textures. Needs the viewer's GL context current,
// also when it is destroyed.
#include <cstdint>
#include <filesystem>
#include <map>

namespace zs::app {

class GalleryThumbnails {
 public:
  GalleryThumbnails() = default;
  GalleryThumbnails(const GalleryThumbnails&) = delete;
  GalleryThumbnails& operator=(const GalleryThumbnails&) = delete;
  ~GalleryThumbnails();

  // The texture of `png` (0 when it cannot be read), with its aspect ratio width/height.
  std::uint32_t texture(const std::filesystem::path& png, float& aspect);

 private:
  struct Entry {
    std::uint32_t texture = 0;
    float aspect = 1;
  };
  std::map<std::filesystem::path, Entry> cache_;
};

}  // namespace zs::app
