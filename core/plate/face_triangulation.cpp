// SPDX-License-Identifier: GPL-3.0-or-later
// A planar face with holes as triangles: each hole joined to the outline by a bridge, then ear
// clipping. Clipper offers booleans and offsets but no triangulation, and Debian packages no C++
// triangulation library small enough for the WebAssembly build, hence these few lines.
#include "plate/face_triangulation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>

#include "analysis/vec3.h"
#include "desia/tolerances.h"

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
bool segmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d, double flat) {
  // Collinear up to `flat` (the rounding of the face's 2D frame) counts as collinear (a bridge
  // along a hole's edge meets it).
  auto side = [flat](double value) { return std::abs(value) <= flat ? 0.0 : value; };
  const double d1 = side(cross2(c, d, a)), d2 = side(cross2(c, d, b)), d3 = side(cross2(a, b, c)),
               d4 = side(cross2(a, b, d));
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) || (d3 == 0 && onSegment(a, b, c)) ||
         (d4 == 0 && onSegment(a, b, d));
}

// Does the direction from loop vertex `at` towards b start inside the region, which lies left of
// the loop's edges (outline counter-clockwise, holes clockwise)?
// With `strict`, a direction along either edge (up to rounding) does not count: a bridge along an
// edge would leave a flat corner that no triangle can take.
bool locallyInside(const std::vector<Point2>& points, const std::vector<int>& loop, size_t at, const Point2& b,
                   bool strict, double flat) {
  const Point2& p = points[loop[(at + loop.size() - 1) % loop.size()]];
  const Point2& o = points[loop[at]];
  const Point2& n = points[loop[(at + 1) % loop.size()]];
  const double least = strict ? flat : 0;
  const bool leftOfIn = cross2(p, o, b) > least || (!strict && cross2(p, o, b) == 0);
  const bool leftOfOut = cross2(o, n, b) > least || (!strict && cross2(o, n, b) == 0);
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
                 const Point2& to, double flat) {
  for (const std::vector<int>& loop : loops) {
    for (size_t e = 0; e < loop.size(); ++e) {
      const Point2& c = points[loop[e]];
      const Point2& d = points[loop[(e + 1) % loop.size()]];
      if (c == from || c == to || d == from || d == to) continue;
      if (segmentsMeet(from, to, c, d, flat)) return false;
    }
  }
  return insideLoops(points, loops, {(from[0] + to[0]) / 2, (from[1] + to[1]) / 2});
}

// The outline's vertices in order of distance from a point, ties in outline order, sorted only as
// far as they are asked for (the first is nearly always visible; an outline that has taken
// thousands of holes is long).
class NearestFirst {
 public:
  NearestFirst(const std::vector<Point2>& points, const std::vector<int>& outer, const Point2& from) {
    heap_.reserve(outer.size());
    for (size_t o = 0; o < outer.size(); ++o) {
      // By squared distance: sums and products only, the same bits natively and in WebAssembly
      // (std::hypot differs by an ulp between glibc and musl, which reorders near-ties).
      const double dx = points[outer[o]][0] - from[0], dy = points[outer[o]][1] - from[1];
      heap_.push_back({dx * dx + dy * dy, o});
    }
    std::make_heap(heap_.begin(), heap_.end(), std::greater<>());
  }

  // The k-th nearest (k below the outline's size).
  size_t at(size_t k) {
    while (sorted_.size() <= k) {
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
      sorted_.push_back(heap_.back().second);
      heap_.pop_back();
    }
    return sorted_[k];
  }

 private:
  std::vector<std::pair<double, size_t>> heap_;  // (distance, position): ties by position
  std::vector<size_t> sorted_;
};

