// SPDX-License-Identifier: GPL-3.0-or-later
// The boundary of a union of closed solids (issue 28 item 11: every exported part one solid), by
// binary space partitioning: each solid's triangles become a BSP tree whose leaves are its inside
// and its outside, and every other solid's polygons are passed down it, split where they cross a
// plane, and kept where they land outside. Iterative throughout (explicit stacks), deterministic
// (polygons in input order, no unordered containers).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "desia/model.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dotOf(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 crossOf(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// A plane n . x = offset, n a unit vector (a solid's outward normal where it comes from a face).
struct Plane {
  Vec3 normal;
  double offset;
  double distance(const Vec3& p) const { return dotOf(normal, p) - offset; }
};

struct Polygon {
  std::vector<Vec3> points;
  Plane plane;  // the plane of the triangle it comes from, facing out of its solid
};

// Points closer to a plane than this lie on it: the solids' vertices are computed apart (a tenon's
// corners some 1e-5 mm off its plate's), and later welded at the same distance.
constexpr double kOnPlane = tolerance::kMeshWeldMm;

enum Side : int { kOn = 0, kFront = 1, kBack = 2, kSpanning = 3 };

// Where a polygon lying on a node's plane goes: in front (outside) or behind (inside), by whether
// it faces the way the plane does. A union keeps a face lying on another solid's face facing the
// same way (it is on the union's boundary; the two merge later) and drops one facing against it
// (the solids touch there); a difference drops the face where the removed solid's face lies on it
// facing the same way (the cut takes it) and keeps it where they face each other.
struct CoplanarRule {
  bool sameFacingInFront = true;
  bool oppositeInFront = false;
};
constexpr CoplanarRule kUnionRule{true, false};
// The same for a face already kept by an earlier solid where it lies on it: one copy is enough.
constexpr CoplanarRule kUnionOnceRule{false, false};
constexpr CoplanarRule kCutRule{false, true};
// Faces of a removed solid are kept only strictly inside the solids they cut.
constexpr CoplanarRule kStrictlyInsideRule{true, true};

// The polygon split by the plane: parts in front and behind; a polygon on the plane goes where
// `rule` says.
void split(const Plane& plane, const Polygon& polygon, std::vector<Polygon>* front, std::vector<Polygon>* back,
           CoplanarRule rule = kUnionRule) {
  int whole = kOn;
  std::vector<int> sides(polygon.points.size());
  for (size_t i = 0; i < polygon.points.size(); ++i) {
    const double d = plane.distance(polygon.points[i]);
    sides[i] = d > kOnPlane ? kFront : d < -kOnPlane ? kBack : kOn;
    whole |= sides[i];
  }
  if (whole == kOn) {
    const bool same = dotOf(plane.normal, polygon.plane.normal) > 0;
    ((same ? rule.sameFacingInFront : rule.oppositeInFront) ? front : back)->push_back(polygon);
    return;
  }
  if (whole == kFront) return front->push_back(polygon);
  if (whole == kBack) return back->push_back(polygon);
  Polygon ahead{{}, polygon.plane}, behind{{}, polygon.plane};
  const size_t n = polygon.points.size();
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const Vec3& a = polygon.points[i];
    const Vec3& b = polygon.points[j];
    if (sides[i] != kBack) ahead.points.push_back(a);
    if (sides[i] != kFront) behind.points.push_back(a);
    if ((sides[i] | sides[j]) == kSpanning) {
      // The crossing point, from the end in front (the same point whichever way the edge runs).
      const Vec3& from = sides[i] == kFront ? a : b;
      const Vec3& to = sides[i] == kFront ? b : a;
      const double t = plane.distance(from) / (plane.distance(from) - plane.distance(to));
      const Vec3 crossing{from[0] + (to[0] - from[0]) * t, from[1] + (to[1] - from[1]) * t,
                          from[2] + (to[2] - from[2]) * t};
      ahead.points.push_back(crossing);
      behind.points.push_back(crossing);
    }
  }
  if (ahead.points.size() >= 3) front->push_back(std::move(ahead));
  if (behind.points.size() >= 3) back->push_back(std::move(behind));
}

