// SPDX-License-Identifier: GPL-3.0-or-later
// The edges of a closed triangle mesh (mesh_edges.h).
#include "plate/mesh_edges.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "analysis/vec3.h"

namespace desia {
namespace {

// Where a solid touches itself along an edge (two joint voxels of a beam meeting only there), the
// edge is in four triangles: around it, in the order they turn about it, each with the next one
// that closes a wedge of solid (its outward normal turned away from that wedge).
std::map<std::pair<int, int>, int> partnersAroundEdge(const TriangleMesh& mesh, int a, int b, const std::vector<int>& four) {
  const Vec3& pa = mesh.vertices[static_cast<size_t>(a)];
  const Vec3 e = normalized(minus(mesh.vertices[static_cast<size_t>(b)], pa));
  struct Around {
    double x, y;  // the direction to its third vertex, in a frame across the edge
    int triangle;
    bool turnsAway;  // its normal points towards smaller angles: the wedge after it is solid
  };
  std::vector<Around> around;
  Vec3 u{0, 0, 0}, v{0, 0, 0};
  for (int t : four) {
    const auto& tri = mesh.triangles[static_cast<size_t>(t)];
    int c = tri[0];
    for (int w : tri) c = (w != a && w != b) ? w : c;
    Vec3 r = minus(mesh.vertices[static_cast<size_t>(c)], pa);
    r = normalized(minus(r, scaled(e, dot(r, e))));
    if (norm(u) == 0) {
      u = r;
      v = cross(e, u);
    }
    const Vec3& p0 = mesh.vertices[static_cast<size_t>(tri[0])];
    const Vec3 n = cross(minus(mesh.vertices[static_cast<size_t>(tri[1])], p0), minus(mesh.vertices[static_cast<size_t>(tri[2])], p0));
    around.push_back({dot(r, u), dot(r, v), t, dot(n, cross(e, r)) < 0});
  }
  // By angle about the edge, without trigonometry (the same order natively and in WebAssembly):
  // the half turn from 0 first, then by the sign of the cross product.
  const auto lowerHalf = [](const Around& p) { return p.y < 0 || (p.y == 0 && p.x < 0); };
  std::sort(around.begin(), around.end(), [&](const Around& p, const Around& q) {
    if (lowerHalf(p) != lowerHalf(q)) return !lowerHalf(p);
    const double turn = p.x * q.y - p.y * q.x;
    return turn != 0 ? turn > 0 : p.triangle < q.triangle;
  });
  std::map<std::pair<int, int>, int> partner;  // (edge key a, triangle) -> its partner
  for (size_t i = 0; i < around.size(); ++i) {
    const Around& next = around[(i + 1) % around.size()];
    if (!around[i].turnsAway || next.turnsAway) continue;
    partner[{a, around[i].triangle}] = next.triangle;
    partner[{a, next.triangle}] = around[i].triangle;
  }
  return partner;
}

}  // namespace

bool everyEdgeInTwoOppositeTriangles(const TriangleMesh& mesh) {
  std::vector<std::pair<int, int>> directed;
  directed.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) directed.push_back({t[k], t[(k + 1) % 3]});
  }
  std::sort(directed.begin(), directed.end());
  for (size_t i = 0; i < directed.size(); ++i) {
    if (i + 1 < directed.size() && directed[i + 1] == directed[i]) return false;
    if (!std::binary_search(directed.begin(), directed.end(), std::make_pair(directed[i].second, directed[i].first)))
      return false;
  }
  return true;
}

double sixVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    volume += dot(a, cross(mesh.vertices[static_cast<size_t>(t[1])], mesh.vertices[static_cast<size_t>(t[2])]));
  }
  return volume;
}

// Gives each pair of partners around an edge in four triangles (partnersAroundEdge) an edge of
// its own: the edge split at its middle, one new vertex per pair there (two vertices at one
// point), so that every edge is in two triangles; where the surface then pinches at a vertex,
// splitPinchedVertices gives each sheet its own copy. One edge at a time, the edges found again
// after each (a triangle may have two such edges).
void splitEdgesInFourTriangles(TriangleMesh& mesh) {
  for (size_t done = 0;; ++done) {
    std::map<std::pair<int, int>, std::vector<int>> byEdge;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      for (int k = 0; k < 3; ++k)
        byEdge[{std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])}].push_back(static_cast<int>(t));
    }
    std::map<std::pair<int, int>, int> partner;
    std::pair<int, int> edge{-1, -1};
    for (const auto& [key, triangles] : byEdge) {
      if (triangles.size() != 4) continue;
      partner = partnersAroundEdge(mesh, key.first, key.second, triangles);
      if (partner.size() == 4) {
        edge = key;
        break;
      }
    }
    if (edge.first < 0 || done > mesh.triangles.size()) return;
    const Vec3 middle = scaled(plus(mesh.vertices[static_cast<size_t>(edge.first)], mesh.vertices[static_cast<size_t>(edge.second)]), 0.5);
    for (int t : byEdge[edge]) {
      const int other = partner.at({edge.first, t});
      if (other < t) continue;
      const int m = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(middle);
      for (int half : {t, other}) {
        std::array<int, 3>& tri = mesh.triangles[static_cast<size_t>(half)];
        int k = 0;
        const auto onEdge = [&](int v) { return v == edge.first || v == edge.second; };
        while (k < 3 && !(onEdge(tri[k]) && onEdge(tri[(k + 1) % 3]))) ++k;
        if (k == 3) return;  // not the edge's triangle: leave the mesh to the check
        const int p = tri[k], q = tri[(k + 1) % 3], r = tri[(k + 2) % 3];
        tri = {p, m, r};
        mesh.triangles.push_back({m, q, r});
      }
    }
  }
}

}  // namespace desia
