#pragma once
// The picture formats surf writes (src/surfscript's `surf` command): JPEG (libjpeg, quality
// 90 as surf's), binary PPM (P6) and 24-bit Sun raster, besides PNG. Each file is written
// whole or not at all: into a temporary file beside it, renamed over the name at the end.
#include <string>

#include "render/image.hpp"

namespace zs {

enum class PictureFormat { Png, Jpeg, Ppm, Sun };

// "" on success, else a message naming the file.
std::string writePicture(const std::string& path, const Image& image, PictureFormat format);

}  // namespace zs