// Joins each hole (clockwise) to the outline (counter-clockwise) by a two-way bridge from the
// hole's rightmost vertex to the nearest outline vertex it can see (no edge in the way, leaving
// both vertices into the region), giving one simple-in-effect polygon that ear clipping can cut.
std::vector<int> bridgeHoles(const std::vector<Point2>& points, std::vector<int> outer,
                             std::vector<std::vector<int>> holes, double flat) {
  const auto rightmostFirst = [&](const std::vector<int>& a, const std::vector<int>& b) {
    auto rightmost = [&](const std::vector<int>& h) {
      double x = -HUGE_VAL;
      for (int i : h) x = std::max(x, points[i][0]);
      return x;
    };
    return rightmost(a) > rightmost(b);
  };
  // Holes with the same rightmost x keep their order: std::sort orders ties differently in
  // libstdc++ and in Emscripten's libc++ (the BOOKCASE's rows of mortises exported other triangles
  // in WebAssembly).
  std::stable_sort(holes.begin(), holes.end(), rightmostFirst);
  for (size_t h = 0; h < holes.size(); ++h) {
    const std::vector<int>& hole = holes[h];
    size_t m = 0;
    for (size_t i = 1; i < hole.size(); ++i) {
      if (points[hole[i]][0] > points[hole[m]][0]) m = i;
    }
    const Point2& from = points[hole[m]];
    std::vector<std::vector<int>> loops{outer};
    loops.insert(loops.end(), holes.begin() + static_cast<long>(h), holes.end());
    NearestFirst candidates(points, outer, from);
    // The nearest visible vertex whose bridge runs along no edge at its ends (collinear holes'
    // edges: such a bridge would leave flat corners), else the nearest visible one.
    size_t best = candidates.at(0);
    bool found = false;
    for (bool strict : {true, false}) {
      if (strict && flat <= 0) continue;  // the plain triangulation (swept collisions) as it always was
      for (size_t k = 0; k < outer.size(); ++k) {
        const size_t o = candidates.at(k);
        const Point2& to = points[outer[o]];
        if (to == from) continue;
        if (locallyInside(points, outer, o, from, strict, flat) && locallyInside(points, hole, m, to, strict, flat) &&
            bridgeClear(points, loops, from, to, flat)) {
          best = o;
          found = true;
          break;
        }
      }
      if (found) break;
    }
    std::vector<int> merged(outer.begin(), outer.begin() + static_cast<long>(best) + 1);
    for (size_t k = 0; k <= hole.size(); ++k) merged.push_back(hole[(m + k) % hole.size()]);
    merged.insert(merged.end(), outer.begin() + static_cast<long>(best), outer.end());
    outer = merged;
  }
  return outer;
}

// Inside or on the border (up to rounding: a point on an edge, collinear up to the frame's
// rounding, is on it).
bool insideTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c, double flat) {
  return cross2(a, b, p) >= -flat && cross2(b, c, p) >= -flat && cross2(c, a, p) >= -flat;
}

