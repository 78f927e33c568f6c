#include "singular/report.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace zs {

namespace {

std::string format(const char* fmt, double a, double b, double c) {
  char buf[128];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

std::string kind(const SingularPoint& p) {
  if (p.isNode()) return "A1 node";
  return "degenerate (" + std::to_string(p.zero) + " zero eigenvalue" + (p.zero > 1 ? "s" : "") +
         ")";
}

std::size_t find(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<UncertifiedRegion> uncertifiedRegions(const SingularResult& result) {
  const std::vector<Box>& boxes = result.uncertified;
  std::vector<std::size_t> order(boxes.size()), parent(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::iota(parent.begin(), parent.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].min[0] < boxes[b].min[0]; });
  // Sweep along x: a box can only touch the boxes that start before it ends.
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Box& a = boxes[order[i]];
    const double slack = 1e-9 * (1 + std::abs(a.max[0]));
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].min[0] <= a.max[0] + slack;
         ++j) {
      const Box& b = boxes[order[j]];
      bool touch = true;
      for (std::size_t k = 1; k < 3; ++k)
        touch = touch && b.min[k] <= a.max[k] + slack && a.min[k] <= b.max[k] + slack;
      if (touch) parent[find(parent, order[i])] = find(parent, order[j]);
    }
  }
  std::vector<UncertifiedRegion> regions;
  std::vector<std::size_t> regionOf(boxes.size(), SIZE_MAX);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    std::size_t& r = regionOf[find(parent, i)];
    if (r == SIZE_MAX) {
      r = regions.size();
      regions.push_back({boxes[i], 0});
    }
    UncertifiedRegion& region = regions[r];
    for (std::size_t k = 0; k < 3; ++k) {
      region.box.min[k] = std::min(region.box.min[k], boxes[i].min[k]);
      region.box.max[k] = std::max(region.box.max[k], boxes[i].max[k]);
    }
    ++region.boxes;
  }
  return regions;
}

std::string singularTable(const SingularResult& result) {
  std::string s =
      "   #            x            y            z    box width       F(p)   Hessian eigenvalues   "
      "                  kind\n";
  int n = 0, nodes = 0;
  for (const SingularPoint& p : result.points) {
    char line[256];
    std::snprintf(
        line, sizeof line, "%4d %12.8f %12.8f %12.8f %12.2e %10.2e   %s   %s\n", ++n, p.point[0],
        p.point[1], p.point[2], p.boxWidth, p.f,
        format("%11.4g %11.4g %11.4g", p.eigenvalues[0], p.eigenvalues[1], p.eigenvalues[2])
            .c_str(),
        kind(p).c_str());
    s += line;
    nodes += p.isNode();
  }
  const std::vector<UncertifiedRegion> regions = uncertifiedRegions(result);
  if (!regions.empty()) {
    s += "\nnot certified (degenerate singularities, curves of singular points, or points too "
         "close to tell apart):\n";
    for (const UncertifiedRegion& r : regions) {
      char line[256];
      std::snprintf(line, sizeof line,
                    "  [%.6g, %.6g] x [%.6g, %.6g] x [%.6g, %.6g]  (%zu boxes)\n", r.box.min[0],
                    r.box.max[0], r.box.min[1], r.box.max[1], r.box.min[2], r.box.max[2], r.boxes);
      s += line;
    }
  }
  char tail[256];
  std::snprintf(tail, sizeof tail,
                "\ncertified singular points: %d (A1 nodes: %d); uncertified regions: %zu; "
                "%zu boxes tested in %.0f ms\n",
                n, nodes, regions.size(), result.boxesTested, result.seconds * 1e3);
  return s + tail;
}

std::string singularCsv(const SingularResult& result) {
  std::string s = "kind,x,y,z,box_width,f,lambda1,lambda2,lambda3,positive,negative,zero\n";
  char line[512];
  for (const SingularPoint& p : result.points) {
    std::snprintf(line, sizeof line, "%s,%.17g,%.17g,%.17g,%.3g,%.3g,%.10g,%.10g,%.10g,%d,%d,%d\n",
                  p.isNode() ? "node" : "degenerate", p.point[0], p.point[1], p.point[2],
                  p.boxWidth, p.f, p.eigenvalues[0], p.eigenvalues[1], p.eigenvalues[2], p.positive,
                  p.negative, p.zero);
    s += line;
  }
  for (const UncertifiedRegion& r : uncertifiedRegions(result)) {
    std::snprintf(line, sizeof line, "uncertified,%.17g,%.17g,%.17g,%.3g,,,,,,,\n",
                  0.5 * (r.box.min[0] + r.box.max[0]), 0.5 * (r.box.min[1] + r.box.max[1]),
                  0.5 * (r.box.min[2] + r.box.max[2]),
                  std::max({r.box.max[0] - r.box.min[0], r.box.max[1] - r.box.min[1],
                            r.box.max[2] - r.box.min[2]}));
    s += line;
  }
  return s;
}

std::string singularJson(const SingularResult& result) {
  std::string s = "{\n  \"points\": [";
  char buf[512];
  for (std::size_t i = 0; i < result.points.size(); ++i) {
    const SingularPoint& p = result.points[i];
    std::snprintf(buf, sizeof buf,
                  "%s\n    {\"point\": [%.17g, %.17g, %.17g], \"box_width\": %.3g, \"f\": %.3g, "
                  "\"eigenvalues\": [%.10g, %.10g, %.10g], \"signature\": [%d, %d, %d], "
                  "\"node\": %s}",
                  i ? "," : "", p.point[0], p.point[1], p.point[2], p.boxWidth, p.f,
                  p.eigenvalues[0], p.eigenvalues[1], p.eigenvalues[2], p.positive, p.negative,
                  p.zero, p.isNode() ? "true" : "false");
    s += buf;
  }
  s += "\n  ],\n  \"uncertified\": [";
  const std::vector<UncertifiedRegion> regions = uncertifiedRegions(result);
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const Box& b = regions[i].box;
    std::snprintf(buf, sizeof buf,
                  "%s\n    {\"min\": [%.17g, %.17g, %.17g], \"max\": [%.17g, %.17g, %.17g], "
                  "\"boxes\": %zu}",
                  i ? "," : "", b.min[0], b.min[1], b.min[2], b.max[0], b.max[1], b.max[2],
                  regions[i].boxes);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "\n  ],\n  \"boxes_tested\": %zu,\n  \"seconds\": %.6f\n}\n",
                result.boxesTested, result.seconds);
  return s + buf;
}

}  // namespace zs
