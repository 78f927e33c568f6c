// depth_check FILE.pfm [MIN_FRACTION]: exits 0 when FILE is a grayscale PFM ("Pf") in which
// at least MIN_FRACTION (default 0.01) of the pixels hold a finite depth, i.e. the picture
// `zeroset render --depth` wrote shows some surface. Self-contained on purpose: the example
// tests must not depend on the renderer's own image code they are checking.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: depth_check FILE.pfm [MIN_FRACTION]\n");
    return 2;
  }
  const double minFraction = argc == 3 ? std::atof(argv[2]) : 0.01;
  std::FILE* f = std::fopen(argv[1], "rb");
  if (!f) {
    std::fprintf(stderr, "depth_check: cannot open %s\n", argv[1]);
    return 1;
  }
  char magic[3] = {};
  int w = 0, h = 0;
  double scale = 0;
  if (std::fscanf(f, "%2s %d %d %lf", magic, &w, &h, &scale) != 4 ||
      std::strcmp(magic, "Pf") != 0 || w <= 0 || h <= 0 || scale == 0 || std::fgetc(f) == EOF) {
    std::fprintf(stderr, "depth_check: %s is not a grayscale PFM\n", argv[1]);
    std::fclose(f);
    return 1;
  }
  std::vector<std::uint32_t> raw(std::size_t(w) * h);
  const std::size_t got = std::fread(raw.data(), 4, raw.size(), f);
  std::fclose(f);
  if (got != raw.size()) {
    std::fprintf(stderr, "depth_check: %s is truncated\n", argv[1]);
    return 1;
  }
  const bool swap = (scale < 0) != (std::endian::native == std::endian::little);
  std::size_t finite = 0, nan = 0;
  for (std::uint32_t bits : raw) {
    const float v = std::bit_cast<float>(swap ? __builtin_bswap32(bits) : bits);
    if (std::isnan(v))
      ++nan;
    else if (std::isfinite(v) && v > 0)
      ++finite;
  }
  const double fraction = double(finite) / double(raw.size());
  std::printf("%s: %dx%d, %.1f%% of the pixels hit the surface\n", argv[1], w, h, 100 * fraction);
  if (nan > 0) {
    std::fprintf(stderr, "depth_check: %zu NaN depths\n", nan);
    return 1;
  }
  if (fraction < minFraction) {
    std::fprintf(stderr,
                 "depth_check: only %.2f%% of the pixels show the surface (want >= %.2f%%)\n",
                 100 * fraction, 100 * minFraction);
    return 1;
  }
  return 0;
}
