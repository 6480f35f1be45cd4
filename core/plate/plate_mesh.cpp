// SPDX-License-Identifier: GPL-3.0-or-later
// A plate as a closed triangle mesh: its two faces (outline with holes) triangulated by ear
// clipping after joining each hole to the outline by a bridge, and one quad (two triangles) per
// side. Clipper offers booleans and offsets but no triangulation, and Debian packages no C++
// triangulation library small enough for the WebAssembly build, hence these few lines.
#include "desia/plate.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/vec3.h"
#include "desia/error.h"

namespace desia {
namespace {

using Point2 = std::array<double, 2>;

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double signedArea(const std::vector<Point2>& points, const std::vector<int>& loop) {
  double area = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Point2& p = points[loop[i]];
    const Point2& q = points[loop[(i + 1) % loop.size()]];
    area += p[0] * q[1] - q[0] * p[1];
  }
  return area / 2;
}

bool onSegment(const Point2& a, const Point2& b, const Point2& p) {
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
         p[1] <= std::max(a[1], b[1]);
}

// Do the closed segments ab and cd meet (touching and collinear overlaps count)?
bool segmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double d1 = cross2(c, d, a), d2 = cross2(c, d, b), d3 = cross2(a, b, c), d4 = cross2(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) || (d3 == 0 && onSegment(a, b, c)) ||
         (d4 == 0 && onSegment(a, b, d));
}

// Does the direction from loop vertex `at` towards b start inside the region, which lies left of
// the loop's edges (outline counter-clockwise, holes clockwise)?
bool locallyInside(const std::vector<Point2>& points, const std::vector<int>& loop, size_t at, const Point2& b) {
  const Point2& p = points[loop[(at + loop.size() - 1) % loop.size()]];
  const Point2& o = points[loop[at]];
  const Point2& n = points[loop[(at + 1) % loop.size()]];
  const bool leftOfIn = cross2(p, o, b) >= 0, leftOfOut = cross2(o, n, b) >= 0;
  return cross2(p, o, n) >= 0 ? leftOfIn && leftOfOut : leftOfIn || leftOfOut;
}

// Even-odd containment of a point in the loops.
bool insideLoops(const std::vector<Point2>& points, const std::vector<std::vector<int>>& loops, const Point2& q) {
  bool inside = false;
  for (const std::vector<int>& loop : loops) {
    for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const Point2& a = points[loop[i]];
      const Point2& b = points[loop[j]];
      if ((a[1] > q[1]) != (b[1] > q[1]) && q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0])
        inside = !inside;
    }
  }
  return inside;
}

// Can a bridge run from `from` to `to` without meeting any edge (other than at its own ends),
// through the inside of the region?
bool bridgeClear(const std::vector<Point2>& points, const std::vector<std::vector<int>>& loops, const Point2& from,
                 const Point2& to) {
  for (const std::vector<int>& loop : loops) {
    for (size_t e = 0; e < loop.size(); ++e) {
      const Point2& c = points[loop[e]];
      const Point2& d = points[loop[(e + 1) % loop.size()]];
      if (c == from || c == to || d == from || d == to) continue;
      if (segmentsMeet(from, to, c, d)) return false;
    }
  }
  return insideLoops(points, loops, {(from[0] + to[0]) / 2, (from[1] + to[1]) / 2});
}

// Joins each hole (clockwise) to the outline (counter-clockwise) by a two-way bridge from the
// hole's rightmost vertex to the nearest outline vertex it can see (no edge in the way, leaving
// both vertices into the region), giving one simple-in-effect polygon that ear clipping can cut.
std::vector<int> bridgeHoles(const std::vector<Point2>& points, std::vector<int> outer,
                             std::vector<std::vector<int>> holes) {
  std::sort(holes.begin(), holes.end(), [&](const std::vector<int>& a, const std::vector<int>& b) {
    auto rightmost = [&](const std::vector<int>& h) {
      double x = -HUGE_VAL;
      for (int i : h) x = std::max(x, points[i][0]);
      return x;
    };
    return rightmost(a) > rightmost(b);
  });
  for (size_t h = 0; h < holes.size(); ++h) {
    const std::vector<int>& hole = holes[h];
    size_t m = 0;
    for (size_t i = 1; i < hole.size(); ++i) {
      if (points[hole[i]][0] > points[hole[m]][0]) m = i;
    }
    const Point2& from = points[hole[m]];
    std::vector<std::vector<int>> loops{outer};
    loops.insert(loops.end(), holes.begin() + static_cast<long>(h), holes.end());
    std::vector<size_t> candidates(outer.size());
    for (size_t o = 0; o < outer.size(); ++o) candidates[o] = o;
    auto distance = [&](size_t o) { return std::hypot(points[outer[o]][0] - from[0], points[outer[o]][1] - from[1]); };
    std::stable_sort(candidates.begin(), candidates.end(),
                     [&](size_t x, size_t y) { return distance(x) < distance(y); });
    size_t best = candidates.front();
    for (size_t o : candidates) {
      const Point2& to = points[outer[o]];
      if (to == from) continue;
      if (locallyInside(points, outer, o, from) && locallyInside(points, hole, m, to) &&
          bridgeClear(points, loops, from, to)) {
        best = o;
        break;
      }
    }
    std::vector<int> merged(outer.begin(), outer.begin() + static_cast<long>(best) + 1);
    for (size_t k = 0; k <= hole.size(); ++k) merged.push_back(hole[(m + k) % hole.size()]);
    merged.insert(merged.end(), outer.begin() + static_cast<long>(best), outer.end());
    outer = merged;
  }
  return outer;
}

