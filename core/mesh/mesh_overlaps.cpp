// SPDX-License-Identifier: GPL-3.0-or-later
// A part that intersects itself (two of its triangles that share no vertex cross), and parts that
// overlap: two triangles of different parts that cross each other by more than the
// tolerance (each pierces the other's plane beyond it, and the two pieces of the crossing line
// overlap along it by more than it), or a part wholly inside another (no crossing; a vertex
// farther than the tolerance from the other's surface is inside it). Faces lying on one another,
// parts touching along an edge or at a point, and overlaps within the tolerance are contacts.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "desia/error.h"
#include "mesh/mesh_geometry.h"

namespace desia::mesh {
namespace {

// The piece of triangle t on the plane (n, c) as an interval along `line`, when t has vertices
// farther than `tolerance` on both sides of the plane.
bool pierceInterval(const Triangle& t, const Vec3& n, double c, const Vec3& line, double tolerance, double* low,
                    double* high) {
  double side[3];
  double least = 0, most = 0;
  for (int k = 0; k < 3; ++k) {
    side[k] = dot(n, t.p[static_cast<size_t>(k)]) - c;
    least = std::min(least, side[k]);
    most = std::max(most, side[k]);
  }
  if (least >= -tolerance || most <= tolerance) return false;
  *low = std::numeric_limits<double>::infinity();
  *high = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const int m = (k + 1) % 3;
    if ((side[k] < 0) == (side[m] < 0) && side[k] != 0) continue;
    if (side[k] == side[m]) continue;
    const Vec3 point = plus(t.p[static_cast<size_t>(k)],
                            scaled(minus(t.p[static_cast<size_t>(m)], t.p[static_cast<size_t>(k)]), side[k] / (side[k] - side[m])));
    const double along = dot(point, line);
    *low = std::min(*low, along);
    *high = std::max(*high, along);
  }
  return *low <= *high;
}

// A point where the triangles cross by more than the tolerance, if they do.
bool trianglesCross(const Triangle& a, const Triangle& b, double tolerance, Vec3* where) {
  if (a.twiceArea == 0 || b.twiceArea == 0) return false;
  const Vec3 direction = cross(a.normal, b.normal);
  const double length = norm(direction);
  if (length <= tolerance::kParallelSine) return false;  // parallel planes: on one another at most
  const Vec3 line = scaled(direction, 1.0 / length);
  double aLow, aHigh, bLow, bHigh;
  if (!pierceInterval(a, b.normal, dot(b.normal, b.p[0]), line, tolerance, &aLow, &aHigh)) return false;
  if (!pierceInterval(b, a.normal, dot(a.normal, a.p[0]), line, tolerance, &bLow, &bHigh)) return false;
  if (std::min(aHigh, bHigh) - std::max(aLow, bLow) <= tolerance) return false;
  *where = scaled(plus(plus(a.p[0], a.p[1]), a.p[2]), 1.0 / 3);
  return true;
}

bool crossingPoint(const PartGeometry& a, const PartGeometry& b, double tolerance, Vec3* where) {
  bool found = false;
  for (const Triangle& t : a.triangles) {
    const Box box = t.box();
    b.tree.query([&](const Box& other) { return box.overlaps(other, -tolerance); },
                 [&](int index) {
                   found = trianglesCross(t, b.triangles[static_cast<size_t>(index)], tolerance, where);
                   return !found;
                 });
    if (found) return true;
  }
  return false;
}

// With no crossing, `inner` is inside `outer` or outside it; a vertex off outer's surface decides.
bool insideWithoutCrossing(const PartGeometry& inner, const PartGeometry& outer, double tolerance, Vec3* where) {
  Box grown = outer.box;
  for (int i = 0; i < 3; ++i) grown.lo[i] -= tolerance, grown.hi[i] += tolerance;
  if (!(grown.lo[0] <= inner.box.lo[0] && grown.lo[1] <= inner.box.lo[1] && grown.lo[2] <= inner.box.lo[2] &&
        inner.box.hi[0] <= grown.hi[0] && inner.box.hi[1] <= grown.hi[1] && inner.box.hi[2] <= grown.hi[2])) {
    return false;
  }
  for (const Triangle& t : inner.triangles) {
    for (const Vec3& p : t.p) {
      double distance = std::numeric_limits<double>::infinity();
      for (const Triangle& s : outer.triangles) distance = std::min(distance, pointTriangleDistance(p, s));
      if (distance <= tolerance) continue;
      *where = p;
      return pointInside(p, outer);
    }
  }
  return false;
}

bool sharesAVertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int u : a) {
    for (int v : b) {
      if (u == v) return true;
    }
  }
  return false;
}

