#include "mesh/mesh_check.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "mesh/huge_pages.hpp"

namespace zs {

namespace {

struct HalfEdge {
  std::uint32_t lo, hi;
  bool forward;  // the triangle runs lo -> hi
  bool operator<(const HalfEdge& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
};

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

MeshTopology checkMesh(const Mesh& mesh) {
  MeshTopology top;
  const std::size_t nv = mesh.positions.size();
  top.faces = mesh.triangles.size();
  std::vector<char> used = mesh::hugeVector<char>(nv, 0);
  std::vector<std::uint32_t> parent = mesh::hugeVector<std::uint32_t>(nv);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) ++top.degenerateTriangles;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
      used[a] = 1;
      parent[findRoot(parent, a)] = findRoot(parent, b);
    }
    const auto& p = mesh.positions[t[0]];
    const auto& q = mesh.positions[t[1]];
    const auto& r = mesh.positions[t[2]];
    top.volume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                   p[2] * (q[0] * r[1] - q[1] * r[0])) /
                  6.0;
  }
  // The half-edges in order: a counting sort on the lower vertex, then each vertex's few by
  // the upper one (millions of them: a comparison sort of the lot costs several times more).
  std::vector<std::uint32_t> bucket = mesh::hugeVector<std::uint32_t>(nv + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++bucket[std::min(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]) + 1];
  std::partial_sum(bucket.begin(), bucket.end(), bucket.begin());
  std::vector<HalfEdge> halves = mesh::hugeVector<HalfEdge>(3 * mesh.triangles.size());
  {
    std::vector<std::uint32_t> cursor = mesh::hugeVector<std::uint32_t>(nv);
    std::copy(bucket.begin(), bucket.end() - 1, cursor.begin());
    for (const auto& t : mesh.triangles) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
        halves[cursor[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), a < b};
      }
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    std::sort(halves.begin() + bucket[v], halves.begin() + bucket[v + 1]);
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while (j < halves.size() && halves[j].lo == halves[i].lo && halves[j].hi == halves[i].hi) ++j;
    ++top.edges;
    if (j - i == 1) ++top.boundaryEdges;
    if (j - i > 2) ++top.nonManifoldEdges;
    if (j - i == 2 && halves[i].forward == halves[i + 1].forward) ++top.misorientedEdges;
    i = j;
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    ++top.vertices;
    if (findRoot(parent, std::uint32_t(v)) == v) ++top.components;
  }
  top.euler = long(top.vertices) - long(top.edges) + long(top.faces);

  // Vertex manifoldness: the triangles around a vertex, joined through the edges at it,
  // must form one fan.
  std::vector<std::uint32_t> start = mesh::hugeVector<std::uint32_t>(nv + 1, 0);
  std::vector<std::uint32_t> around = mesh::hugeVector<std::uint32_t>(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> fill = mesh::hugeVector<std::uint32_t>(nv);
  std::copy(start.begin(), start.end() - 1, fill.begin());
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f)
    for (std::uint32_t v : mesh.triangles[f]) around[fill[v]++] = f;
  std::vector<std::uint32_t> local;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t b = start[v], e = start[v + 1];
    if (e - b < 2) continue;
    local.resize(e - b);
    std::iota(local.begin(), local.end(), 0u);
    for (std::uint32_t i = b; i < e; ++i) {
      for (std::uint32_t j = i + 1; j < e; ++j) {
        int shared = 0;
        for (std::uint32_t x : mesh.triangles[around[i]])
          for (std::uint32_t y : mesh.triangles[around[j]]) shared += (x == y && x != v);
        if (shared > 0) local[findRoot(local, i - b)] = findRoot(local, j - b);
      }
    }
    std::size_t fans = 0;
    for (std::uint32_t i = 0; i < e - b; ++i) fans += findRoot(local, i) == i;
    if (fans > 1) ++top.nonManifoldVertices;
  }
  return top;
}

}  // namespace zs
