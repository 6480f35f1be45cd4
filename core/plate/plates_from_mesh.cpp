// SPDX-License-Identifier: GPL-3.0-or-later
// Plates from a modelling tool's mesh: every OBJ object or group (`o` / `g`), or every
// connected piece of a mesh without groups, is one plate, a closed slab whose two largest parallel
// faces are the plate's faces. Blender or SketchUp designs open as they are.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"

namespace desia {
namespace {


// Triangle indices per piece: the OBJ groups, or the pieces joined by shared vertices.
std::vector<std::vector<int>> pieces(const TriangleMesh& mesh) {
  std::vector<std::vector<int>> result;
  if (!mesh.groupNames.empty()) {
    result.resize(mesh.groupNames.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) result[mesh.triangleGroup[t]].push_back(static_cast<int>(t));
    result.erase(std::remove_if(result.begin(), result.end(), [](const std::vector<int>& p) { return p.empty(); }), result.end());
    return result;
  }
  // Triangles join across an edge that exactly two triangles use: plates that touch at a corner or
  // share a mitred edge (four triangles) stay apart, as STL welds their coinciding vertices.
  std::map<std::pair<int, int>, std::vector<int>> edgeTriangles;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      edgeTriangles[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(t));
    }
  }
  std::vector<int> parent(mesh.triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [edge, users] : edgeTriangles) {
    if (users.size() == 2) parent[find(users[1])] = find(users[0]);
  }
  std::map<int, int> pieceOfRoot;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int root = find(static_cast<int>(t));
    auto [it, added] = pieceOfRoot.emplace(root, static_cast<int>(result.size()));
    if (added) result.emplace_back();
    result[it->second].push_back(static_cast<int>(t));
  }
  return result;
}

struct PlanarFace {
  Vec3 normal{0, 0, 0};  // unit, outward (the triangles' winding)
  double offset = 0;     // normal · point
  double area = 0;
  std::vector<int> triangles;
};

// Coplanar triangles with the same outward normal form one face.
std::vector<PlanarFace> planarFaces(const TriangleMesh& mesh, const std::vector<int>& triangles, double tolerance) {
  std::vector<PlanarFace> faces;
  for (int t : triangles) {
    const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
    const Vec3 n2 = cross(minus(mesh.vertices[mesh.triangles[t][1]], a), minus(mesh.vertices[mesh.triangles[t][2]], a));
    if (norm(n2) == 0) continue;
    const Vec3 n = normalized(n2);
    PlanarFace* face = nullptr;
    for (PlanarFace& f : faces) {
      if (dot(f.normal, n) > 1 - tolerance::kDirection && std::abs(dot(f.normal, a) - f.offset) <= tolerance) face = &f;
    }
    if (!face) {
      faces.push_back({n, dot(n, a), 0, {}});
      face = &faces.back();
    }
    face->area += norm(n2) / 2;
    face->triangles.push_back(t);
  }
  return faces;
}

// The boundary loops of a face (edges used once among its triangles, chained), the largest first.
std::vector<Loop> boundaryLoops(const TriangleMesh& mesh, const PlanarFace& face, const std::string& who) {
  std::map<std::pair<Vec3, Vec3>, int> directed;
  for (int t : face.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{mesh.vertices[mesh.triangles[t][k]], mesh.vertices[mesh.triangles[t][(k + 1) % 3]]}];
  }
  std::map<Vec3, Vec3> next;  // boundary edges, by their start
  for (const auto& [edge, count] : directed) {
    if (directed.count({edge.second, edge.first}) == 0) {
      if (!next.emplace(edge.first, edge.second).second) throwBadInput(who, "a face's outline touches itself at a vertex");
    }
  }
  std::vector<Loop> loops;
  while (!next.empty()) {
    Loop loop;
    Vec3 at = next.begin()->first;
    while (next.count(at)) {
      loop.push_back(at);
      const Vec3 to = next[at];
      next.erase(at);
      at = to;
    }
    // Drop vertices where the outline runs straight on (a triangulation's extra points).
    Loop corners;
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3& p = loop[(i + loop.size() - 1) % loop.size()];
      const Vec3& q = loop[(i + 1) % loop.size()];
      const double turn = norm(cross(minus(loop[i], p), minus(q, loop[i])));
      if (turn > tolerance::kDirection * norm(minus(q, p)) * norm(minus(q, p))) corners.push_back(loop[i]);
    }
    if (corners.size() >= 3) loops.push_back(corners);
  }
  auto area = [](const Loop& loop) { return norm(loopNormal(loop)); };
  std::stable_sort(loops.begin(), loops.end(), [&](const Loop& a, const Loop& b) { return area(a) > area(b); });
  return loops;
}

