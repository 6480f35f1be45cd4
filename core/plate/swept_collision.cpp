// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/swept_collision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/plane_frame.h"

namespace desia {
namespace {

struct Shadow {  // a triangle seen along d: 2D corners (u, v) and their depths along d
  std::array<std::array<double, 2>, 3> corner;
  std::array<double, 3> depth;
  double minU, maxU, minV, maxV;
};

// The shadows of the triangles whose outward normal points along `facing` times the frame's
// normal (the direction of motion).
std::vector<Shadow> shadowsOf(const TriangleMesh& mesh, const PlaneFrame& frame, int facing) {
  std::vector<Shadow> shadows;
  for (const auto& triangle : mesh.triangles) {
    Shadow s;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = mesh.vertices[triangle[i]];
      const Vec3 offset = minus(p, frame.origin);
      s.corner[i] = {dot(offset, frame.u), dot(offset, frame.v)};
      s.depth[i] = dot(offset, frame.normal);
    }
    const double twiceArea = (s.corner[1][0] - s.corner[0][0]) * (s.corner[2][1] - s.corner[0][1]) -
                             (s.corner[2][0] - s.corner[0][0]) * (s.corner[1][1] - s.corner[0][1]);
    if (std::abs(twiceArea) < tolerance::kEdgeOnTwiceAreaMm2)
      continue;  // edge-on: its solid is seen through its neighbours
    // Keep the triangles facing `facing` times d (outward triangles wind counter-clockwise seen
    // from outside, and (u, v, d) is right-handed: those facing +d have a positive area).
    if ((twiceArea > 0) != (facing > 0)) continue;
    if (twiceArea < 0) {
      std::swap(s.corner[1], s.corner[2]);
      std::swap(s.depth[1], s.depth[2]);
    }
    s.minU = std::min({s.corner[0][0], s.corner[1][0], s.corner[2][0]});
    s.maxU = std::max({s.corner[0][0], s.corner[1][0], s.corner[2][0]});
    s.minV = std::min({s.corner[0][1], s.corner[1][1], s.corner[2][1]});
    s.maxV = std::max({s.corner[0][1], s.corner[1][1], s.corner[2][1]});
    shadows.push_back(s);
  }
  return shadows;
}

using Point2 = std::array<double, 2>;

// The part of a convex polygon left of the directed line a -> b (Sutherland-Hodgman, one edge).
std::vector<Point2> clipLeftOf(const std::vector<Point2>& polygon, const Point2& a, const Point2& b) {
  auto side = [&](const Point2& p) { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
  std::vector<Point2> out;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % polygon.size()];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

// Depth of a shadow's triangle plane at a 2D point (barycentric interpolation).
double depthAt(const Shadow& s, const Point2& p) {
  const auto& a = s.corner[0];
  const auto& b = s.corner[1];
  const auto& c = s.corner[2];
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  const double l1 = ((p[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (p[1] - a[1])) / det;
  const double l2 = ((b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])) / det;
  return s.depth[0] + l1 * (s.depth[1] - s.depth[0]) + l2 * (s.depth[2] - s.depth[0]);
}

double polygonPerimeter(const std::vector<Point2>& polygon) {
  double length = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % polygon.size()];
    length += std::hypot(q[0] - p[0], q[1] - p[1]);
  }
  return length;
}

double polygonArea(const std::vector<Point2>& polygon) {
  double twice = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % polygon.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return std::abs(twice) / 2;
}

}  // namespace

bool plateCollidesAlong(const Plate& mover, const Plate& obstacle, const Vec3& d, double tolerance) {
  return meshCollidesAlong(plateMesh(mover), plateMesh(obstacle), d, tolerance);
}

namespace {

Box boxOf(const TriangleMesh& mesh) {
  Box box{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for (const auto& p : mesh.vertices) {
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], p[k]), box.hi[k] = std::max(box.hi[k], p[k]);
  }
  return box;
}

// The region a box sweeps along d (unbounded on the side d points to, on each axis).
Box sweptRegion(const Box& mover, const Vec3& d) {
  Box region = mover;
  for (int k = 0; k < 3; ++k) {
    if (d[k] > tolerance::kComponentNoise) region.hi[k] = HUGE_VAL;
    if (d[k] < -tolerance::kComponentNoise) region.lo[k] = -HUGE_VAL;
  }
  return region;
}

