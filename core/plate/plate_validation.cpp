// SPDX-License-Identifier: GPL-3.0-or-later
// Plates checked as they are read (validatePlates): planar faces, a positive thickness, matching
// faces, loops that do not cross themselves, holes inside the outline.
#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

using geometry::centroidOf;
using geometry::maxDistanceToPlane;
using geometry::millimetres;
using geometry::plateName;
using geometry::preciseMillimetres;

void requirePlanar(const Plate& plate, const std::vector<Loop>& loops, const char* which, double tolerance,
                   const std::string& source) {
  const Vec3 n = loopNormal(loops[0]);
  if (norm(n) < tolerance::kNoTwiceAreaMm2)
    throwBadInput(source, plateName(plate) + ": its " + which + " face has no area");
  const PlaneFrame frame(centroidOf(loops[0]), n);
  for (size_t l = 0; l < loops.size(); ++l) {
    for (size_t i = 0; i < loops[l].size(); ++i) {
      const double off = std::abs(dot(minus(loops[l][i], frame.origin), frame.normal));
      if (off > tolerance) {
        throwBadInput(source, plateName(plate) + ": its " + which + " face is not planar: vertex " +
                                  std::to_string(i + 1) + (l ? " of hole " + std::to_string(l) : std::string()) +
                                  " is " + millimetres(off) + " off the face's plane (tolerance " +
                                  millimetres(tolerance) + ")");
      }
    }
  }
}

// Proper crossings or touchings of two non-adjacent edges of a loop, in the loop's plane.
void requireSimpleLoop(const Plate& plate, const Loop& loop, size_t loopIndex, const std::string& source) {
  const PlaneFrame frame(centroidOf(loop), loopNormal(loop));
  std::vector<std::array<double, 2>> p;
  for (const Vec3& q : loop) p.push_back({dot(minus(q, frame.origin), frame.u), dot(minus(q, frame.origin), frame.v)});
  // Which side of a-b the point c lies on; within rounding of the lengths involved, on it (edges
  // along one line, as the wood beside a mitre tenon's pocket, must not count as crossing).
  auto orient = [&](size_t a, size_t b, size_t c) {
    const double bx = p[b][0] - p[a][0], by = p[b][1] - p[a][1], cx = p[c][0] - p[a][0], cy = p[c][1] - p[a][1];
    const double value = bx * cy - by * cx;
    const double rounding = tolerance::kProductRounding * std::hypot(bx, by) * std::hypot(cx, cy);
    return value > rounding ? 1 : (value < -rounding ? -1 : 0);
  };
  const size_t n = p.size();
  const auto crosses = [&](size_t i, size_t j) {  // edges i and j (i < j), not adjacent
    const size_t i2 = (i + 1) % n, j2 = (j + 1) % n;
    if (i2 == j || j2 == i) return false;  // adjacent edges share a vertex
    const int o1 = orient(i, i2, j), o2 = orient(i, i2, j2), o3 = orient(j, j2, i), o4 = orient(j, j2, i2);
    return o1 * o2 <= 0 && o3 * o4 <= 0 && !(o1 == 0 && o2 == 0);
  };
  // Only edges whose spans along u overlap can meet: the edges sorted by where they start along u,
  // each compared with those still open there (a sweep: comparing every pair is quadratic, seconds
  // on an outline of tens of thousands of vertices). The first crossing pair in edge order is
  // named.
  std::vector<size_t> byStart(n);
  std::vector<double> low(n), high(n);
  for (size_t k = 0; k < n; ++k) {
    byStart[k] = k;
    low[k] = std::min(p[k][0], p[(k + 1) % n][0]);
    high[k] = std::max(p[k][0], p[(k + 1) % n][0]);
  }
  std::sort(byStart.begin(), byStart.end(), [&](size_t a, size_t b) { return low[a] < low[b] || (low[a] == low[b] && a < b); });
  std::vector<size_t> open;
  std::pair<size_t, size_t> first{n, n};
  for (size_t edge : byStart) {
    open.erase(std::remove_if(open.begin(), open.end(), [&](size_t other) { return high[other] < low[edge]; }), open.end());
    for (size_t other : open) {
      const std::pair<size_t, size_t> pair{std::min(edge, other), std::max(edge, other)};
      if (pair < first && crosses(pair.first, pair.second)) first = pair;
    }
    open.push_back(edge);
  }
  if (first.first < n) {
    const size_t i = first.first, j = first.second;
    throwBadInput(source, plateName(plate) + ": its " +
                              (loopIndex ? "hole " + std::to_string(loopIndex) : std::string("outline")) +
                              " crosses itself: edge " + std::to_string(i + 1) + "-" + std::to_string((i + 1) % n + 1) +
                              " meets edge " + std::to_string(j + 1) + "-" + std::to_string((j + 1) % n + 1));
  }
}

