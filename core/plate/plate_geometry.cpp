// SPDX-License-Identifier: GPL-3.0-or-later
// Plate geometry (paper Section 5.2): validation, faces of the plate solids, and the contacts
// between plates found where faces lie on one another. The overlap of two coplanar faces is a 2D
// polygon intersection, done by Clipper (Angus Johnson's library, Debian's libpolyclipping) on
// integer coordinates, exact and the same natively and in WebAssembly.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/cut_points.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "plate/normal_classes.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {


Vec3 centroidOf(const Loop& loop) {
  Vec3 c{0, 0, 0};
  for (const Vec3& p : loop) c = plus(c, p);
  return scaled(c, 1.0 / static_cast<double>(loop.size()));
}

std::string plateName(const Plate& plate) {
  return "plate " + std::to_string(plate.id) + (plate.name.empty() ? "" : " (" + plate.name + ")");
}

std::string millimetres(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value << " mm";
  return out.str();
}

// Enough digits to tell apart values that differ by more than a micrometre.
std::string preciseMillimetres(double value) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(std::abs(value) < 1 ? 6 : 4);
  out << value << " mm";
  return out.str();
}

// One planar face of a plate solid: its loops (outline and holes, or one side quad) and its
// outward unit normal.
struct SolidFace {
  std::vector<Loop> loops;
  Vec3 normal;
};

}  // namespace

Vec3 loopNormal(const Loop& loop) {
  Vec3 n{0, 0, 0};
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& p = loop[i];
    const Vec3& q = loop[(i + 1) % loop.size()];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

Vec3 plateThicknessAxis(const Plate& plate) {
  Vec3 n = normalized(loopNormal(plate.bottom[0]));
  if (dot(n, minus(centroidOf(plate.top[0]), centroidOf(plate.bottom[0]))) < 0) n = negated(n);
  return n;
}

namespace {

Vec3 thicknessAxis(const Plate& plate) { return plateThicknessAxis(plate); }

// Even-odd test of a point of the bottom face's plane against all its loops (outline and holes).
bool insideBottomFace(const Plate& plate, const PlaneFrame& frame, const Vec3& point) {
  const double px = dot(minus(point, frame.origin), frame.u), py = dot(minus(point, frame.origin), frame.v);
  bool inside = false;
  for (const Loop& loop : plate.bottom) {
    for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const double xi = dot(minus(loop[i], frame.origin), frame.u), yi = dot(minus(loop[i], frame.origin), frame.v);
      const double xj = dot(minus(loop[j], frame.origin), frame.u), yj = dot(minus(loop[j], frame.origin), frame.v);
      if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) inside = !inside;
    }
  }
  return inside;
}

}  // namespace

// A side face's normal points out of the solid: a step from the middle of its bottom edge along
// the normal (projected into the bottom plane) must leave the bottom face. Loop orientation and
// holes need no separate rules this way. The quads of one loop all turn the same way about it,
// so the step is taken once per loop, from its longest edge: a step per edge made this quadratic
// (each a point-in-polygon test; a 30,000-vertex outline: 1.8 s of a 2 s check).
std::vector<Vec3> plateSideNormals(const Plate& plate, size_t loopIndex) {
  const Vec3 axis = plateThicknessAxis(plate);
  const Loop& bottom = plate.bottom[loopIndex];
  const Loop& top = plate.top[loopIndex];
  std::vector<Vec3> normals;
  size_t longest = 0;
  for (size_t k = 0; k < bottom.size(); ++k) {
    const size_t next = (k + 1) % bottom.size();
    normals.push_back(normalized(loopNormal(Loop{bottom[k], bottom[next], top[next], top[k]})));
    if (norm(minus(bottom[next], bottom[k])) >
        norm(minus(bottom[(longest + 1) % bottom.size()], bottom[longest])))
      longest = k;
  }
  if (normals.empty()) return normals;
  const PlaneFrame bottomFrame(centroidOf(plate.bottom[0]), axis);
  constexpr double kStep = 1e-3;  // mm
  const Vec3& n = normals[longest];
  const Vec3 inPlane = normalized(minus(n, scaled(axis, dot(n, axis))));
  const Vec3 middle = scaled(plus(bottom[longest], bottom[(longest + 1) % bottom.size()]), 0.5);
  if (insideBottomFace(plate, bottomFrame, plus(middle, scaled(inPlane, kStep)))) {
    for (Vec3& normal : normals) normal = negated(normal);
  }
  return normals;
}

