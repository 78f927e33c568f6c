// The cap of a box domain: on each face, the part where F < 0, triangulated over the same
// grid as the cells beside it (each face square split along the diagonal the cells' Kuhn
// tetrahedra use), so the cap meets the surface at exactly the surface's boundary vertices.
#include <array>

#include "mesh/march.hpp"

namespace zs::mesh {

namespace {

struct Face {
  int axis = 0, side = 0;  // the face x_axis = 0 (side 0) or = n (side 1)
  int u = 1, v = 2;        // the other axes, cyclic after `axis`: e_u x e_v = e_axis
};

const std::array<Face, 6>& faces() {
  static const std::array<Face, 6> all = [] {
    std::array<Face, 6> f;
    for (int a = 0; a < 3; ++a)
      for (int s = 0; s < 2; ++s) f[std::size_t(2 * a + s)] = {a, s, (a + 1) % 3, (a + 2) % 3};
    return f;
  }();
  return all;
}

std::uint64_t faceCorner(const Face& f, std::uint32_t n, std::uint32_t i, std::uint32_t j) {
  std::array<std::uint64_t, 3> c{};
  c[std::size_t(f.axis)] = f.side ? n : 0;
  c[std::size_t(f.u)] = i;
  c[std::size_t(f.v)] = j;
  return packKey(c[0], c[1], c[2]);
}

// The square's two triangles, counter-clockwise about e_axis: (00, 10, 11) and (00, 11, 01).
std::array<std::array<std::uint64_t, 3>, 2> squareTriangles(const Face& f, std::uint32_t n,
                                                            std::uint32_t i, std::uint32_t j) {
  const std::uint64_t c00 = faceCorner(f, n, i, j), c10 = faceCorner(f, n, i + 1, j),
                      c01 = faceCorner(f, n, i, j + 1), c11 = faceCorner(f, n, i + 1, j + 1);
  return {{{c00, c10, c11}, {c00, c11, c01}}};
}

}  // namespace

BoxFaces::BoxFaces(const Grid& grid, FieldEvaluator& evaluator)
    : n_(grid.cellsPerAxis()), b_(grid.brickCells()) {
  const std::size_t side = std::size_t(n_ + 1) * (n_ + 1);
  std::vector<double> xs, ys, zs;
  for (const Face& f : faces()) {
    for (std::uint32_t j = 0; j <= n_; ++j) {
      for (std::uint32_t i = 0; i <= n_; ++i) {
        const P3 p = grid.position(faceCorner(f, n_, i, j));  // as the bricks compute it
        xs.push_back(p[0]), ys.push_back(p[1]), zs.push_back(p[2]);
      }
    }
  }
  values_.resize(6 * side);
  evaluator.values(xs, ys, zs, values_);
}

bool BoxFaces::negative(int face, std::uint64_t key) const {
  const Face f = faces()[std::size_t(face)];
  return values_[std::size_t(face) * (n_ + 1) * (n_ + 1) +
                 std::size_t(keyAxis(key, f.v)) * (n_ + 1) + keyAxis(key, f.u)] < 0;
}

std::vector<std::uint64_t> BoxFaces::bricksBesideCrossedSquares() const {
  std::vector<std::uint64_t> bricks;
  for (int face = 0; face < 6; ++face) {
    const Face& f = faces()[std::size_t(face)];
    for (std::uint32_t i = 0; i < n_; ++i) {
      for (std::uint32_t j = 0; j < n_; ++j) {
        int neg = 0;
        for (std::uint32_t c = 0; c < 4; ++c)
          neg += negative(face, faceCorner(f, n_, i + (c & 1), j + (c >> 1)));
        if (neg == 0 || neg == 4) continue;
        std::array<std::uint64_t, 3> brick{};
        brick[std::size_t(f.axis)] = f.side ? (n_ - 1) / b_ : 0;
        brick[std::size_t(f.u)] = i / b_;
        brick[std::size_t(f.v)] = j / b_;
        bricks.push_back(packKey(brick[0], brick[1], brick[2]));
      }
    }
  }
  return bricks;
}

void capBox(const Grid& grid, const BoxFaces& boxFaces, const Marched& marched, Mesh& mesh) {
  const std::uint32_t n = grid.cellsPerAxis();
  FlatIndex cornerVertex(1 << 16);  // grid corner -> its mesh vertex on the cap
  for (int face = 0; face < 6; ++face) {
    const Face& f = faces()[std::size_t(face)];
    std::array<float, 3> outward{0, 0, 0};
    outward[std::size_t(f.axis)] = f.side ? 1.0f : -1.0f;
    auto corner = [&](std::uint64_t key) {
      bool inserted;
      const std::uint32_t v =
          cornerVertex.insert(key, std::uint32_t(mesh.positions.size()), inserted);
      if (inserted) {
        mesh.positions.push_back(grid.position(key));
        mesh.normals.push_back(outward);
        mesh.kinds.push_back(VertexKind::Cap);
      }
      return v;
    };
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = 0; j < n; ++j) {
        for (const auto& tri : squareTriangles(f, n, i, j)) {
          // The negative part of the triangle, walked in the triangle's own order.
          std::array<std::uint32_t, 4> poly{};
          int count = 0;
          for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = tri[std::size_t(k)], b = tri[std::size_t((k + 1) % 3)];
            const bool aNeg = boxFaces.negative(face, a), bNeg = boxFaces.negative(face, b);
            if (aNeg) poly[std::size_t(count++)] = corner(a);
            if (aNeg != bNeg) poly[std::size_t(count++)] = marched.edgeIndex.find(edgeKey(a, b));
          }
          if (count < 3) continue;
          // Side 0 faces look along -e_axis: reverse the counter-clockwise order.
          auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            if (f.side)
              mesh.triangles.push_back({a, b, c});
            else
              mesh.triangles.push_back({a, c, b});
          };
          emit(poly[0], poly[1], poly[2]);
          if (count == 4) emit(poly[0], poly[2], poly[3]);
        }
      }
    }
  }
}

}  // namespace zs::mesh