bool insideTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Ear clipping of a counter-clockwise polygon (bridges allowed: repeated points are skipped in the
// containment test). Appends triangles as index triples.
void clipEars(const std::vector<Point2>& points, std::vector<int> polygon, std::vector<std::array<int, 3>>* triangles) {
  while (polygon.size() > 3) {
    const size_t n = polygon.size();
    size_t ear = n;
    for (size_t i = 0; i < n && ear == n; ++i) {
      const int a = polygon[(i + n - 1) % n], b = polygon[i], c = polygon[(i + 1) % n];
      if (cross2(points[a], points[b], points[c]) <= 0) continue;  // reflex or flat
      bool empty = true;
      for (size_t j = 0; j < n && empty; ++j) {
        const int p = polygon[j];
        if (points[p] == points[a] || points[p] == points[b] || points[p] == points[c]) continue;
        if (insideTriangle(points[p], points[a], points[b], points[c])) empty = false;
      }
      if (empty) ear = i;
    }
    if (ear == n) {
      // Only flat or degenerate corners left (rounding): drop the flattest one without a triangle.
      size_t flattest = 0;
      double smallest = HUGE_VAL;
      for (size_t i = 0; i < n; ++i) {
        const double area =
            std::abs(cross2(points[polygon[(i + n - 1) % n]], points[polygon[i]], points[polygon[(i + 1) % n]]));
        if (area < smallest) {
          smallest = area;
          flattest = i;
        }
      }
      polygon.erase(polygon.begin() + static_cast<long>(flattest));
      continue;
    }
    triangles->push_back({polygon[(ear + n - 1) % n], polygon[ear], polygon[(ear + 1) % n]});
    polygon.erase(polygon.begin() + static_cast<long>(ear));
  }
  if (polygon.size() == 3 && cross2(points[polygon[0]], points[polygon[1]], points[polygon[2]]) > 0) {
    triangles->push_back({polygon[0], polygon[1], polygon[2]});
  }
}

// Triangles of a planar face (loops[0] the outline, the rest holes) wound counter-clockwise about
// `outward`; the loops' vertices are mesh vertices first, first + 1, ... in loop order.
void addFace(const std::vector<Loop>& loops, const Vec3& outward, int first, TriangleMesh* mesh) {
  const Vec3 axis = std::abs(outward[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(outward, axis));
  const Vec3 v = cross(outward, u);
  std::vector<Point2> points;
  std::vector<std::vector<int>> indexLoops;
  for (const Loop& loop : loops) {
    std::vector<int> indices;
    for (const Vec3& p : loop) {
      indices.push_back(static_cast<int>(points.size()));
      points.push_back({dot(p, u), dot(p, v)});
    }
    indexLoops.push_back(indices);
  }
  // The outline counter-clockwise, holes clockwise, in the (u, v) frame seen from outside.
  if (signedArea(points, indexLoops[0]) < 0) std::reverse(indexLoops[0].begin(), indexLoops[0].end());
  for (size_t h = 1; h < indexLoops.size(); ++h) {
    if (signedArea(points, indexLoops[h]) > 0) std::reverse(indexLoops[h].begin(), indexLoops[h].end());
  }
  const std::vector<int> polygon =
      bridgeHoles(points, indexLoops[0], std::vector<std::vector<int>>(indexLoops.begin() + 1, indexLoops.end()));
  std::vector<std::array<int, 3>> triangles;
  clipEars(points, polygon, &triangles);
  for (const auto& t : triangles) mesh->triangles.push_back({first + t[0], first + t[1], first + t[2]});
}


}  // namespace

TriangleMesh plateMesh(const Plate& plate) {
  const Vec3 axis = plateThicknessAxis(plate);
  TriangleMesh mesh;
  // Shared vertices: every bottom loop, then every top loop, so the faces and sides meet on
  // common vertices and each edge is used by exactly two triangles.
  std::vector<int> bottomStart, topStart;
  for (const auto* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      (face == &plate.bottom ? bottomStart : topStart).push_back(static_cast<int>(mesh.vertices.size()));
      mesh.vertices.insert(mesh.vertices.end(), loop.begin(), loop.end());
    }
  }
  addFace(plate.bottom, negated(axis), bottomStart[0], &mesh);
  addFace(plate.top, axis, topStart[0], &mesh);
  // Sides: the quad between bottom edge k and top edge k, wound so that its normal is the side's
  // outward normal.
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& b = plate.bottom[l];
    const Loop& t = plate.top[l];
    const std::vector<Vec3> outward = plateSideNormals(plate, l);
    for (size_t k = 0; k < b.size(); ++k) {
      const size_t next = (k + 1) % b.size();
      const int b0 = bottomStart[l] + static_cast<int>(k), b1 = bottomStart[l] + static_cast<int>(next);
      const int t0 = topStart[l] + static_cast<int>(k), t1 = topStart[l] + static_cast<int>(next);
      const Vec3 n = cross(minus(b[next], b[k]), minus(t[k], b[k]));
      if (dot(n, outward[k]) > 0) {
        mesh.triangles.push_back({b0, b1, t1});
        mesh.triangles.push_back({b0, t1, t0});
      } else {
        mesh.triangles.push_back({b0, t1, b1});
        mesh.triangles.push_back({b0, t0, t1});
      }
    }
  }
  // Attached solids (milled joints): closed shells of their own, in the same mesh.
  for (const Plate& solid : plate.attached) {
    const TriangleMesh piece = plateMesh(solid);
    const int first = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const auto& t : piece.triangles) mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  }
  return mesh;
}

}  // namespace desia
