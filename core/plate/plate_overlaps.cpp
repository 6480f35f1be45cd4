// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/plate_overlaps.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

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


// How a plate's first-face plane meets another plate's slab where they cross at any angle: the
// slab is a strip along the crossing line, offsets along `across` (unit, in the plate's plane,
// square to the line, the other plate's axis rising along it by `rise` = the sine of the angle
// between the planes) from the crossing point. At the plate's mid-plane the strip is [midFrom,
// midTo]; anywhere across the plate's thickness, seen along its axis, [from, to] (paper Fig. 16c:
// the walls of a halved joint's notch follow the other plate's faces, slanted to this one's).
struct SlabTrace {
  Vec3 across;
  double rise = 1, midFrom = 0, midTo = 0, from = 0, to = 0;
};

SlabTrace slabTrace(const Vec3& axis, double thickness, const Vec3& otherAxis, double otherThickness) {
  double cosine = dot(axis, otherAxis);
  SlabTrace trace;
  if (std::abs(cosine) < tolerance::kSquareCosine) {
    cosine = 0;
    trace.across = otherAxis;
  } else {
    trace.across = normalized(minus(otherAxis, scaled(axis, cosine)));
    trace.rise = dot(trace.across, otherAxis);
  }
  // A point `s` along `across` at height h across the plate is at h * cosine + s * rise into the slab.
  const double shift = thickness * cosine / trace.rise, width = otherThickness / trace.rise;
  trace.midFrom = -shift / 2;
  trace.midTo = width - shift / 2;
  trace.from = std::min(0.0, -shift);
  trace.to = std::max(width, width - shift);
  return trace;
}

// The strip [from, to] along `across` from `point`, `reach` each way along `line`: where a slab
// (or its trace) meets a plane, as a loop in that plane.
Loop stripAlong(const Vec3& point, const Vec3& line, const Vec3& across, double from, double to, double reach) {
  const Vec3 low = plus(point, scaled(across, from)), high = plus(point, scaled(across, to));
  return {plus(low, scaled(line, -reach)), plus(low, scaled(line, reach)), plus(high, scaled(line, reach)),
          plus(high, scaled(line, -reach))};
}