// Ear clipping of a counter-clockwise polygon (bridges allowed: repeated points are skipped in the
// containment test). Appends triangles as index triples. The ear cut is always the first one in
// the polygon's order; what makes this near-quadratic instead of cubic is that a corner found not
// to be an ear keeps that verdict until it can change: a reflex or flat corner until a neighbour
// is cut away, a corner with a point inside until that point's corner is cut away. Only corners
// whose verdict may have changed are tested again (faces of a long table's top have a mortise per
// panel: thousands of corners).
class EarClipper {
 public:
  EarClipper(const std::vector<Point2>& points, const std::vector<int>& polygon, double flat)
      : points_(points), polygon_(polygon), flat_(flat), next_(polygon.size()), previous_(polygon.size()),
        blocker_(polygon.size(), kUntested), blocks_(polygon.size()) {
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
      next_[i] = (i + 1) % n;
      previous_[i] = (i + n - 1) % n;
      untested_.insert(i);
    }
    size_ = n;
  }

  void clip(std::vector<std::array<int, 3>>* triangles) {
    while (size_ > 3) {
      const size_t ear = firstEar();
      if (ear == kNone) {
        // Only flat or degenerate corners left (rounding): drop the flattest one without a triangle.
        remove(flattestCorner());
        continue;
      }
      triangles->push_back({point(previous_[ear]), point(ear), point(next_[ear])});
      remove(ear);
    }
    const size_t second = next_[head_], third = next_[second];
    if (size_ == 3 && cross2(at(head_), at(second), at(third)) > flat_) {
      triangles->push_back({point(head_), point(second), point(third)});
    }
  }

 private:
  static constexpr size_t kNone = static_cast<size_t>(-1);
  static constexpr size_t kUntested = static_cast<size_t>(-2);
  static constexpr size_t kNotConvex = static_cast<size_t>(-3);

  int point(size_t corner) const { return polygon_[corner]; }
  const Point2& at(size_t corner) const { return points_[static_cast<size_t>(polygon_[corner])]; }

  // The first corner in polygon order that is an ear; corners tested and found not to be are
  // remembered with the reason.
  size_t firstEar() {
    while (!untested_.empty()) {
      const size_t corner = *untested_.begin();
      untested_.erase(untested_.begin());
      const size_t reason = whyNotAnEar(corner);
      if (reason == kNone) {
        untested_.insert(corner);  // tested again if it is ever needed
        return corner;
      }
      blocker_[corner] = reason;
      if (reason != kNotConvex) blocks_[reason].push_back(corner);
    }
    return kNone;
  }

  // kNone for an ear, kNotConvex for a reflex or flat corner, else a corner whose point lies in
  // the triangle.
  size_t whyNotAnEar(size_t corner) const {
    const Point2& a = at(previous_[corner]);
    const Point2& b = at(corner);
    const Point2& c = at(next_[corner]);
    if (cross2(a, b, c) <= flat_) return kNotConvex;
    size_t other = head_;
    for (size_t k = 0; k < size_; ++k, other = next_[other]) {
      const Point2& p = at(other);
      if (p == a || p == b || p == c) continue;
      if (insideTriangle(p, a, b, c, flat_)) return other;
    }
    return kNone;
  }

  size_t flattestCorner() const {
    size_t flattest = head_;
    double smallest = HUGE_VAL;
    size_t corner = head_;
    for (size_t k = 0; k < size_; ++k, corner = next_[corner]) {
      const double area = std::abs(cross2(at(previous_[corner]), at(corner), at(next_[corner])));
      if (area < smallest) {
        smallest = area;
        flattest = corner;
      }
    }
    return flattest;
  }

  void retest(size_t corner) {
    blocker_[corner] = kUntested;
    untested_.insert(corner);
  }

  // Takes a corner out: its neighbours and the corners it blocked are tested again.
  void remove(size_t corner) {
    const size_t before = previous_[corner], after = next_[corner];
    next_[before] = after;
    previous_[after] = before;
    if (head_ == corner) head_ = after;
    --size_;
    untested_.erase(corner);
    retest(before);
    retest(after);
    for (size_t blocked : blocks_[corner]) {
      if (blocker_[blocked] == corner) retest(blocked);
    }
    blocks_[corner].clear();
  }

  const std::vector<Point2>& points_;
  const std::vector<int>& polygon_;
  const double flat_;
  std::vector<size_t> next_, previous_;
  std::vector<size_t> blocker_;              // why a corner is not an ear, while that holds
  std::vector<std::vector<size_t>> blocks_;  // the corners each corner's point was found in
  std::set<size_t> untested_;                // in polygon order, which is the order of the ears cut
  size_t head_ = 0;                          // the first corner left, in polygon order
  size_t size_ = 0;
};

void clipEars(const std::vector<Point2>& points, const std::vector<int>& polygon,
              std::vector<std::array<int, 3>>* triangles, double flat) {
  EarClipper(points, polygon, flat).clip(triangles);
}

}  // namespace

// Triangles of a planar face (loops[0] the outline, the rest holes) wound counter-clockwise about
// `outward`; the loops' vertices are mesh vertices first, first + 1, ... in loop order.
void addFaceTriangles(const std::vector<Loop>& loops, const Vec3& outward, int first, TriangleMesh* mesh, double flat) {
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
      bridgeHoles(points, indexLoops[0], std::vector<std::vector<int>>(indexLoops.begin() + 1, indexLoops.end()), flat);
  std::vector<std::array<int, 3>> triangles;
  clipEars(points, polygon, &triangles, flat);
  for (const auto& t : triangles) mesh->triangles.push_back({first + t[0], first + t[1], first + t[2]});
}

}  // namespace desia
