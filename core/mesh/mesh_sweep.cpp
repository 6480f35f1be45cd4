// SPDX-License-Identifier: GPL-3.0-or-later
// Sweeping parts of a mesh assembly along a direction (paper Section 3.3: a removal is valid when
// the moving parts pass every part in place). Along any line parallel to d, a solid is a set of
// intervals: it enters through a back-facing triangle (normal·d < 0) and leaves through a
// front-facing one. Moving solid A along d to infinity runs into solid B exactly when, on some
// open set of lines, B is entered at or beyond where A is left: a front-facing triangle a of A and
// a back-facing triangle b of B whose shadows (along d) overlap with positive area, and somewhere
// in that overlap b's depth reaches a's (within the tolerance: a contact face against the
// direction of motion blocks it). Depths are linear on the overlap, a convex polygon, so its
// corners decide. The triangle swept along d is the prism tested; box trees prune the pairs.
// Triangles within tolerance::kDrawnDirectionRad of parallel to d slide along d: drawn to a few
// decimals, a face the motion slides along is tilted that much, and its sliver of shadow would
// read as a wall.
#include <algorithm>
#include <cmath>

#include "desia/tolerances.h"
#include "mesh/mesh_geometry.h"

namespace desia::mesh {
namespace {

using Point2 = std::array<double, 2>;
using Polygon2 = std::vector<Point2>;

struct Shadow {
  Vec3 u, v, d;
  explicit Shadow(const Vec3& direction) : d(direction) {
    const Vec3 axis = std::abs(d[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u = normalized(cross(d, axis));
    v = cross(d, u);
  }
  Point2 flat(const Vec3& p) const { return {dot(p, u), dot(p, v)}; }
  // The depth along d of the point of t's plane over the shadow point q.
  double depth(const Triangle& t, const Point2& q) const {
    const Vec3 inPlane = plus(scaled(u, q[0]), scaled(v, q[1]));
    return (dot(t.normal, t.p[0]) - dot(t.normal, inPlane)) / dot(t.normal, d);
  }
};

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

Polygon2 counterClockwise(Polygon2 polygon) {
  if (cross2(polygon[0], polygon[1], polygon[2]) < 0) std::swap(polygon[1], polygon[2]);
  return polygon;
}

// Sutherland–Hodgman: the convex polygon clipped by each edge of the counter-clockwise triangle.
Polygon2 clipByTriangle(Polygon2 polygon, const Polygon2& triangle) {
  for (size_t e = 0; e < 3 && !polygon.empty(); ++e) {
    const Point2& a = triangle[e];
    const Point2& b = triangle[(e + 1) % 3];
    Polygon2 kept;
    for (size_t k = 0; k < polygon.size(); ++k) {
      const Point2& p = polygon[k];
      const Point2& q = polygon[(k + 1) % polygon.size()];
      const double sp = cross2(a, b, p), sq = cross2(a, b, q);
      if (sp >= 0) kept.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const double s = sp / (sp - sq);
        kept.push_back({p[0] + (q[0] - p[0]) * s, p[1] + (q[1] - p[1]) * s});
      }
    }
    polygon = std::move(kept);
  }
  return polygon;
}

double areaOf(const Polygon2& polygon) {
  double twice = 0;
  for (size_t k = 0; k + 2 < polygon.size(); ++k) twice += cross2(polygon[0], polygon[k + 1], polygon[k + 2]);
  return twice / 2;
}

// The diagonal of the polygon's bounding box: a region of area at most tolerance × this is a sliver
// no wider than the tolerance (two faces meeting along an edge, seen along a direction in their
// contact plane up to rounding), not an overlap.
double extentOf(const Polygon2& polygon) {
  double lo[2] = {polygon[0][0], polygon[0][1]}, hi[2] = {polygon[0][0], polygon[0][1]};
  for (const Point2& p : polygon) {
    for (int i = 0; i < 2; ++i) lo[i] = std::min(lo[i], p[static_cast<size_t>(i)]), hi[i] = std::max(hi[i], p[static_cast<size_t>(i)]);
  }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

// How far `front`'s part can travel along d before `back`'s part stops it: infinity when the
// shadows do not overlap with positive area or b lies behind a (by more than the tolerance);
// else the least depth gap over the overlap, at least 0 (touching already).
double pairTravel(const Triangle& front, const Triangle& back, const Shadow& shadow, double tolerance,
                  double emptyArea) {
  constexpr double kClear = std::numeric_limits<double>::infinity();
  Polygon2 a, b;
  for (const Vec3& p : front.p) a.push_back(shadow.flat(p));
  for (const Vec3& p : back.p) b.push_back(shadow.flat(p));
  const Polygon2 overlap = clipByTriangle(counterClockwise(a), counterClockwise(b));
  if (overlap.size() < 3 || areaOf(overlap) <= std::max(emptyArea, tolerance * extentOf(overlap))) return kClear;
  // Keep the part of the overlap where b is not behind a (gap >= -tolerance): the gap is linear,
  // so that part is the overlap clipped by a line. Where it is a sliver, b is behind a except
  // along an edge where both solids thin out to nothing (their silhouettes), which blocks nothing.
  std::vector<double> gaps;
  for (const Point2& q : overlap) gaps.push_back(shadow.depth(back, q) - shadow.depth(front, q) + tolerance);
  Polygon2 ahead;
  std::vector<double> aheadGaps;
  for (size_t k = 0; k < overlap.size(); ++k) {
    const size_t m = (k + 1) % overlap.size();
    if (gaps[k] >= 0) ahead.push_back(overlap[k]), aheadGaps.push_back(gaps[k]);
    if ((gaps[k] >= 0) != (gaps[m] >= 0)) {
      const double s = gaps[k] / (gaps[k] - gaps[m]);
      ahead.push_back({overlap[k][0] + (overlap[m][0] - overlap[k][0]) * s, overlap[k][1] + (overlap[m][1] - overlap[k][1]) * s});
      aheadGaps.push_back(0);
    }
  }
  if (ahead.size() < 3 || areaOf(ahead) <= std::max(emptyArea, tolerance * extentOf(ahead))) return kClear;
  const double least = *std::min_element(aheadGaps.begin(), aheadGaps.end()) - tolerance;
  return std::max(least, 0.0);
}

// The box moved by `offset`.
Box shifted(const Box& box, const Vec3& offset) { return Box{plus(box.lo, offset), plus(box.hi, offset)}; }

Triangle shifted(Triangle triangle, const Vec3& offset) {
  for (Vec3& p : triangle.p) p = plus(p, offset);
  return triangle;
}

// The least travel over the pairs of the two parts, the mover placed `moverOffset` off where its
// geometry lies, stopping early once it is below `stopBelow`. *work (if given) counts the mover's
// triangles looked at and the triangle pairs compared: the cost, whatever the meshes' sizes.
double partTravel(const PartGeometry& mover, const Vec3& moverOffset, const PartGeometry& obstacle,
                  const Shadow& shadow, double tolerance, double emptyArea, double stopBelow, int64_t* work) {
  const Vec3& d = shadow.d;
  const bool moved = moverOffset != Vec3{0, 0, 0};
  double travel = std::numeric_limits<double>::infinity();
  if (work) ++*work;  // the boxes' test: a pair whose boxes miss costs a step too
  if (!sweptBoxMeets(shifted(mover.box, moverOffset), d, obstacle.box, tolerance)) return travel;
  int64_t pairs = 0;
  for (const Triangle& placed : mover.triangles) {
    if (dot(placed.normal, d) <= tolerance::kDrawnDirectionRad) continue;
    const Triangle front = moved ? shifted(placed, moverOffset) : placed;
    const Box box = front.box();
    if (!sweptBoxMeets(box, d, obstacle.box, tolerance)) continue;
    obstacle.tree.query([&](const Box& other) { return sweptBoxMeets(box, d, other, tolerance); },
                        [&](int index) {
                          const Triangle& back = obstacle.triangles[static_cast<size_t>(index)];
                          if (dot(back.normal, d) < -tolerance::kDrawnDirectionRad) {
                            ++pairs;
                            travel = std::min(travel, pairTravel(front, back, shadow, tolerance, emptyArea));
                          }
                          return travel >= stopBelow;
                        });
    if (travel < stopBelow) break;
  }
  if (work) *work += static_cast<int64_t>(mover.triangles.size()) + pairs;
  return travel;
}

}  // namespace

double travelDistance(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                      const std::vector<const PartGeometry*>& movers, const std::vector<bool>& obstacles,
                      const Vec3& d, double stopBelow, int* obstacle) {
  const Shadow shadow(normalized(d));
  const double emptyArea = tolerance::kMeshEmptyAreaShare * meshes.diagonal * meshes.diagonal;
  double travel = std::numeric_limits<double>::infinity();
  for (size_t other = 0; other < geometry.size(); ++other) {
    if (!obstacles[other]) continue;
    for (const PartGeometry* mover : movers) {
      const double t = partTravel(*mover, Vec3{0, 0, 0}, geometry[other], shadow, meshes.tolerance, emptyArea, stopBelow, nullptr);
      if (t < travel) {
        travel = t;
        if (obstacle) *obstacle = static_cast<int>(other);
      }
      if (travel < stopBelow) return travel;
    }
  }
  return travel;
}

double pairTravelDistance(const MeshAssembly& meshes, const PartGeometry& mover, const Vec3& moverOffset,
                          const PartGeometry& obstacle, const Vec3& d, int64_t* work) {
  const double emptyArea = tolerance::kMeshEmptyAreaShare * meshes.diagonal * meshes.diagonal;
  // 0: the least travel, never stopping early
  return partTravel(mover, moverOffset, obstacle, Shadow(normalized(d)), meshes.tolerance, emptyArea, 0, work);
}

std::string sweepObstacle(const MeshAssembly& meshes, const std::vector<PartGeometry>& geometry,
                          const std::vector<int>& moving, const std::vector<bool>& present, const Vec3& d) {
  std::vector<bool> obstacles = present;
  std::vector<const PartGeometry*> movers;
  for (int part : moving) {
    obstacles[static_cast<size_t>(part)] = false;
    movers.push_back(&geometry[static_cast<size_t>(part)]);
  }
  int obstacle = -1;
  const double travel =
      travelDistance(meshes, geometry, movers, obstacles, d, std::numeric_limits<double>::infinity(), &obstacle);
  return std::isinf(travel) ? "" : "part " + std::to_string(meshes.parts[static_cast<size_t>(obstacle)].id);
}

}  // namespace desia::mesh

namespace desia {

std::string meshSweepObstacle(const MeshAssembly& meshes, const std::vector<int>& moving,
                              const std::vector<bool>& present, const Vec3& d) {
  return mesh::sweepObstacle(meshes, mesh::geometryOf(meshes), moving, present, d);
}

}  // namespace desia
