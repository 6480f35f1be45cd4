// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/mitred_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"

namespace desia {
namespace mitred {
namespace {

uint64_t directedKey(int a, int b) { return static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32 | static_cast<uint32_t>(b); }

struct Plane {
  Vec3 normal;  // unit
  double offset = 0;
};

// The mesh with exactly repeated positions welded into their first vertex (OBJ and STL exports
// may repeat a position per face), and the triangles that collapse by that dropped. Vertex numbers
// stay the file's.
TriangleMesh weldedMesh(const TriangleMesh& mesh, const std::string& source) {
  const int vertexCount = static_cast<int>(mesh.vertices.size());
  for (int v = 0; v < vertexCount; ++v) {
    for (double c : mesh.vertices[v]) {
      if (!std::isfinite(c)) throwBadInput(source, "vertex " + std::to_string(v + 1) + " has a coordinate that is not finite");
    }
  }
  TriangleMesh welded;
  welded.vertices = mesh.vertices;
  std::map<Vec3, int> firstAt;
  std::vector<int> target(mesh.vertices.size());
  for (int v = 0; v < vertexCount; ++v) target[v] = firstAt.emplace(mesh.vertices[v], v).first->second;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<int, 3> tri = mesh.triangles[t];
    for (int& v : tri) {
      if (v < 0 || v >= vertexCount) throwBadInput(source, "triangle " + std::to_string(t + 1) + " refers to a vertex that does not exist");
      v = target[v];
    }
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]) welded.triangles.push_back(tri);
  }
  return welded;
}

// twin[t][k]: the triangle on the other side of triangle t's edge k (from corner k to k+1).
std::vector<std::array<int, 3>> triangleTwins(const TriangleMesh& mesh, const std::string& source) {
  std::unordered_map<uint64_t, int> owner;
  owner.reserve(mesh.triangles.size() * 3);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      const auto [it, added] = owner.emplace(directedKey(a, b), static_cast<int>(t));
      if (!added) {
        throwBadInput(source, "the mesh is not consistently oriented: triangles " + std::to_string(it->second + 1) + " and " +
                                  std::to_string(t + 1) + " both run from " + vertexText(mesh, a) + " to " + vertexText(mesh, b) +
                                  " (one of them faces the other way; in Blender: Mesh > Normals > Recalculate Outside)");
      }
    }
  }
  std::vector<std::array<int, 3>> twins(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      // Every edge is in exactly two triangles (checked before), so the reverse edge exists.
      twins[t][k] = owner.at(directedKey(mesh.triangles[t][(k + 1) % 3], mesh.triangles[t][k]));
    }
  }
  return twins;
}

// Closed (checkClosedMesh: every edge in an even number of triangles), then manifold: every edge
// in exactly two, and the triangles around every vertex one fan.
void requireManifold(const TriangleMesh& mesh, const std::string& source) {
  checkClosedMesh(mesh, source);
  std::map<std::pair<int, int>, int> uses;  // ordered: the first bad edge named is the same everywhere
  for (const auto& tri : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++uses[{std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])}];
  }
  for (const auto& [edge, count] : uses) {
    if (count > 2) {
      throwBadInput(source, "the mesh is not manifold: the edge between " + vertexText(mesh, edge.first) + " and " +
                                vertexText(mesh, edge.second) + " belongs to " + std::to_string(count) +
                                " triangles (a closed surface has 2 at every edge; solids touching along an edge "
                                "cannot be made of mitred plates)");
    }
  }
}