// Does the box reach more than the tolerance into the region on every axis?
bool reachesInto(const Box& box, const Box& region, double tolerance) {
  for (int k = 0; k < 3; ++k) {
    if (box.hi[k] <= region.lo[k] + tolerance || region.hi[k] <= box.lo[k] + tolerance) return false;
  }
  return true;
}

}  // namespace

bool meshCollidesAlong(const TriangleMesh& mover, const TriangleMesh& obstacle, const Vec3& d, double tolerance) {
  if (mover.vertices.empty() || obstacle.vertices.empty()) return false;
  // Boxes first: the obstacle must reach into the box the mover sweeps.
  if (!reachesInto(boxOf(obstacle), sweptRegion(boxOf(mover), d), tolerance)) return false;
  const PlaneFrame frame(mover.vertices[0], d);
  // On a line along d, a piece [p0, p1] of the mover moved by t > 0 meets a piece [q0, q1] of the
  // obstacle for some t exactly when q1 > p0: the obstacle's far end (a triangle facing +d) lies
  // beyond the mover's rear end (a triangle facing -d). Those triangles alone decide.
  const std::vector<Shadow> moving = shadowsOf(mover, frame, -1);
  const std::vector<Shadow> standing = shadowsOf(obstacle, frame, +1);
  for (const Shadow& m : moving) {
    for (const Shadow& s : standing) {
      if (m.maxU <= s.minU || s.maxU <= m.minU || m.maxV <= s.minV || s.maxV <= m.minV) continue;
      std::vector<Point2> overlap(m.corner.begin(), m.corner.end());
      for (int i = 0; i < 3 && !overlap.empty(); ++i) overlap = clipLeftOf(overlap, s.corner[i], s.corner[(i + 1) % 3]);
      // Shadows that only touch (at an edge, or at a corner: an "overlap" of rounding noise), or
      // overlap in a sliver narrower than the tolerance (2 area / perimeter is about a sliver's
      // width), do not meet.
      const double area = polygonArea(overlap);
      if (overlap.size() < 3 || area <= tolerance * tolerance || 2 * area <= tolerance * polygonPerimeter(overlap)) continue;
      // The depth gap is affine over the overlap: its largest value is at a corner.
      for (const Point2& p : overlap) {
        if (depthAt(s, p) - depthAt(m, p) > tolerance) return true;
      }
    }
  }
  return false;
}

}  // namespace desia

namespace desia {

SweptBoxIndex::SweptBoxIndex(const std::vector<TriangleMesh>& meshes) {
  for (const TriangleMesh& mesh : meshes) boxes_.push_back(boxOf(mesh));
  for (size_t k = 0; k < meshes.size(); ++k) {
    if (!meshes[k].vertices.empty()) order_.push_back(static_cast<int>(k));
  }
  nodes_ = buildMedianSplitTree(
      order_, [&](int i) { return std::array<Vec3, 2>{boxes_[i].lo, boxes_[i].hi}; },
      [&](int i, int axis) { return boxes_[i].lo[axis] + boxes_[i].hi[axis]; });
}

bool SweptBoxIndex::anyInTheWay(int mover, const Vec3& d, double tolerance,
                                const std::function<bool(int)>& visit) const {
  if (nodes_.empty()) return false;
  // A node's bounds hold its boxes: if they miss the region, so does each box (same comparisons).
  const Box region = sweptRegion(boxes_[static_cast<size_t>(mover)], d);
  std::vector<size_t> pending{0};
  while (!pending.empty()) {
    const SplitTreeNode& node = nodes_[pending.back()];
    pending.pop_back();
    if (!reachesInto(Box{node.lo, node.hi}, region, tolerance)) continue;
    if (node.children[0] == 0) {
      for (size_t r = node.begin; r < node.end; ++r) {
        const int q = order_[r];
        if (q != mover && reachesInto(boxes_[q], region, tolerance) && visit(q)) return true;
      }
      continue;
    }
    pending.push_back(node.children[0]);
    pending.push_back(node.children[1]);
  }
  return false;
}

}  // namespace desia
