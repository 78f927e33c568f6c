// An open ball domain: the surface marched over the ball's bounding box is cut along the
// sphere. Each mesh edge that leaves the ball gets one new vertex (shared by the two
// triangles beside it, so the cut has no cracks), on the sphere and moved onto F = 0 there
// by Newton steps for the two equations; a triangle keeps its part inside the ball.
#include <algorithm>
#include <cmath>

#include "mesh/march.hpp"

namespace zs::mesh {

namespace {

double dot(const P3& a, const P3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
P3 minus(const P3& a, const P3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// The point where the segment from p (inside) to q (outside) meets the sphere.
P3 segmentOnSphere(const P3& p, const P3& q, const Ball& ball) {
  const P3 d = minus(q, p), m = minus(p, ball.center);
  const double a = dot(d, d), b = 2 * dot(m, d), c = dot(m, m) - ball.radius * ball.radius;
  const double disc = std::max(0.0, b * b - 4 * a * c);
  const double t = std::clamp((-b + std::sqrt(disc)) / (2 * a), 0.0, 1.0);
  return {p[0] + d[0] * t, p[1] + d[1] * t, p[2] + d[2] * t};
}

// Newton on {F = 0, |x - c|^2 = r^2} with the least-norm step; gives up (keeping `start`)
// if it does not converge within a cell.
P3 ontoSurfaceAndSphere(const P3& start, const Ball& ball, double cellSize, FieldEvaluator& ev) {
  P3 x = start;
  for (int it = 0; it < 12; ++it) {
    const std::array<double, 4> fg = ev.fAndGradient(x);
    const P3 g1{fg[1], fg[2], fg[3]}, rel = minus(x, ball.center),
                                      g2{2 * rel[0], 2 * rel[1], 2 * rel[2]};
    const double r1 = fg[0], r2 = dot(rel, rel) - ball.radius * ball.radius;
    const double a = dot(g1, g1), b = dot(g1, g2), c = dot(g2, g2), det = a * c - b * b;
    if (!std::isfinite(det) || det <= 1e-14 * a * c) return start;
    // Solve (J J^T) y = (r1, r2), step = -J^T y.
    const double y1 = (c * r1 - b * r2) / det, y2 = (a * r2 - b * r1) / det;
    for (std::size_t k = 0; k < 3; ++k) x[k] -= y1 * g1[k] + y2 * g2[k];
    if (std::sqrt(dot(minus(x, start), minus(x, start))) > cellSize) return start;
    if (std::abs(r1) <= 1e-12 * std::sqrt(a) * cellSize && std::abs(r2) <= 1e-12 * c) break;
  }
  return x;
}

}  // namespace

void clipBall(const Ball& ball, double cellSize, FieldEvaluator& ev, Mesh& mesh) {
  std::vector<char> inside(mesh.positions.size());
  const double r2 = ball.radius * ball.radius;
  for (std::size_t v = 0; v < inside.size(); ++v) {
    const P3 d = minus(mesh.positions[v], ball.center);
    inside[v] = dot(d, d) <= r2;
  }
  FlatIndex cut(1 << 12);  // (inside vertex << 32 | outside vertex) -> new vertex
  auto cutVertex = [&](std::uint32_t in, std::uint32_t out) {
    bool inserted;
    const std::uint64_t key = (std::uint64_t(in) << 32) | out;
    const std::uint32_t v = cut.insert(key, std::uint32_t(mesh.positions.size()), inserted);
    if (inserted) {
      const P3 p = ontoSurfaceAndSphere(
          segmentOnSphere(mesh.positions[in], mesh.positions[out], ball), ball, cellSize, ev);
      const std::array<double, 4> fg = ev.fAndGradient(p);
      const double len = std::sqrt(fg[1] * fg[1] + fg[2] * fg[2] + fg[3] * fg[3]);
      mesh.positions.push_back(p);
      mesh.normals.push_back(
          len > 0 && std::isfinite(len)
              ? std::array<float, 3>{float(fg[1] / len), float(fg[2] / len), float(fg[3] / len)}
              : mesh.normals[in]);
      mesh.kinds.push_back(VertexKind::Surface);
    }
    return v;
  };
  std::vector<std::array<std::uint32_t, 3>> kept;
  kept.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const int count = inside[t[0]] + inside[t[1]] + inside[t[2]];
    if (count == 3) kept.push_back(t);
    if (count == 0 || count == 3) continue;
    // Walk the triangle in order, keeping inside corners and the cuts between: the part
    // inside keeps the triangle's orientation.
    std::array<std::uint32_t, 4> poly{};
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
      if (inside[a]) poly[std::size_t(n++)] = a;
      if (inside[a] != inside[b])
        poly[std::size_t(n++)] = inside[a] ? cutVertex(a, b) : cutVertex(b, a);
    }
    kept.push_back({poly[0], poly[1], poly[2]});
    if (n == 4) kept.push_back({poly[0], poly[2], poly[3]});
  }
  mesh.triangles = std::move(kept);
}

}  // namespace zs::mesh
