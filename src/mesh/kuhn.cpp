#include "mesh/kuhn.hpp"

#include <algorithm>
#include <vector>

namespace zs::mesh {

namespace {

using I3 = std::array<int, 3>;

I3 corner(int c) {
  return {c & 1, (c >> 1) & 1, (c >> 2) & 1};
}

I3 sub(const I3& a, const I3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
I3 cross(const I3& a, const I3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
int dot(const I3& a, const I3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

struct Tables {
  std::array<CellEdge, kCellEdges> edges{};
  std::array<std::array<int, 8>, 8> edgeId{};
  std::array<std::array<int, 4>, 6> tets{};
  std::array<std::array<TetPiece, 256>, 6> pieces{};  // indexed by the cell's corner mask

  Tables() {
    int n = 0;
    for (auto& row : edgeId) row.fill(-1);
    for (int lo = 0; lo < 8; ++lo)
      for (int hi = 0; hi < 8; ++hi)
        if (lo != hi && (lo & hi) == lo) {
          edges[std::size_t(n)] = {std::uint8_t(lo), std::uint8_t(hi)};
          edgeId[std::size_t(lo)][std::size_t(hi)] = edgeId[std::size_t(hi)][std::size_t(lo)] = n++;
        }
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int t = 0; t < 6; ++t) {
      const int c1 = 1 << perms[t][0], c2 = c1 | (1 << perms[t][1]);
      tets[std::size_t(t)] = {0, c1, c2, 7};
      for (int mask = 0; mask < 256; ++mask)
        pieces[std::size_t(t)][std::size_t(mask)] = build(t, mask);
    }
  }

  // Twice the midpoint of the edge between corners a and b: exact small integers, so the
  // orientation test below is exact. Roots elsewhere on the same edges keep its answer.
  static I3 mid(int a, int b) {
    const I3 p = corner(a), q = corner(b);
    return {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
  }

  TetPiece build(int t, int mask) const {
    std::vector<int> neg, pos;
    for (int c : tets[std::size_t(t)]) ((mask >> c) & 1 ? neg : pos).push_back(c);
    TetPiece piece;
    if (neg.empty() || pos.empty()) return piece;
    std::vector<std::array<int, 2>> poly;  // edges as (negative corner, positive corner)
    if (neg.size() == 1) {
      for (int p : pos) poly.push_back({neg[0], p});
    } else if (pos.size() == 1) {
      for (int n : neg) poly.push_back({n, pos[0]});
    } else {  // a cycle: a-c, a-d, b-d, b-c
      poly = {{neg[0], pos[0]}, {neg[0], pos[1]}, {neg[1], pos[1]}, {neg[1], pos[0]}};
    }
    const I3 m0 = mid(poly[0][0], poly[0][1]), m1 = mid(poly[1][0], poly[1][1]),
             m2 = mid(poly[2][0], poly[2][1]);
    const I3 normal = cross(sub(m1, m0), sub(m2, m0));
    I3 towardPositive{};
    for (int a = 0; a < 3; ++a) {
      int sp = 0, sn = 0;
      for (int p : pos) sp += corner(p)[std::size_t(a)];
      for (int n : neg) sn += corner(n)[std::size_t(a)];
      towardPositive[std::size_t(a)] = int(neg.size()) * sp - int(pos.size()) * sn;
    }
    if (dot(normal, towardPositive) < 0) std::reverse(poly.begin(), poly.end());
    piece.count = std::uint8_t(poly.size());
    for (std::size_t i = 0; i < poly.size(); ++i)
      piece.edges[i] = std::uint8_t(edgeId[std::size_t(poly[i][0])][std::size_t(poly[i][1])]);
    return piece;
  }
};

const Tables& tables() {
  static const Tables t;
  return t;
}

}  // namespace

const std::array<CellEdge, kCellEdges>& cellEdges() {
  return tables().edges;
}

const TetPiece& tetPiece(int tet, int negativeCorners) {
  return tables().pieces[std::size_t(tet)][std::size_t(negativeCorners)];
}

}  // namespace zs::mesh
