#include "app/bench/fps_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/bench/bench_report.hpp"
#include "app/bench/canvas.hpp"
#include "app/bench/thesis_data.hpp"

namespace zs::bench {

namespace {

constexpr Rgb kWhite{255, 255, 255}, kInk{40, 40, 40}, kGrid{225, 225, 225}, kGoal{200, 30, 30};
// Tableau-10 colors: distinguishable for the seven surfaces, also in gray print.
constexpr Rgb kPalette[7] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},  {214, 39, 40},
                             {148, 103, 189}, {140, 86, 75},  {227, 119, 194}};
constexpr double kGoalFps = 60;

struct Point {
  int level;
  double fps;
};

// fps of surface s at each level of the deep-level series, skipping unmeasured ones.
std::vector<Point> series(const BenchResults& results, int surface) {
  std::vector<Point> points;
  for (int level = 0; level <= results.options.maxLevel; ++level) {
    const ConfigResult* r = findConfig(results, {surface, level, 10, 0.001});
    if (r && r->error.empty() && r->stats.fps() > 0) points.push_back({level, r->stats.fps()});
  }
  return points;
}

}  // namespace

Image fpsByLevelPlot(const BenchResults& results, int width, int height) {
  std::vector<std::vector<Point>> all;
  double lo = kGoalFps, hi = kGoalFps;
  for (const ThesisSurface& s : kThesisSurfaces) {
    all.push_back(series(results, s.number));
    for (const Point& p : all.back()) lo = std::min(lo, p.fps), hi = std::max(hi, p.fps);
  }
  // Log scale: fps spans orders of magnitude between level 0 and deep levels. The bottom
  // is a whole decade so the 1-2-5 ticks always have a place; the top leaves 30% headroom.
  const double logLo = std::floor(std::log10(lo)), logHi = std::log10(hi * 1.3);
  const int left = 64, right = width - 110, top = 24, bottom = height - 56;
  const int maxLevel = std::max(1, results.options.maxLevel);
  const auto px = [&](double level) {
    return left + static_cast<int>(std::lround(level / maxLevel * (right - left)));
  };
  const auto py = [&](double fps) {
    const double t = (std::log10(fps) - logLo) / (logHi - logLo);
    return bottom - static_cast<int>(std::lround(t * (bottom - top)));
  };

  Canvas canvas(width, height, kWhite);
  for (double decade = std::pow(10.0, logLo); decade < std::pow(10.0, logHi) * 1.01; decade *= 10) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = decade * m;
      if (v > std::pow(10.0, logHi) * 1.01) break;
      const int y = py(v);
      canvas.line(left, y, right, y, kGrid);
      char label[16];
      std::snprintf(label, sizeof label, "%g", v);
      canvas.text(left - 8 - Canvas::textWidth(label), y - 5, label, kInk);
    }
  }
  for (int level = 0; level <= maxLevel; ++level) {
    const int x = px(level);
    canvas.line(x, top, x, bottom, kGrid);
    canvas.text(x - 3, bottom + 8, std::to_string(level), kInk);
  }
  canvas.line(left, top, left, bottom, kInk, 2);
  canvas.line(left, bottom, right, bottom, kInk, 2);
  canvas.text((left + right) / 2 - Canvas::textWidth("octree level") / 2, bottom + 30,
              "octree level", kInk);
  canvas.text(8, top - 16, "fps", kInk);

  const int goalY = py(kGoalFps);
  canvas.line(left, goalY, right, goalY, kGoal, 2, 6);
  canvas.text(left + 8, goalY - 14, "goal 60", kGoal);

  for (std::size_t i = 0; i < all.size(); ++i) {
    const Rgb color = kPalette[i % 7];
    const std::vector<Point>& points = all[i];
    for (std::size_t k = 0; k + 1 < points.size(); ++k)
      canvas.line(px(points[k].level), py(points[k].fps), px(points[k + 1].level),
                  py(points[k + 1].fps), color, 3);
    for (const Point& p : points)
      canvas.fillRect(px(p.level) - 3, py(p.fps) - 3, px(p.level) + 3, py(p.fps) + 3, color);
    // Legend: a colored bar and the thesis' surface number, top right.
    const int ly = top + 20 + static_cast<int>(i) * 20;
    canvas.fillRect(right + 10, ly, right + 34, ly + 4, color);
    canvas.text(right + 42, ly - 3, std::to_string(kThesisSurfaces[i].number), kInk);
  }
  canvas.text(right + 10, top, "surface", kInk);
  return canvas.image();
}

}  // namespace zs::bench