struct Bounds {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  // Do the two boxes meet (touching counts: a face lying on a solid's face is cut by it)?
  bool meets(const Bounds& o) const {
    for (int k = 0; k < 3; ++k) {
      if (lo[k] > o.hi[k] + kOnPlane || o.lo[k] > hi[k] + kOnPlane) return false;
    }
    return true;
  }
};

Bounds boundsOf(const std::vector<Vec3>& points) {
  Bounds b;
  for (const Vec3& p : points) b.add(p);
  return b;
}

// A closed solid as a BSP tree: each node a plane of its faces, the solid's faces in front of it
// in the front subtree and behind it in the back one; past a leaf in front is outside, behind is
// inside (the faces are wound outward).
class SolidTree {
 public:
  explicit SolidTree(std::vector<Polygon> polygons) {
    for (const Polygon& polygon : polygons) {
      for (const Vec3& p : polygon.points) bounds_.add(p);
    }
    if (polygons.empty()) return;
    // Nodes to build: (node, the polygons that fall to it).
    std::vector<std::pair<int, std::vector<Polygon>>> pending;
    nodes_.push_back({polygons[0].plane, -1, -1});
    pending.push_back({0, std::move(polygons)});
    while (!pending.empty()) {
      auto [node, list] = std::move(pending.back());
      pending.pop_back();
      const Plane plane = list[0].plane;
      nodes_[static_cast<size_t>(node)].plane = plane;
      std::vector<Polygon> front, back, coplanarFront, coplanarBack;
      for (const Polygon& polygon : list) {
        std::vector<Polygon> ahead, behind;
        split(plane, polygon, &ahead, &behind);
        // Polygons on the node's plane belong to the node (either way they face).
        for (Polygon& p : ahead) (onPlane(plane, p) ? coplanarFront : front).push_back(std::move(p));
        for (Polygon& p : behind) (onPlane(plane, p) ? coplanarBack : back).push_back(std::move(p));
      }
      if (!front.empty()) {
        nodes_[static_cast<size_t>(node)].front = static_cast<int>(nodes_.size());
        nodes_.push_back({front[0].plane, -1, -1});
        pending.push_back({nodes_[static_cast<size_t>(node)].front, std::move(front)});
      }
      if (!back.empty()) {
        nodes_[static_cast<size_t>(node)].back = static_cast<int>(nodes_.size());
        nodes_.push_back({back[0].plane, -1, -1});
        pending.push_back({nodes_[static_cast<size_t>(node)].back, std::move(back)});
      }
    }
  }

  const Bounds& bounds() const { return bounds_; }

  // The parts of the polygon outside the solid (`inside` false) or inside it (true), those on its
  // faces sorted by `rule`, appended.
  void keep(const Polygon& polygon, std::vector<Polygon>* kept, CoplanarRule rule = kUnionRule,
            bool inside = false) const {
    if (nodes_.empty() || !bounds_.meets(boundsOf(polygon.points))) {
      if (!inside) kept->push_back(polygon);
      return;
    }
    std::vector<std::pair<int, Polygon>> pending{{0, polygon}};
    std::vector<std::pair<int, Polygon>> later;
    while (!pending.empty()) {
      auto [node, part] = std::move(pending.back());
      pending.pop_back();
      const Node& at = nodes_[static_cast<size_t>(node)];
      std::vector<Polygon> front, back;
      split(at.plane, part, &front, &back, rule);
      // Pushed back first so that the front parts come out first: the order of the output follows
      // the tree, the same on every platform.
      for (Polygon& p : back) {
        if (at.back >= 0) later.push_back({at.back, std::move(p)});
        else if (inside) kept->push_back(std::move(p));
      }
      for (Polygon& p : front) {
        if (at.front >= 0) later.push_back({at.front, std::move(p)});
        else if (!inside) kept->push_back(std::move(p));
      }
      for (auto it = later.rbegin(); it != later.rend(); ++it) pending.push_back(std::move(*it));
      later.clear();
    }
  }

