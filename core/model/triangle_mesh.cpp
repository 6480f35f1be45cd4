// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "desia/error.h"
#include "desia/tolerances.h"

namespace desia {

namespace {

using Point = std::array<double, 3>;

double twiceArea(const Point& a, const Point& b, const Point& c) {
  const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

double squaredLength(const Point& a, const Point& b) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) sum += (b[k] - a[k]) * (b[k] - a[k]);
  return sum;
}

}  // namespace

int flipZeroAreaTriangles(TriangleMesh& mesh) {
  std::map<std::pair<int, int>, size_t> triangleOfEdge;  // directed edge -> the triangle using it
  const auto link = [&](size_t t, bool add) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> edge{tri[k], tri[(k + 1) % 3]};
      if (add) {
        triangleOfEdge[edge] = t;
      } else {
        triangleOfEdge.erase(edge);
      }
    }
  };
  for (size_t t = 0; t < mesh.triangles.size(); ++t) link(t, true);
  const auto point = [&](int v) -> const Point& { return mesh.vertices[static_cast<size_t>(v)]; };
  const auto degenerate = [&](size_t t) {
    const auto& tri = mesh.triangles[t];
    return twiceArea(point(tri[0]), point(tri[1]), point(tri[2])) <= tolerance::kDegenerateTriangleTwiceAreaMm2;
  };
  // Passes until nothing changes; a flip can leave a new flat triangle (d on the line too), so the
  // number of flips is bounded as well.
  size_t flipsLeft = 3 * mesh.triangles.size();
  for (bool changed = true; changed && flipsLeft > 0;) {
    changed = false;
    for (size_t t = 0; t < mesh.triangles.size() && flipsLeft > 0; ++t) {
      if (!degenerate(t)) continue;
      const auto tri = mesh.triangles[t];
      int longest = 0;
      for (int k = 1; k < 3; ++k) {
        if (squaredLength(point(tri[k]), point(tri[(k + 1) % 3])) >
            squaredLength(point(tri[longest]), point(tri[(longest + 1) % 3])))
          longest = k;
      }
      const int a = tri[longest], c = tri[(longest + 1) % 3], b = tri[(longest + 2) % 3];
      const auto across = triangleOfEdge.find({c, a});
      if (across == triangleOfEdge.end()) continue;
      const size_t n = across->second;
      int d = -1;
      for (int v : mesh.triangles[n]) {
        if (v != a && v != c) d = v;
      }
      if (d < 0 || d == b || triangleOfEdge.count({b, d}) || triangleOfEdge.count({d, b})) continue;
      link(t, false);
      link(n, false);
      mesh.triangles[t] = {c, b, d};
      mesh.triangles[n] = {b, a, d};
      link(t, true);
      link(n, true);
      changed = true;
      --flipsLeft;
    }
  }
  int left = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) left += degenerate(t) ? 1 : 0;
  return left;
}

void splitPinchedVertices(TriangleMesh& mesh) {
  const size_t vertexCount = mesh.vertices.size();
  // Triangles around each vertex (corner k of triangle t as 3t + k), in triangle order.
  std::vector<size_t> start(vertexCount + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (int v : t) ++start[static_cast<size_t>(v) + 1];
  }
  for (size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
  std::vector<size_t> corners(start.back());
  std::vector<size_t> fill(start.begin(), start.end() - 1);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) corners[fill[static_cast<size_t>(mesh.triangles[t][k])]++] = 3 * t + static_cast<size_t>(k);
  }
  std::vector<size_t> parent;
  std::vector<std::pair<int, size_t>> byNeighbour;
  for (size_t v = 0; v < vertexCount; ++v) {
    const size_t first = start[v], count = start[v + 1] - first;
    if (count < 2) continue;
    // Fans: triangles around v joined where they share an edge (v, w).
    parent.resize(count);
    std::iota(parent.begin(), parent.end(), size_t{0});
    auto find = [&](size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    byNeighbour.clear();
    for (size_t i = 0; i < count; ++i) {
      const size_t t = corners[first + i] / 3, k = corners[first + i] % 3;
      byNeighbour.push_back({mesh.triangles[t][(k + 1) % 3], i});
      byNeighbour.push_back({mesh.triangles[t][(k + 2) % 3], i});
    }
    std::sort(byNeighbour.begin(), byNeighbour.end());
    for (size_t j = 1; j < byNeighbour.size(); ++j) {
      if (byNeighbour[j].first == byNeighbour[j - 1].first) {
        parent[find(byNeighbour[j].second)] = find(byNeighbour[j - 1].second);
      }
    }
    // The fan of the first triangle keeps v; each other fan gets a copy.
    std::vector<std::pair<size_t, int>> copies;  // fan root -> vertex
    for (size_t i = 0; i < count; ++i) {
      const size_t root = find(i);
      int vertex = -1;
      for (const auto& [fan, copy] : copies) {
        if (fan == root) vertex = copy;
      }
      if (vertex < 0) {
        if (copies.empty()) {
          vertex = static_cast<int>(v);
        } else {
          vertex = static_cast<int>(mesh.vertices.size());
          const std::array<double, 3> position = mesh.vertices[v];
          mesh.vertices.push_back(position);
        }
        copies.push_back({root, vertex});
      }
      const size_t t = corners[first + i] / 3, k = corners[first + i] % 3;
      mesh.triangles[t][k] = vertex;
    }
  }
}

void checkClosedMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.vertices.empty()) throwBadInput(source, "the mesh has no vertices");
  if (mesh.triangles.empty()) throwBadInput(source, "the mesh has no triangles (no faces)");
  const int64_t vertexCount = static_cast<int64_t>(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    for (double value : mesh.vertices[v]) {
      if (!std::isfinite(value)) {
        throwBadInput(source, "vertex " + std::to_string(v + 1) + " has a coordinate that is not finite (" +
                                  (std::isnan(value) ? "nan" : "inf") + ")");
      }
    }
  }
  // One key per undirected edge (smaller index in the high half): sorting groups equal edges, in
  // vertex order, so the first bad edge named is the same on every platform.
  std::vector<uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= vertexCount) {
        throwBadInput(source, "triangle " + std::to_string(t + 1) + " refers to vertex " + std::to_string(tri[k] + 1) +
                                  ", but the mesh has " + std::to_string(vertexCount) + " vertices");
      }
    }
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = static_cast<uint32_t>(tri[k]), b = static_cast<uint32_t>(tri[(k + 1) % 3]);
      if (a == b) {
        throwBadInput(source, "triangle " + std::to_string(t + 1) + " uses vertex " + std::to_string(a + 1) + " twice");
      }
      edges.push_back(static_cast<uint64_t>(std::min(a, b)) << 32 | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t k = 0; k < edges.size();) {
    size_t end = k + 1;
    while (end < edges.size() && edges[end] == edges[k]) ++end;
    const size_t uses = end - k;
    // The ray-parity test needs the surface to be a cycle mod 2: every edge in an even number of
    // triangles. Two is the usual case; four happens where two solid blocks touch only along an
    // edge, e.g. a voxel part's STL export, whose readers weld the two copies of a pinch edge.
    if (uses % 2 != 0) {
      throwBadInput(source, "the mesh is not closed: edge between vertices " + std::to_string((edges[k] >> 32) + 1) +
                                " and " + std::to_string((edges[k] & 0xffffffffu) + 1) + " belongs to " +
                                std::to_string(uses) + (uses == 1 ? " triangle" : " triangles") +
                                " (a closed solid needs 2)");
    }
    k = end;
  }
}

}  // namespace desia