void requireManifoldVertices(const TriangleMesh& mesh, const std::vector<std::array<int, 3>>& twins, const std::string& source) {
  std::vector<std::vector<std::pair<int, int>>> around(mesh.vertices.size());  // (triangle, corner)
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) around[mesh.triangles[t][k]].push_back({static_cast<int>(t), k});
  }
  for (size_t v = 0; v < around.size(); ++v) {
    if (around[v].empty()) continue;
    // Walk the fan: leave each triangle over its edge starting at v; the next triangle has v too.
    int t = around[v][0].first, k = around[v][0].second;
    size_t steps = 0;
    do {
      const int next = twins[t][k];
      const auto& tri = mesh.triangles[next];
      k = tri[0] == static_cast<int>(v) ? 0 : (tri[1] == static_cast<int>(v) ? 1 : 2);
      t = next;
      ++steps;
    } while (t != around[v][0].first && steps <= around[v].size());
    if (steps != around[v].size()) {
      throwBadInput(source, "the mesh is not manifold: the surface touches itself at " + vertexText(mesh, static_cast<int>(v)) +
                                " (" + std::to_string(around[v].size()) + " triangles there, in separate fans)");
    }
  }
}

void requireOnePiece(const TriangleMesh& mesh, const std::vector<std::array<int, 3>>& twins, const std::string& source) {
  std::vector<int> parent(mesh.triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t t = 0; t < twins.size(); ++t) {
    for (int k = 0; k < 3; ++k) parent[find(twins[t][k])] = find(static_cast<int>(t));
  }
  int pieces = 0;
  for (size_t t = 0; t < parent.size(); ++t) pieces += find(static_cast<int>(t)) == static_cast<int>(t);
  if (pieces > 1) {
    throwBadInput(source, "the mesh has " + std::to_string(pieces) +
                              " separate closed pieces; plates-from-mesh makes one structure from one closed surface "
                              "(the pieces' plates would not touch)");
  }
}

}  // namespace

std::string number(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

std::string pointText(const Vec3& p) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return out.str();
}

std::string vertexText(const TriangleMesh& mesh, int v) {
  return "vertex " + std::to_string(v + 1) + " " + pointText(mesh.vertices[v]);
}

// How many times the closed surface winds around `point` (1 inside, 0 outside): the triangles'
// solid angles (Van Oosterom and Strackee) over 4 pi.
double windingNumber(const TriangleMesh& mesh, const Vec3& point) {
  double total = 0;
  for (const auto& tri : mesh.triangles) {
    const Vec3 a = minus(mesh.vertices[tri[0]], point), b = minus(mesh.vertices[tri[1]], point), c = minus(mesh.vertices[tri[2]], point);
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * kPi);
}

OrientedMesh orientedMesh(const TriangleMesh& input, const std::string& source) {
  OrientedMesh oriented;
  TriangleMesh& mesh = oriented.mesh;
  mesh = weldedMesh(input, source);
  requireManifold(mesh, source);
  std::vector<std::array<int, 3>>& twins = oriented.twins;
  twins = triangleTwins(mesh, source);
  requireManifoldVertices(mesh, twins, source);
  requireOnePiece(mesh, twins, source);
  // Outward or inside out: the sign of the enclosed volume (about the bounding box's centre, for
  // precision far from the origin).
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& tri : mesh.triangles) {
    for (int v : tri) {
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], mesh.vertices[v][k]), hi[k] = std::max(hi[k], mesh.vertices[v][k]);
    }
  }
  const Vec3 middle = scaled(plus(lo, hi), 0.5);
  const double size = norm(minus(hi, lo));
  oriented.size = size;
  double volume = 0;
  for (const auto& tri : mesh.triangles) {
    volume += dot(minus(mesh.vertices[tri[0]], middle), cross(minus(mesh.vertices[tri[1]], middle), minus(mesh.vertices[tri[2]], middle))) / 6;
  }
  if (!(std::abs(volume) > tolerance::kRelativeRounding * size * size * size))
    throwBadInput(source, "the mesh encloses no volume");
  if (volume < 0) {
    for (auto& tri : mesh.triangles) std::swap(tri[1], tri[2]);
    twins = triangleTwins(mesh, source);
    oriented.reoriented = true;
  }
  return oriented;
}

}  // namespace mitred
}  // namespace desia