namespace {

std::vector<SolidFace> solidFaces(const Plate& plate) {
  const Vec3 axis = thicknessAxis(plate);
  std::vector<SolidFace> faces{{plate.bottom, negated(axis)}, {plate.top, axis}};
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& bottom = plate.bottom[l];
    const Loop& top = plate.top[l];
    const std::vector<Vec3> normals = plateSideNormals(plate, l);
    for (size_t k = 0; k < bottom.size(); ++k) {
      const size_t next = (k + 1) % bottom.size();
      faces.push_back({{Loop{bottom[k], bottom[next], top[next], top[k]}}, normals[k]});
    }
  }
  return faces;
}

double maxDistanceToPlane(const std::vector<Loop>& loops, const PlaneFrame& frame) {
  double worst = 0;
  for (const Loop& loop : loops) {
    for (const Vec3& p : loop) worst = std::max(worst, std::abs(dot(minus(p, frame.origin), frame.normal)));
  }
  return worst;
}

struct Box {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  bool touches(const Box& o, double tolerance) const {
    for (int k = 0; k < 3; ++k) {
      if (lo[k] > o.hi[k] + tolerance || o.lo[k] > hi[k] + tolerance) return false;
    }
    return true;
  }
};

Box boxOf(const Plate& plate) {
  Box box;
  for (const auto* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      for (const Vec3& p : loop) box.add(p);
    }
  }
  return box;
}

// --- validation --------------------------------------------------------------------------------