double clipperArea(const ClipperLib::Paths& paths) {
  double area = 0;
  for (const ClipperLib::Path& path : paths) area += ClipperLib::Area(path);
  return std::abs(area) / (kClipperScale * kClipperScale);
}

ClipperLib::Paths grownBy(const ClipperLib::Paths& paths, double millimetres) {
  ClipperLib::ClipperOffset offset;
  offset.AddPaths(paths, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths grown;
  offset.Execute(grown, millimetres * kClipperScale);
  return grown;
}

ClipperLib::Paths clipped(const ClipperLib::Paths& a, const ClipperLib::Paths& b, ClipperLib::ClipType operation) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(a, ClipperLib::ptSubject, true);
  clipper.AddPaths(b, ClipperLib::ptClip, true);
  ClipperLib::Paths result;
  clipper.Execute(operation, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return result;
}

// A plate's holes (loops 1.. of its first face) must each have an area, lie inside its outline
// without touching it, and neither overlap nor touch each other (within the tolerance): else the
// cut files would make an extra piece, a tab or a loose island, and the meshes would not close.
// Clipper's booleans keep this O(n log n) in the vertices.
void requireHolesInside(const Plate& plate, double tolerance, const std::string& source) {
  if (plate.bottom.size() < 2) return;
  const PlaneFrame frame(centroidOf(plate.bottom[0]), loopNormal(plate.bottom[0]));
  const ClipperLib::Paths outline{clipperPath(plate.bottom[0], frame)};
  const double sliver = tolerance::kEmptyAreaMm2;
  std::vector<ClipperLib::Paths> holes;
  double separateArea = 0;
  for (size_t h = 1; h < plate.bottom.size(); ++h) {
    const std::string hole = plateName(plate) + ": hole " + std::to_string(h);
    ClipperLib::Paths path{clipperPath(plate.bottom[h], frame)};
    if (clipperArea(path) <= tolerance * tolerance) throwBadInput(source, hole + " has no area");
    const ClipperLib::Paths grown = grownBy(path, tolerance / 2);
    if (clipperArea(clipped(grown, outline, ClipperLib::ctDifference)) > sliver) {
      throwBadInput(source, hole + " is not inside the plate's outline (it crosses or touches it, or lies outside)");
    }
    separateArea += clipperArea(grown);
    holes.push_back(grown);
  }
  ClipperLib::Paths all;
  for (const ClipperLib::Paths& hole : holes) all.insert(all.end(), hole.begin(), hole.end());
  ClipperLib::Clipper clipper;
  clipper.AddPaths(all, ClipperLib::ptSubject, true);
  ClipperLib::Paths united;
  clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  if (clipperArea(united) + sliver * static_cast<double>(holes.size()) >= separateArea) return;
  for (size_t a = 0; a < holes.size(); ++a) {  // only when some overlap: name the first pair
    for (size_t b = a + 1; b < holes.size(); ++b) {
      if (clipperArea(clipped(holes[a], holes[b], ClipperLib::ctIntersection)) > sliver) {
        throwBadInput(source, plateName(plate) + ": holes " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                                  " overlap or touch");
      }
    }
  }
}

void validatePlate(const Plate& plate, double tolerance, const std::string& source) {
  if (plate.bottom.empty() || plate.bottom.size() != plate.top.size()) {
    throwBadInput(source, plateName(plate) + ": its two faces have different numbers of loops");
  }
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    if (plate.bottom[l].size() < 3) throwBadInput(source, plateName(plate) + ": a face loop needs at least 3 vertices");
    if (plate.bottom[l].size() != plate.top[l].size()) {
      throwBadInput(source, plateName(plate) + ": its faces do not match: " + std::to_string(plate.bottom[l].size()) +
                                " and " + std::to_string(plate.top[l].size()) + " vertices");
    }
  }
  requirePlanar(plate, plate.bottom, "first", tolerance, source);
  requirePlanar(plate, plate.top, "second", tolerance, source);
  for (size_t l = 0; l < plate.bottom.size(); ++l) requireSimpleLoop(plate, plate.bottom[l], l, source);
  requireHolesInside(plate, tolerance, source);
  // Parallel faces a positive distance apart: every vertex of the second face at the same height
  // above the first face's plane.
  const PlaneFrame bottom(centroidOf(plate.bottom[0]), loopNormal(plate.bottom[0]));
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Loop& loop : plate.top) {
    for (const Vec3& p : loop) {
      const double h = dot(minus(p, bottom.origin), bottom.normal);
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  }
  if (hi - lo > tolerance) {
    throwBadInput(source, plateName(plate) + ": its faces are not parallel: the second face's vertices are " +
                              preciseMillimetres(lo) + " to " + preciseMillimetres(hi) +
                              " from the first face's plane, more than the contact tolerance (" +
                              preciseMillimetres(tolerance) + ") apart");
  }
  if (std::abs(lo) <= tolerance) {
    throwBadInput(source, plateName(plate) + ": its thickness (" + preciseMillimetres(std::abs(lo)) +
                              ") is not more than the contact tolerance (" + preciseMillimetres(tolerance) +
                              "); coordinates are millimetres unless the document gives \"unit\" (\"cm\", \"m\" or \"in\")");
  }
  // Every side face (one per edge) must be planar: the faces match vertex for vertex.
  const Vec3 axis = plateThicknessAxis(plate);
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& b = plate.bottom[l];
    const Loop& t = plate.top[l];
    for (size_t k = 0; k < b.size(); ++k) {
      const size_t next = (k + 1) % b.size();
      const Loop quad{b[k], b[next], t[next], t[k]};
      const double off = maxDistanceToPlane({quad}, PlaneFrame(centroidOf(quad), loopNormal(quad)));
      if (off > tolerance || dot(minus(t[k], b[k]), axis) <= 0) {
        throwBadInput(source, plateName(plate) + ": its faces do not match: the side between vertices " +
                                  std::to_string(k + 1) + " and " + std::to_string(next + 1) + " is twisted by " +
                                  millimetres(off));
      }
    }
  }
}

}  // namespace

void validatePlates(const std::vector<Plate>& plates, const PlateOptions& options, const std::string& source) {
  if (!(options.contactTolerance > 0) || !std::isfinite(options.contactTolerance)) {
    throwBadInput(source, "the contact tolerance must be a positive number of millimetres");
  }
  for (const Plate& plate : plates) {
    validatePlate(plate, options.contactTolerance, source);
    for (const Plate& solid : plate.attached) {
      if (!solid.attached.empty()) throwBadInput(source, plateName(plate) + ": an attached solid has attachments of its own");
      Plate named = solid;
      named.id = plate.id;
      named.name = (plate.name.empty() ? "" : plate.name + ", ") + "attached solid";
      validatePlate(named, options.contactTolerance, source);
    }
  }
}

}  // namespace desia