// The top loop's vertices put in the bottom loop's order: the cyclic shift (with the same sense of
// turning) that brings each top vertex nearest to its bottom vertex carried across the thickness.
Loop matchLoop(const Loop& bottom, Loop top, const Vec3& across, const std::string& who) {
  if (top.size() != bottom.size()) throwBadInput(who, "its two large faces do not match: " + std::to_string(bottom.size()) + " and " + std::to_string(top.size()) + " corners");
  const size_t n = bottom.size();
  double best = HUGE_VAL;
  Loop matched;
  for (int reversed = 0; reversed < 2; ++reversed) {
    if (reversed) std::reverse(top.begin(), top.end());
    for (size_t shift = 0; shift < n; ++shift) {
      double cost = 0;
      for (size_t k = 0; k < n; ++k) cost += norm(minus(top[(k + shift) % n], {bottom[k][0] + across[0], bottom[k][1] + across[1], bottom[k][2] + across[2]}));
      if (cost < best) {
        best = cost;
        matched.clear();
        for (size_t k = 0; k < n; ++k) matched.push_back(top[(k + shift) % n]);
      }
    }
  }
  return matched;
}

Plate plateFromPiece(const TriangleMesh& mesh, const std::vector<int>& triangles, int id, const std::string& name,
                     double tolerance, const std::string& source) {
  const std::string who = source + ": plate " + std::to_string(id) + (name.empty() ? "" : " (" + name + ")");
  std::vector<PlanarFace> faces = planarFaces(mesh, triangles, tolerance);
  std::stable_sort(faces.begin(), faces.end(), [](const PlanarFace& a, const PlanarFace& b) { return a.area > b.area; });
  // The largest face and the largest one facing the other way, parallel to it.
  const PlanarFace* bottom = faces.empty() ? nullptr : &faces[0];
  const PlanarFace* top = nullptr;
  for (size_t f = 1; f < faces.size() && bottom; ++f) {
    if (dot(faces[f].normal, bottom->normal) < -1 + tolerance::kFacingCosine) {
      top = &faces[f];
      break;
    }
  }
  if (!top) {
    throwBadInput(who, std::string("is not a slab: it has no two parallel faces facing away from each other") +
                           (mesh.groupNames.empty() ? " (in a mesh without objects, plates that share whole faces, such as mitres, "
                                                      "cannot be told apart: give each plate its own OBJ object)"
                                                    : ""));
  }
  std::vector<Loop> bottomLoops = boundaryLoops(mesh, *bottom, who);
  std::vector<Loop> topLoops = boundaryLoops(mesh, *top, who);
  if (bottomLoops.empty() || bottomLoops.size() != topLoops.size()) throwBadInput(who, "its two large faces have different holes");
  const double thickness = bottom->offset + top->offset;  // between the planes, across from the bottom face
  const Vec3 across = scaled(negated(bottom->normal), thickness);
  Plate plate;
  plate.id = id;
  plate.name = name;
  for (size_t l = 0; l < bottomLoops.size(); ++l) {
    // Pair each top loop with the bottom loop it lies over (nearest centroids).
    auto centroid = [](const Loop& loop) {
      Vec3 c{0, 0, 0};
      for (const Vec3& p : loop) c = {c[0] + p[0], c[1] + p[1], c[2] + p[2]};
      return scaled(c, 1.0 / static_cast<double>(loop.size()));
    };
    size_t bestTop = 0;
    for (size_t m = 1; m < topLoops.size(); ++m) {
      if (norm(minus(centroid(topLoops[m]), centroid(bottomLoops[l]))) < norm(minus(centroid(topLoops[bestTop]), centroid(bottomLoops[l])))) bestTop = m;
    }
    plate.bottom.push_back(bottomLoops[l]);
    plate.top.push_back(matchLoop(bottomLoops[l], topLoops[bestTop], across, who));
    topLoops.erase(topLoops.begin() + static_cast<long>(bestTop));
  }
  return plate;
}

}  // namespace

std::vector<Plate> platesFromMesh(const TriangleMesh& mesh, const PlateOptions& options, const std::string& source) {
  std::vector<Plate> plates;
  const std::vector<std::vector<int>> parts = pieces(mesh);
  if (parts.empty()) throwBadInput(source, "the mesh has no faces");
  for (size_t p = 0; p < parts.size(); ++p) {
    std::string name;
    if (!mesh.groupNames.empty()) name = mesh.groupNames[mesh.triangleGroup[parts[p][0]]];
    plates.push_back(plateFromPiece(mesh, parts[p], static_cast<int>(p) + 1, name, options.contactTolerance, source));
  }
  return plates;
}

}  // namespace desia