void requirePlanar(const Plate& plate, const std::vector<Loop>& loops, const char* which, double tolerance,
                   const std::string& source) {
  const Vec3 n = loopNormal(loops[0]);
  if (norm(n) < 1e-12) throwBadInput(source, plateName(plate) + ": its " + which + " face has no area");
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
    const double rounding = 1e-12 * std::hypot(bx, by) * std::hypot(cx, cy);
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
  // each compared with those still open there (a sweep; a 30,000-vertex outline took 19.7 s by
  // comparing every pair). The first crossing pair in edge order is named, as before.
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
  const double sliver = 1e-6;  // mm^2
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
  const Vec3 axis = thicknessAxis(plate);
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

namespace {

// The part of `plate`'s face inside the slab of `other` (between its faces), as Clipper paths in
// `frame` (the plate's first face plane).
ClipperLib::Paths insideSlab(const Plate& plate, const PlaneFrame& frame, const Vec3& point, const Vec3& line,
                             const Vec3& across, double width, double reach, double tolerance) {
  // The slab's inside, a tolerance in from each face: a hole as wide as the slab (a mortise) then
  // splits the region, and a face lying on the slab's face adds nothing.
  const Vec3 low = plus(point, scaled(across, tolerance)), high = plus(point, scaled(across, width - tolerance));
  const Loop strip{plus(low, scaled(line, -reach)), plus(low, scaled(line, reach)), plus(high, scaled(line, reach)),
                   plus(high, scaled(line, -reach))};
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(plate.bottom, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths({strip}, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths inside;
  clipper.Execute(ClipperLib::ctIntersection, inside, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
  return inside;
}

double pathsArea(const ClipperLib::Paths& paths) {
  double area = 0;
  for (const ClipperLib::Path& path : paths) area += ClipperLib::Area(path);
  return std::abs(area) / (kClipperScale * kClipperScale);
}

// Where along `line` (from `point`) the region has material: each outer path's extent (a connected
// piece covers every position between its ends), merged.
std::vector<std::pair<double, double>> shadowOnLine(const ClipperLib::Paths& paths, const PlaneFrame& frame,
                                                    const Vec3& point, const Vec3& line) {
  std::vector<std::pair<double, double>> spans;
  for (const ClipperLib::Path& path : paths) {
    if (!ClipperLib::Orientation(path)) continue;  // a hole: its piece's ends are its outline's
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const ClipperLib::IntPoint& q : path) {
      const double t = dot(minus(frame.fromClipper(q), point), line);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    spans.push_back({lo, hi});
  }
  std::sort(spans.begin(), spans.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& span : spans) {
    if (!merged.empty() && span.first <= merged.back().second)
      merged.back().second = std::max(merged.back().second, span.second);
    else
      merged.push_back(span);
  }
  return merged;
}

// The stretches where both shadows have material, longer than the tolerance.
std::vector<std::pair<double, double>> commonStretches(const std::vector<std::pair<double, double>>& x,
                                                       const std::vector<std::pair<double, double>>& y,
                                                       double tolerance) {
  std::vector<std::pair<double, double>> common;
  for (const auto& [x0, x1] : x) {
    for (const auto& [y0, y1] : y) {
      const double from = std::max(x0, y0), to = std::min(x1, y1);
      if (to - from > tolerance) common.push_back({from, to});
    }
  }
  return common;
}

std::optional<PlateContact> plateCrossing(const std::vector<Plate>& plates, int p, int q, double tolerance);

// Perpendicular plates of which one or both have mitred sides cannot cross (halved joints need
// plates of their whole thickness), so they must not share volume at all: judged by their core
// prisms (where they have their whole thickness, corePrism), which lie inside them. A refusal is
// always a real overlap; one within the mitres alone can pass (the design's swept check finds it).
void requireMitredPerpendicularApart(const Plate& a, const Plate& b, double tolerance) {
  if (std::abs(dot(plateThicknessAxis(a), plateThicknessAxis(b))) > 1e-6 || (isPrism(a) && isPrism(b))) return;
  const std::vector<Plate> cores{corePrism(a), corePrism(b)};
  if (cores[0].bottom.empty() || cores[1].bottom.empty()) return;
  bool overlap = false;
  try {
    overlap = plateCrossing(cores, 0, 1, tolerance).has_value();
  } catch (const Error&) {
    overlap = true;  // a partial overlap of the cores
  }
  if (overlap) {
    throwBadInput("", plateName(a) + " and " + plateName(b) +
                          " overlap where no contact explains it (perpendicular plates with mitred sides cannot "
                          "cross through each other): move them apart until they touch");
  }
}

// Plates p and q crossing through each other: perpendicular prisms whose faces each fill the other's
// slab over a common stretch of the line where their planes meet. A partial overlap is refused.
std::optional<PlateContact> plateCrossing(const std::vector<Plate>& plates, int p, int q, double tolerance) {
  const Plate& a = plates[p];
  const Plate& b = plates[q];
  const Vec3 ta = plateThicknessAxis(a), tb = plateThicknessAxis(b);
  if (std::abs(dot(ta, tb)) > 1e-6) return std::nullopt;
  const double ha = plateThickness(a), hb = plateThickness(b);
  if (!isPrism(a) || !isPrism(b)) return std::nullopt;  // requireMitredPerpendicularApart judges them
  const Vec3 line = canonicalSign(normalized(cross(ta, tb)));
  // On both first faces: the planes' common line, with (ta, tb, line) orthonormal.
  const Vec3 point = plus(scaled(ta, dot(a.bottom[0][0], ta)), scaled(tb, dot(b.bottom[0][0], tb)));
  const Box boxA = boxOf(a), boxB = boxOf(b);
  double reach = 0;
  for (int k = 0; k < 3; ++k)
    reach += std::max(boxA.hi[k], boxB.hi[k]) - std::min(boxA.lo[k], boxB.lo[k]) + std::abs(point[k]);
  const PlaneFrame frameA(a.bottom[0][0], ta), frameB(b.bottom[0][0], tb);
  const ClipperLib::Paths inA =
      insideSlab(a, frameA, point, line, tb, hb, reach, tolerance);  // a's material in b's slab
  const ClipperLib::Paths inB = insideSlab(b, frameB, point, line, ta, ha, reach, tolerance);
  if (pathsArea(inA) <= tolerance * tolerance || pathsArea(inB) <= tolerance * tolerance) return std::nullopt;
  // A point at `t` along the line is in both plates when each has material in the other's slab
  // there: the plates meet where their shadows on the line overlap (a tenon in its mortise: never).
  const std::vector<std::pair<double, double>> shadowA = shadowOnLine(inA, frameA, point, line);
  const std::vector<std::pair<double, double>> shadowB = shadowOnLine(inB, frameB, point, line);
  const std::vector<std::pair<double, double>> common = commonStretches(shadowA, shadowB, tolerance);

  if (common.empty()) return std::nullopt;
  if (common.size() > 1) {
    throwBadInput(
        "", plateName(a) + " and " + plateName(b) + " overlap in " + std::to_string(common.size()) +
                " places: make them cross through once (each filling the other's thickness) or meet face to face");
  }
  const double from = common[0].first, to = common[0].second;
  const double a0 = shadowA.front().first, a1 = shadowA.back().second, b0 = shadowB.front().first,
               b1 = shadowB.back().second;
  // Crossing through: over [from, to] each plate's material fills the other's whole thickness.
  auto band = [&](const Vec3& across, double width) {
    const Vec3 low = plus(point, scaled(across, tolerance)), high = plus(point, scaled(across, width - tolerance));
    return Loop{plus(low, scaled(line, from)), plus(low, scaled(line, to)), plus(high, scaled(line, to)),
                plus(high, scaled(line, from))};
  };
  const Loop bandA = band(tb, hb), bandB = band(ta, ha);
  auto filled = [&](const Plate& plate, const PlaneFrame& frame, const Loop& band, double width) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(clipperPaths(plate.bottom, frame), ClipperLib::ptSubject, true);
    clipper.AddPaths(clipperPaths({band}, frame), ClipperLib::ptClip, true);
    ClipperLib::Paths inside;
    clipper.Execute(ClipperLib::ctIntersection, inside, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
    return std::abs(pathsArea(inside) - (width - 2 * tolerance) * (to - from)) <= tolerance * (to - from + width);
  };
  if (!filled(a, frameA, bandA, hb) || !filled(b, frameB, bandB, ha)) {
    throwBadInput("", plateName(a) + " and " + plateName(b) +
                          " overlap without passing through each other: make them cross "
                          "through (each filling the other's thickness) or meet face to face");
  }
  PlateContact crossing;
  crossing.a = p;
  crossing.b = q;
  crossing.crossing = true;
  crossing.edgeDirection = line;
  crossing.crossingPoint = point;
  crossing.crossingFrom = from;
  crossing.crossingTo = to;
  crossing.area = (to - from) * std::max(ha, hb);
  // A slot opens where the plate's material in the other's slab ends with the crossing.
  crossing.aOpens = {a0 >= from - tolerance, a1 <= to + tolerance};
  crossing.bOpens = {b0 >= from - tolerance, b1 <= to + tolerance};
  return crossing;
}

// Two plates that are neither parallel-and-apart nor perpendicular (those are crossings) must not
// share volume: sliced by planes parallel to the first plate's faces (a quarter, half and three
// quarters of the way through it), the second plate's section must not overlap the first's face by
// more than a sliver of the tolerance's width. A plate with mitred sides is judged by its core
// prism (where it has its whole thickness, corePrism), which lies inside it. A refusal is always a
// real overlap; an overlap thinner than a quarter of the first plate's thickness between the
// slices, or within the mitres, can pass (the design's swept check still finds it).
void requireNoSlantedOverlap(const Plate& plateA, const Plate& plateB, double tolerance) {
  const Vec3 ta = plateThicknessAxis(plateA), tb = plateThicknessAxis(plateB);
  const double cosine = dot(ta, tb);
  if (std::abs(cosine) < 1e-6) return;  // perpendicular: computePlateContacts' crossings
  const Plate a = corePrism(plateA), b = corePrism(plateB);
  if (a.bottom.empty() || b.bottom.empty()) return;
  const double ha = plateThickness(plateA), hb = plateThickness(plateB);
  const Box boxA = boxOf(a), boxB = boxOf(b);
  double reach = 0;
  for (int k = 0; k < 3; ++k) reach += std::max(boxA.hi[k], boxB.hi[k]) - std::min(boxA.lo[k], boxB.lo[k]);
  const bool parallel = std::abs(cosine) > 1 - 1e-9;
  const Vec3 along = parallel ? Vec3{0, 0, 0} : normalized(cross(ta, tb));       // in the slice, across tb
  const Vec3 towards = parallel ? Vec3{0, 0, 0} : normalized(cross(along, ta));  // in the slice, along tb's shadow
  for (double fraction : {0.25, 0.5, 0.75}) {
    const Vec3 origin = plus(a.bottom[0][0], scaled(ta, fraction * ha));
    const PlaneFrame frame(origin, ta);
    const double level = dot(minus(origin, b.bottom[0][0]), tb);  // b's height at the slice's origin
    ClipperLib::Paths section;  // b's section by the slice, in the slice's frame
    for (const Loop& loop : b.bottom) {
      // A point v of b's first face rises along tb to the slice at s = dot(origin - v, ta) / cosine.
      ClipperLib::Path path;
      for (const Vec3& v : loop) path.push_back(frame.toClipper(plus(v, scaled(tb, dot(minus(origin, v), ta) / cosine))));
      section.push_back(path);
    }
    ClipperLib::Clipper clipper;
    clipper.AddPaths(clipperPaths(a.bottom, frame), ClipperLib::ptSubject, true);
    clipper.AddPaths(section, ClipperLib::ptClip, true);
    ClipperLib::Paths shared;
    clipper.Execute(ClipperLib::ctIntersection, shared, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    if (parallel) {
      if (level <= tolerance || level >= hb - tolerance) continue;  // the slice misses b's inside
    } else {
      // Only where the slice is inside b's slab, a tolerance in from its faces.
      const double rise = dot(towards, tb);  // b's height gained per mm along `towards`
      const double low = (tolerance - level) / rise, high = (hb - tolerance - level) / rise;
      const Loop strip{plus(origin, plus(scaled(along, -reach), scaled(towards, low))), plus(origin, plus(scaled(along, reach), scaled(towards, low))),
                       plus(origin, plus(scaled(along, reach), scaled(towards, high))), plus(origin, plus(scaled(along, -reach), scaled(towards, high)))};
      ClipperLib::Clipper inSlab;
      inSlab.AddPaths(shared, ClipperLib::ptSubject, true);
      inSlab.AddPaths(clipperPaths({strip}, frame), ClipperLib::ptClip, true);
      ClipperLib::Paths inside;
      inSlab.Execute(ClipperLib::ctIntersection, inside, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
      shared = inside;
    }
    for (const ClipperLib::Path& piece : shared) {
      double perimeter = 0;
      for (size_t i = 0; i < piece.size(); ++i) {
        const ClipperLib::IntPoint& u = piece[i];
        const ClipperLib::IntPoint& w = piece[(i + 1) % piece.size()];
        perimeter += std::hypot(static_cast<double>(w.X - u.X), static_cast<double>(w.Y - u.Y)) / kClipperScale;
      }
      const double area = std::abs(ClipperLib::Area(piece)) / (kClipperScale * kClipperScale);
      if (perimeter > 0 && 2 * area / perimeter > tolerance) {
        throwBadInput("", plateName(plateA) + " and " + plateName(plateB) + " overlap (their solids share " + millimetres(2 * area / perimeter) +
                              " wide and more) where no contact or crossing explains it: move them apart until they touch");
      }
    }
  }
}

}  // namespace

namespace {
std::vector<PlateContact> contactsOfSolids(const std::vector<Plate>& plates, const std::vector<int>& owner,
                                           size_t firstAttached, const PlateOptions& options);
}  // namespace

// Plates with attached solids (milled joints): every solid on its own, solids of one plate never
// in contact with each other, each contact then given to the solids' plates.
std::vector<PlateContact> computePlateContacts(const std::vector<Plate>& plates, const PlateOptions& options) {
  std::vector<Plate> solids;
  std::vector<int> owner;
  for (size_t p = 0; p < plates.size(); ++p) {
    solids.push_back(plates[p]);
    solids.back().attached.clear();
    owner.push_back(static_cast<int>(p));
  }
  for (size_t p = 0; p < plates.size(); ++p) {
    for (const Plate& solid : plates[p].attached) {
      solids.push_back(solid);
      solids.back().id = plates[p].id;
      solids.back().name = plates[p].name;
      owner.push_back(static_cast<int>(p));
    }
  }
  std::vector<PlateContact> contacts = contactsOfSolids(solids, owner, plates.size(), options);
  snapContactNormals(&contacts);
  if (solids.size() == plates.size()) return contacts;
  for (PlateContact& contact : contacts) {
    contact.a = owner[contact.a];
    contact.b = owner[contact.b];
    if (contact.a > contact.b) {  // pairs in plate order, the normal from a into b
      std::swap(contact.a, contact.b);
      contact.normal = negated(contact.normal);
      std::swap(contact.aOpens, contact.bOpens);
    }
  }
  // In a fixed order: by plate pair, then as found.
  std::stable_sort(contacts.begin(), contacts.end(), [](const PlateContact& x, const PlateContact& y) {
    return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return contacts;
}

namespace {

// Solids from `firstAttached` on are attached solids (milled joint pieces, built from the joint's
// exact directions); a cut plate's faces come from a 2D boolean on a 1e-4 mm grid. Where the two
// meet, the attached solid's face gives the contact's normal: a wall the grid turned by 1e-5 rad
// would otherwise block a tenon sliding along it (a mitre tenon leaving its pocket).
std::vector<PlateContact> contactsOfSolids(const std::vector<Plate>& plates, const std::vector<int>& owner,
                                           size_t firstAttached, const PlateOptions& options) {
  const double tolerance = options.contactTolerance;
  std::vector<std::vector<SolidFace>> faces;
  std::vector<Box> boxes;
  std::vector<Vec3> axes;
  for (const Plate& plate : plates) {
    faces.push_back(solidFaces(plate));
    boxes.push_back(boxOf(plate));
    axes.push_back(thicknessAxis(plate));
  }
  std::vector<PlateContact> contacts;
  for (size_t p = 0; p < plates.size(); ++p) {
    for (size_t q = p + 1; q < plates.size(); ++q) {
      if (owner[p] == owner[q] || !boxes[p].touches(boxes[q], tolerance)) continue;
      for (const SolidFace& f : faces[p]) {
        const PlaneFrame frame(f.loops[0][0], f.normal);
        for (const SolidFace& g : faces[q]) {
          if (dot(f.normal, g.normal) > -0.999) continue;                // not facing each other
          if (maxDistanceToPlane(g.loops, frame) > tolerance) continue;  // not in one plane
          ClipperLib::Clipper clipper;
          clipper.AddPaths(clipperPaths(f.loops, frame), ClipperLib::ptSubject, true);
          clipper.AddPaths(clipperPaths(g.loops, frame), ClipperLib::ptClip, true);
          ClipperLib::Paths overlap;
          clipper.Execute(ClipperLib::ctIntersection, overlap, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
          double area = 0;
          const ClipperLib::Path* largest = nullptr;
          for (const ClipperLib::Path& path : overlap) {
            const double a = ClipperLib::Area(path) / (kClipperScale * kClipperScale);
            area += a;
            if (!largest || std::abs(a) > std::abs(ClipperLib::Area(*largest)) / (kClipperScale * kClipperScale))
              largest = &path;
          }
          if (area <= tolerance * tolerance) continue;
          PlateContact contact;
          contact.a = static_cast<int>(p);
          contact.b = static_cast<int>(q);
          const bool otherIsExact = p < firstAttached && q >= firstAttached;
          contact.normal = *cleanedNormal(otherIsExact ? negated(g.normal) : f.normal);
          contact.area = area;
          for (const ClipperLib::IntPoint& point : *largest) contact.region.push_back(frame.fromClipper(point));
          Vec3 edge = cross(axes[p], axes[q]);
          if (norm(edge) < 1e-6) {
            // Parallel plates meet edge to edge: the shared edge runs along the contact's longest side.
            for (size_t i = 0; i < contact.region.size(); ++i) {
              const Vec3 side = minus(contact.region[(i + 1) % contact.region.size()], contact.region[i]);
              if (norm(side) > norm(edge)) edge = side;
            }
          }
          contact.edgeDirection = canonicalSign(normalized(edge));
          contacts.push_back(contact);
        }
      }
      if (std::optional<PlateContact> crossing =
              plateCrossing(plates, static_cast<int>(p), static_cast<int>(q), tolerance)) {
        contacts.push_back(*crossing);
      }
      requireNoSlantedOverlap(plates[p], plates[q], tolerance);
      requireMitredPerpendicularApart(plates[p], plates[q], tolerance);
    }
  }
  return contacts;
}

}  // namespace

void requireConnectedPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                            const std::string& source) {
  const int n = static_cast<int>(plates.size());
  if (n < 2) return;
  std::vector<int> group(n);
  for (int i = 0; i < n; ++i) group[i] = i;
  auto find = [&](int x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  std::vector<bool> touches(n, false);
  for (const PlateContact& c : contacts) {
    touches[c.a] = touches[c.b] = true;
    group[find(c.a)] = find(c.b);
  }
  for (int i = 0; i < n; ++i) {
    if (!touches[i])
      throwBadInput(source,
                    plateName(plates[i]) + " touches no other plate (no face of it lies on another plate's face)");
  }
  std::vector<int> firstOfGroup;
  for (int i = 0; i < n; ++i) {
    if (find(i) == i) firstOfGroup.push_back(i);
  }
  if (firstOfGroup.size() > 1) {
    std::string groups;
    for (size_t g = 0; g < firstOfGroup.size() && g < 4; ++g) {
      std::string members;
      int count = 0;
      for (int i = 0; i < n && count < 6; ++i) {
        if (find(i) == firstOfGroup[g]) members += (count++ ? ", " : "") + std::to_string(plates[i].id);
      }
      groups += (g ? "; " : "") + std::string("plates ") + members;
    }
    throwBadInput(source, "the design falls apart into " + std::to_string(firstOfGroup.size()) +
                              " groups that do not touch: " + groups);
  }
}

Assembly assemblyFromPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts) {
  Assembly assembly;
  for (const Plate& plate : plates) assembly.parts.push_back({plate.id, plate.name});
  // A crossing blocks nothing yet: it is a joint to be cut (it joins the parts-graph all the same).
  for (const PlateContact& c : contacts) {
    if (!c.crossing) assembly.contacts.push_back({c.a, c.b, c.normal, c.area});
  }
  return assembly;
}

std::vector<int> plateCutPoints(int plateCount, const std::vector<PlateContact>& contacts) {
  std::vector<std::pair<int, int>> edges;
  for (const PlateContact& c : contacts) edges.push_back({c.a, c.b});
  return findCutPoints(plateCount, edges);
}

}  // namespace desia