 private:
  struct Node {
    Plane plane;
    int front, back;
  };
  static bool onPlane(const Plane& plane, const Polygon& polygon) {
    for (const Vec3& p : polygon.points) {
      if (std::abs(plane.distance(p)) > kOnPlane) return false;
    }
    return true;
  }
  std::vector<Node> nodes_;
  Bounds bounds_;
};

std::vector<Polygon> polygonsOf(const TriangleMesh& mesh) {
  std::vector<Polygon> polygons;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<size_t>(t[2])];
    Vec3 n = crossOf(sub(b, a), sub(c, a));
    const double length = std::sqrt(dotOf(n, n));
    if (length <= tolerance::kDegenerateTriangleTwiceAreaMm2) continue;  // no plane, no area
    for (double& x : n) x /= length;
    polygons.push_back({{a, b, c}, {n, dotOf(n, a)}});
  }
  return polygons;
}

}  // namespace

std::vector<BoundaryPolygon> booleanBoundaryPolygons(const std::vector<TriangleMesh>& solids,
                                                     const std::vector<TriangleMesh>& removed) {
  std::vector<std::vector<Polygon>> polygons, cuts;
  std::vector<SolidTree> trees, cutTrees;
  for (const TriangleMesh& solid : solids) {
    polygons.push_back(polygonsOf(solid));
    trees.emplace_back(polygons.back());
  }
  for (const TriangleMesh& solid : removed) {
    cuts.push_back(polygonsOf(solid));
    cutTrees.emplace_back(cuts.back());
  }
  std::vector<BoundaryPolygon> boundary;
  // Each solid's faces outside the other solids and outside every removed solid.
  for (size_t i = 0; i < solids.size(); ++i) {
    std::vector<Polygon> left = polygons[i];
    for (size_t j = 0; j < solids.size() + removed.size(); ++j) {
      if (j == i) continue;
      std::vector<Polygon> outside;
      for (const Polygon& polygon : left) {
        if (j < solids.size()) trees[j].keep(polygon, &outside, j < i ? kUnionOnceRule : kUnionRule);
        else cutTrees[j - solids.size()].keep(polygon, &outside, kCutRule);
      }
      left = std::move(outside);
    }
    for (Polygon& polygon : left) boundary.push_back({std::move(polygon.points), polygon.plane.normal, static_cast<int>(i)});
  }
  // Each removed solid's faces inside some solid (outside the others kept before: no part twice),
  // outside the other removed solids, turned to face out of what is left.
  for (size_t k = 0; k < removed.size(); ++k) {
    std::vector<Polygon> inUnion;
    for (const Polygon& polygon : cuts[k]) {
      std::vector<Polygon> rest{polygon};
      for (size_t i = 0; i < solids.size() && !rest.empty(); ++i) {
        std::vector<Polygon> outside;
        for (const Polygon& part : rest) {
          trees[i].keep(part, &inUnion, kStrictlyInsideRule, true);
          trees[i].keep(part, &outside, kStrictlyInsideRule, false);
        }
        rest = std::move(outside);
      }
    }
    for (size_t other = 0; other < removed.size(); ++other) {
      if (other == k) continue;
      std::vector<Polygon> outside;
      for (const Polygon& polygon : inUnion) cutTrees[other].keep(polygon, &outside, kUnionRule);
      inUnion = std::move(outside);
    }
    for (Polygon& polygon : inUnion) {
      std::reverse(polygon.points.begin(), polygon.points.end());
      const Vec3 n = polygon.plane.normal;
      boundary.push_back({std::move(polygon.points), {-n[0], -n[1], -n[2]}, static_cast<int>(solids.size() + k)});
    }
  }
  return boundary;
}

std::vector<BoundaryPolygon> unionBoundaryPolygons(const std::vector<TriangleMesh>& solids) {
  return booleanBoundaryPolygons(solids, {});
}

}  // namespace desia