// The loops' region within the strip [from, to] along `across` (from `point`, `reach` each way
// along `line`), as Clipper paths in `frame`.
ClipperLib::Paths regionInStrip(const std::vector<Loop>& loops, const PlaneFrame& frame, const Vec3& point,
                                const Vec3& line, const Vec3& across, double from, double to, double reach) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(loops, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths({stripAlong(point, line, across, from, to, reach)}, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths inside;
  clipper.Execute(ClipperLib::ctIntersection, inside, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
  return inside;
}

// The part of `plate`'s face inside the slab of another plate (`width` thick from `point` along
// `across`), as Clipper paths in `frame` (the plate's first face plane). The slab's inside, a
// tolerance in from each face: a hole as wide as the slab (a mortise) then splits the region, and
// a face lying on the slab's face adds nothing.
ClipperLib::Paths insideSlab(const Plate& plate, const PlaneFrame& frame, const Vec3& point, const Vec3& line,
                             const Vec3& across, double width, double reach, double tolerance) {
  return regionInStrip(plate.bottom, frame, point, line, across, tolerance, width - tolerance, reach);
}

// Where along `line` (from `point`) the plate has material across the whole strip `trace` of the
// other plate's slab (seen along the plate's axis, a tolerance in from its edges): the strip less the
// plate leaves gaps, and wherever a gap's shadow falls some of the strip is empty.
std::vector<std::pair<double, double>> throughStretches(const Plate& plate, const PlaneFrame& frame, const Vec3& point,
                                                        const Vec3& line, const SlabTrace& trace, double reach,
                                                        double tolerance) {
  const Loop strip = stripAlong(point, line, trace.across, trace.from + tolerance / trace.rise,
                                trace.to - tolerance / trace.rise, reach);
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths({strip}, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths(plate.bottom, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths gaps;
  clipper.Execute(ClipperLib::ctDifference, gaps, ClipperLib::pftNonZero, ClipperLib::pftEvenOdd);
  std::vector<std::pair<double, double>> through;
  double start = -reach;
  for (const auto& [gapFrom, gapTo] : shadowOnLine(gaps, frame, point, line)) {
    if (gapFrom - start > tolerance) through.push_back({start, gapFrom});
    start = std::max(start, gapTo);
  }
  if (reach - start > tolerance) through.push_back({start, reach});
  return through;
}

// How far the plate's material in the other's slab (`trace`: both faces' traces) reaches past the
// crossing's ends [from, to] (PlateContact::aOverhang): where past an end it has material across
// the whole trace somewhere (its through stretch runs on), it does not taper there: infinite.
std::array<double, 2> overhangsPast(const Plate& plate, const PlaneFrame& frame, const Vec3& point, const Vec3& line,
                                    const SlabTrace& trace, double from, double to, double reach, double tolerance) {
  const ClipperLib::Paths material = regionInStrip(plate.bottom, frame, point, line, trace.across,
                                                   trace.from + tolerance / trace.rise, trace.to - tolerance / trace.rise, reach);
  const std::vector<std::pair<double, double>> shadow = shadowOnLine(material, frame, point, line);
  if (shadow.empty()) return {PlateContact::kNoTaper, PlateContact::kNoTaper};
  std::array<double, 2> overhang{std::max(0.0, from - shadow.front().first), std::max(0.0, shadow.back().second - to)};
  for (const auto& [start, end] : throughStretches(plate, frame, point, line, trace, reach, tolerance)) {
    if (end < from - tolerance || start > to + tolerance) continue;  // another stretch than the crossing's
    if (start < from - tolerance) overhang[0] = PlateContact::kNoTaper;
    if (end > to + tolerance) overhang[1] = PlateContact::kNoTaper;
  }
  return overhang;
}

}  // namespace

namespace geometry {

// Perpendicular plates of which one or both have mitred sides cannot cross (halved joints need
// plates of their whole thickness), so they must not share volume at all: judged by their core
// prisms (where they have their whole thickness, corePrism), which lie inside them. A refusal is
// always a real overlap; one within the mitres alone can pass (the design's swept check finds it).
void requireMitredPerpendicularApart(const Plate& a, const Plate& b, double tolerance) {
  if (std::abs(dot(plateThicknessAxis(a), plateThicknessAxis(b))) > tolerance::kSquareCosine ||
      (isPrism(a) && isPrism(b)))
    return;
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
                          " overlap where no contact explains it (perpendicular plates with mitred sides must touch "
                          "or pass right through each other): move them apart until they touch");
  }
}

// The contact of plates p and q crossing through each other over [from, to] along the line (point,
// direction) where their planes meet; `depth` is the larger of their stretches across each other.
PlateContact crossingContact(int p, int q, const Vec3& direction, const Vec3& point, double from, double to,
                             double depth) {
  PlateContact crossing;
  crossing.a = p;
  crossing.b = q;
  crossing.crossing = true;
  crossing.edgeDirection = direction;
  crossing.crossingPoint = point;
  crossing.crossingFrom = from;
  crossing.crossingTo = to;
  crossing.area = (to - from) * depth;
  return crossing;
}

// Plates crossing at any angle, prisms or with mitred sides (judged by their core prisms, where
// they have their whole thickness): over a stretch of the line where their planes meet, each has
// material across the other's whole slab (the parallelogram where the slabs meet, seen along its
// own axis), and nowhere else do their shadows on that line meet. Anything less is no crossing
// here: the callers' overlap checks judge it and refuse a real overlap naming both plates.
std::optional<PlateContact> slantedCrossing(const std::vector<Plate>& plates, int p, int q, double tolerance) {
  const Plate a = isPrism(plates[p]) ? plates[p] : corePrism(plates[p]);
  const Plate b = isPrism(plates[q]) ? plates[q] : corePrism(plates[q]);
  if (a.bottom.empty() || b.bottom.empty()) return std::nullopt;
  const Vec3 ta = plateThicknessAxis(plates[p]), tb = plateThicknessAxis(plates[q]);
  if (norm(cross(ta, tb)) < tolerance::kParallelSine) return std::nullopt;
  const double ha = plateThickness(plates[p]), hb = plateThickness(plates[q]);
  const Vec3 line = canonicalSign(normalized(cross(ta, tb)));
  // On both first faces: the point of the planes' common line nearest the origin's projection.
  const double cosine = dot(ta, tb), sineSquared = 1 - cosine * cosine;
  const double ca = dot(a.bottom[0][0], ta), cb = dot(b.bottom[0][0], tb);
  const Vec3 point = plus(scaled(ta, (ca - cosine * cb) / sineSquared), scaled(tb, (cb - cosine * ca) / sineSquared));
  const SlabTrace inA = slabTrace(ta, ha, tb, hb), inB = slabTrace(tb, hb, ta, ha);  // b's slab on a's plane, ...
  const Box boxA = boxOf(a), boxB = boxOf(b);
  double reach = 0;
  for (int k = 0; k < 3; ++k)
    reach += std::max(boxA.hi[k], boxB.hi[k]) - std::min(boxA.lo[k], boxB.lo[k]) + std::abs(point[k]);
  const PlaneFrame frameA(a.bottom[0][0], ta), frameB(b.bottom[0][0], tb);
  // Each plate's material in the other's slab at its mid-plane, a tolerance in from the slab's faces.
  const ClipperLib::Paths materialA = regionInStrip(a.bottom, frameA, point, line, inA.across,
                                                    inA.midFrom + tolerance / inA.rise, inA.midTo - tolerance / inA.rise, reach);
  const ClipperLib::Paths materialB = regionInStrip(b.bottom, frameB, point, line, inB.across,
                                                    inB.midFrom + tolerance / inB.rise, inB.midTo - tolerance / inB.rise, reach);
  if (pathsArea(materialA) <= tolerance * tolerance || pathsArea(materialB) <= tolerance * tolerance) return std::nullopt;
  const std::vector<std::pair<double, double>> shadowA = shadowOnLine(materialA, frameA, point, line);
  const std::vector<std::pair<double, double>> shadowB = shadowOnLine(materialB, frameB, point, line);
  const std::vector<std::pair<double, double>> common = commonStretches(shadowA, shadowB, tolerance);
  if (common.size() != 1) return std::nullopt;
  const double from = common[0].first, to = common[0].second;
  // Through: over a stretch each plate has material across the other's whole slab, seen along its
  // own axis (its slot's walls are the other's faces). Beyond that stretch only a plate ending
  // across the line at a slant may be in the other's slab, for at most as far as the slabs' traces
  // are wide (its mid-plane shadow reaches that much further than its whole thickness does; twice
  // that allows for the mitres a core prism leaves out); its slot runs out past the end all the
  // same. Plates crossing between their tips (timber-plate pavilions, reciprocal roofs: 10 to 30 mm
  // through at 46 to 80 degrees) have only that stretch. A plate stopping inside the other's slab
  // is through nowhere: a real overlap, refused by the callers.
  const std::vector<std::pair<double, double>> through =
      commonStretches(throughStretches(a, frameA, point, line, inA, reach, tolerance),
                      throughStretches(b, frameB, point, line, inB, reach, tolerance), tolerance);
  if (through.size() != 1) return std::nullopt;
  const double slant = std::max(inA.to - inA.from, inB.to - inB.from);
  const double endLength = 2 * slant;
  if (to - from > 2 * endLength &&
      (through[0].first > from + endLength + tolerance || through[0].second < to - endLength - tolerance))
    return std::nullopt;
  PlateContact crossing = crossingContact(p, q, line, point, from, to, std::max(inA.to - inA.from, inB.to - inB.from));
  crossing.aOpens = {shadowA.front().first >= from - tolerance, shadowA.back().second <= to + tolerance};
  crossing.bOpens = {shadowB.front().first >= from - tolerance, shadowB.back().second <= to + tolerance};
  crossing.aOverhang = overhangsPast(a, frameA, point, line, inA, from, to, reach, tolerance);
  crossing.bOverhang = overhangsPast(b, frameB, point, line, inB, from, to, reach, tolerance);
  return crossing;
}

// Plates p and q crossing through each other: perpendicular prisms whose faces each fill the other's
// slab over a common stretch of the line where their planes meet. A partial overlap is refused.
std::optional<PlateContact> plateCrossing(const std::vector<Plate>& plates, int p, int q, double tolerance) {
  const Plate& a = plates[p];
  const Plate& b = plates[q];
  const Vec3 ta = plateThicknessAxis(a), tb = plateThicknessAxis(b);
  if (std::abs(dot(ta, tb)) > tolerance::kSquareCosine || !isPrism(a) || !isPrism(b))
    return slantedCrossing(plates, p, q, tolerance);
  const double ha = plateThickness(a), hb = plateThickness(b);
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
    // A plate ending across the line at a slant fills the other's slab short of its mid-plane
    // shadow's end: slantedCrossing allows for that.
    if (std::optional<PlateContact> slanted = slantedCrossing(plates, p, q, tolerance)) return slanted;
    throwBadInput("", plateName(a) + " and " + plateName(b) +
                          " overlap without passing through each other: make them cross "
                          "through (each filling the other's thickness) or meet face to face");
  }
  PlateContact crossing = crossingContact(p, q, line, point, from, to, std::max(ha, hb));
  // A slot opens where the plate's material in the other's slab ends with the crossing.
  crossing.aOpens = {a0 >= from - tolerance, a1 <= to + tolerance};
  crossing.bOpens = {b0 >= from - tolerance, b1 <= to + tolerance};
  crossing.aOverhang = overhangsPast(a, frameA, point, line, slabTrace(ta, ha, tb, hb), from, to, reach, tolerance);
  crossing.bOverhang = overhangsPast(b, frameB, point, line, slabTrace(tb, hb, ta, ha), from, to, reach, tolerance);
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
  if (std::abs(cosine) < tolerance::kSquareCosine) return;  // perpendicular: computePlateContacts' crossings
  const Plate a = corePrism(plateA), b = corePrism(plateB);
  if (a.bottom.empty() || b.bottom.empty()) return;
  const double ha = plateThickness(plateA), hb = plateThickness(plateB);
  const Box boxA = boxOf(a), boxB = boxOf(b);
  double reach = 0;
  for (int k = 0; k < 3; ++k) reach += std::max(boxA.hi[k], boxB.hi[k]) - std::min(boxA.lo[k], boxB.lo[k]);
  const bool parallel = std::abs(cosine) > 1 - tolerance::kDirection;
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

}  // namespace geometry
}  // namespace desia