// The shell of each triangle: triangles joined through shared vertices (union-find, iterative).
std::vector<int> shellOfTriangles(const TriangleMesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  const auto root = [&](int v) {
    while (parent[static_cast<size_t>(v)] != v) {
      parent[static_cast<size_t>(v)] = parent[static_cast<size_t>(parent[static_cast<size_t>(v)])];
      v = parent[static_cast<size_t>(v)];
    }
    return v;
  };
  for (const auto& t : mesh.triangles) {
    parent[static_cast<size_t>(root(t[1]))] = root(t[0]);
    parent[static_cast<size_t>(root(t[2]))] = root(t[0]);
  }
  std::vector<int> shell;
  shell.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) shell.push_back(root(t[0]));
  return shell;
}

// A point where two triangles of one shell of the part that share no vertex cross by more than the
// tolerance. Shells of one part may cross each other: the part is their union (desia's own frame
// exports write a beam's body and its joint voxels as overlapping closed boxes).
bool selfCrossing(const TriangleMesh& mesh, const PartGeometry& part, double tolerance, Vec3* where) {
  const std::vector<int> shell = shellOfTriangles(mesh);
  bool found = false;
  for (size_t t = 0; t < part.triangles.size() && !found; ++t) {
    const Box box = part.triangles[t].box();
    part.tree.query([&](const Box& other) { return box.overlaps(other, -tolerance); },
                    [&](int index) {
                      if (static_cast<size_t>(index) <= t || shell[t] != shell[static_cast<size_t>(index)] ||
                          sharesAVertex(mesh.triangles[t], mesh.triangles[static_cast<size_t>(index)])) {
                        return true;
                      }
                      found = trianglesCross(part.triangles[t], part.triangles[static_cast<size_t>(index)], tolerance, where);
                      return !found;
                    });
  }
  return found;
}

}  // namespace

void requireNoOverlaps(const std::vector<MeshPart>& parts, const std::vector<PartGeometry>& geometry,
                       double tolerance) {
  for (size_t a = 0; a < parts.size(); ++a) {
    Vec3 where{};
    if (selfCrossing(parts[a].mesh, geometry[a], tolerance, &where)) {
      throwBadInput(partLabel(parts[a]), "intersects itself: two of its triangles cross near " + pointText(where));
    }
  }
  for (size_t a = 0; a < parts.size(); ++a) {
    for (size_t b = a + 1; b < parts.size(); ++b) {
      if (!geometry[a].box.overlaps(geometry[b].box, -tolerance)) continue;
      Vec3 where{};
      if (crossingPoint(geometry[a], geometry[b], tolerance, &where)) {
        throwBadInput(partLabel(parts[a]), "overlaps part " + std::to_string(parts[b].id) + " (" + parts[b].source +
                                               ") by more than the tolerance of " + std::to_string(tolerance) +
                                               " mm: their surfaces cross near " + pointText(where));
      }
      const bool aInB = insideWithoutCrossing(geometry[a], geometry[b], tolerance, &where);
      if (aInB || insideWithoutCrossing(geometry[b], geometry[a], tolerance, &where)) {
        const MeshPart& inner = aInB ? parts[a] : parts[b];
        const MeshPart& outer = aInB ? parts[b] : parts[a];
        throwBadInput(partLabel(inner), "lies inside part " + std::to_string(outer.id) + " (" + outer.source +
                                            "): its vertex " + pointText(where) + " is inside it");
      }
    }
  }
}

}  // namespace desia::mesh
