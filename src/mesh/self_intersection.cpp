// Pairs of triangles that share no vertex yet cross: an edge of one passes through the
// other. Triangles are binned by their bounding boxes on a uniform grid, so only nearby
// pairs are tested. Orientation signs are plain double determinants: on our meshes
// non-adjacent triangles are apart by far more than their rounding error.
#include <algorithm>
#include <climits>
#include <cmath>
#include <unordered_map>

#include "mesh/mesh_check.hpp"

namespace zs {

namespace {

using P = std::array<double, 3>;

double orient(const P& a, const P& b, const P& c, const P& d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

int sign(double v) {
  return (v > 0) - (v < 0);
}

// Does the segment pq cross the triangle abc (a proper crossing, not a touch)?
bool segmentCrossesTriangle(const P& p, const P& q, const P& a, const P& b, const P& c) {
  const int sp = sign(orient(a, b, c, p)), sq = sign(orient(a, b, c, q));
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int s1 = sign(orient(p, q, a, b)), s2 = sign(orient(p, q, b, c)),
            s3 = sign(orient(p, q, c, a));
  return s1 != 0 && s1 == s2 && s2 == s3;
}

bool trianglesCross(const Mesh& m, const std::array<std::uint32_t, 3>& s,
                    const std::array<std::uint32_t, 3>& t) {
  const auto& P = m.positions;
  for (int k = 0; k < 3; ++k) {
    if (segmentCrossesTriangle(P[s[std::size_t(k)]], P[s[std::size_t((k + 1) % 3)]], P[t[0]],
                               P[t[1]], P[t[2]]))
      return true;
    if (segmentCrossesTriangle(P[t[std::size_t(k)]], P[t[std::size_t((k + 1) % 3)]], P[s[0]],
                               P[s[1]], P[s[2]]))
      return true;
  }
  return false;
}

}  // namespace

std::size_t countSelfIntersections(const Mesh& mesh) {
  const auto& tris = mesh.triangles;
  if (tris.empty()) return 0;
  double mean = 0;
  P lo{INFINITY, INFINITY, INFINITY};
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) {
      const P& a = mesh.positions[t[std::size_t(k)]];
      const P& b = mesh.positions[t[std::size_t((k + 1) % 3)]];
      mean += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                        (a[2] - b[2]) * (a[2] - b[2]));
      for (std::size_t i = 0; i < 3; ++i) lo[i] = std::min(lo[i], a[i]);
    }
  }
  const double bin = std::max(2 * mean / double(3 * tris.size()), 1e-12);
  auto binOf = [&](double v, std::size_t axis) { return long(std::floor((v - lo[axis]) / bin)); };
  auto key = [](long x, long y, long z) {
    return (std::uint64_t(x) << 42) ^ (std::uint64_t(y) << 21) ^ std::uint64_t(z);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> bins;
  std::vector<std::array<long, 6>> range(tris.size());
  for (std::uint32_t f = 0; f < tris.size(); ++f) {
    std::array<long, 6> r{LONG_MAX, LONG_MAX, LONG_MAX, LONG_MIN, LONG_MIN, LONG_MIN};
    for (std::uint32_t v : tris[f])
      for (std::size_t i = 0; i < 3; ++i) {
        r[i] = std::min(r[i], binOf(mesh.positions[v][i], i));
        r[i + 3] = std::max(r[i + 3], binOf(mesh.positions[v][i], i));
      }
    range[f] = r;
    for (long x = r[0]; x <= r[3]; ++x)
      for (long y = r[1]; y <= r[4]; ++y)
        for (long z = r[2]; z <= r[5]; ++z) bins[key(x, y, z)].push_back(f);
  }
  std::size_t crossings = 0;
  std::vector<std::uint32_t> near;
  for (std::uint32_t f = 0; f < tris.size(); ++f) {
    near.clear();
    const auto& r = range[f];
    for (long x = r[0]; x <= r[3]; ++x)
      for (long y = r[1]; y <= r[4]; ++y)
        for (long z = r[2]; z <= r[5]; ++z) {
          auto it = bins.find(key(x, y, z));
          if (it == bins.end()) continue;
          for (std::uint32_t g : it->second)
            if (g > f) near.push_back(g);
        }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (std::uint32_t g : near) {
      bool shares = false;
      for (std::uint32_t a : tris[f])
        for (std::uint32_t b : tris[g]) shares |= a == b;
      if (!shares && trianglesCross(mesh, tris[f], tris[g])) ++crossings;
    }
  }
  return crossings;
}

}  // namespace zs
