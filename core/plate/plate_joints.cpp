// SPDX-License-Identifier: GPL-3.0-or-later
// Joint geometry for plate structures (paper Section 5.2, geometry realization; Fig. 2, left).
//
// A mortise-and-tenon joint: the tenon plate S stands with a square side on a face of the mortise
// plate F, S at a right angle to F. Tenons grow out of that side, as deep as F is thick; mortises
// of the same size (plus the clearance) go through F, inside it or open at its edge where S is
// flush with it. The tenons' cheeks (normals +-S's thickness axis; one of them for an open
// mortise) and ends (+-along the side) and the shoulder then block every way but out.
//
// The plates are prisms (every side square to the faces), so a cut is a 2D boolean on the face,
// done by Clipper, and the second face is the first moved by the thickness: a jointed plate is
// again a Plate that the contact computation, the meshes and the exports take as it is.
#include "desia/plate_joints.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "plate/exact_vertices.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {


constexpr double kSquare = 1e-6;        // |cos| below this: at a right angle
constexpr double kTolerance = 0.05;     // mm: faces closer than this lie on one another
constexpr double kMortiseMargin = 1.0;  // mm of material left around a mortise at least
constexpr double kShortestJoint = 3.0;  // mm: a shorter contact gets no tenon

std::string plateLabel(const Plate& plate) {
  return "plate " + std::to_string(plate.id) + (plate.name.empty() ? "" : " (" + plate.name + ")");
}

// Side k of the outline is square: its face stands at a right angle on the plate's faces (a
// plate given by its two faces may have mitred sides elsewhere).
bool sideIsSquare(const Plate& plate, size_t k) {
  const Vec3 lift = scaled(plateThicknessAxis(plate), plateThickness(plate));
  const size_t next = (k + 1) % plate.bottom[0].size();
  return norm(minus(plate.top[0][k], plus(plate.bottom[0][k], lift))) < 1e-6 &&
         norm(minus(plate.top[0][next], plus(plate.bottom[0][next], lift))) < 1e-6;
}

double areaOf(const ClipperLib::Paths& paths) {
  double area = 0;
  for (const ClipperLib::Path& path : paths) area += ClipperLib::Area(path);
  return std::abs(area) / (kClipperScale * kClipperScale);
}

// Area of the loops' region (non-zero) inside or outside `face` (its outline minus its holes).
double areaAgainst(const std::vector<Loop>& loops, const std::vector<Loop>& face, const PlaneFrame& frame,
                   bool outside) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(loops, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths(face, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths result;
  clipper.Execute(outside ? ClipperLib::ctDifference : ClipperLib::ctIntersection, result, ClipperLib::pftNonZero,
                  ClipperLib::pftEvenOdd);
  return areaOf(result);
}

// A rectangle on the tenon plate's side: [start, end] along it, [low, high] across the tenon
// plate's thickness, on the face the tenon plate stands on.
Loop footprint(const Plate& tenonPlate, const TenonSite& site, double start, double end, double low, double high) {
  const Vec3 base = tenonPlate.bottom[0][site.edge];
  auto at = [&](double s, double t) { return plus(base, plus(scaled(site.along, s), scaled(site.across, t))); };
  return {at(start, low), at(end, low), at(end, high), at(start, high)};
}

// The mortise of one tenon: its footprint grown by half the clearance, run out past the open edge.
Loop mortiseOf(const std::vector<Plate>& plates, const TenonSite& site, double start, double end, double clearance) {
  const Plate& tenonPlate = plates[site.tenonPlate];
  const double width = plateThickness(tenonPlate), grow = clearance / 2;
  const double low = site.openSide < 0 ? -kMortiseMargin - grow : -grow;
  const double high = site.openSide > 0 ? width + kMortiseMargin + grow : width + grow;
  return footprint(tenonPlate, site, start - grow, end + grow, low, high);
}

// The tenon itself, in the tenon plate's plane: out of its side, as deep as the mortise plate.
Loop tenonOf(const std::vector<Plate>& plates, const TenonSite& site, double start, double end) {
  const Vec3 base = plates[site.tenonPlate].bottom[0][site.edge];
  const Vec3 out = scaled(site.intoMortise, plateThickness(plates[site.mortisePlate]));
  // Reaching 0.01 mm into the plate, so that the union joins them across rounding (a turned design).
  const Vec3 in = scaled(site.intoMortise, -0.01);
  const Vec3 a = plus(base, scaled(site.along, start)), b = plus(base, scaled(site.along, end));
  return {plus(a, in), plus(b, in), plus(b, out), plus(a, out)};
}

// Which kind of mortise fits: through (inside the face plate with a margin all round), open at
// one side (that side of the tenon plate flush with the face plate's edge), or none.
std::optional<int> mortiseKind(const std::vector<Plate>& plates, TenonSite site,
                               const std::vector<std::pair<double, double>>& spans, double clearance) {
  const Plate& tenonPlate = plates[site.tenonPlate];
  const Plate& mortisePlate = plates[site.mortisePlate];
  const PlaneFrame frame(mortisePlate.bottom[0][0], plateThicknessAxis(mortisePlate));
  const double width = plateThickness(tenonPlate), margin = kMortiseMargin + clearance / 2;
  constexpr double kFlush = 0.01;  // mm
  const std::vector<Loop> whole = faceRegion(mortisePlate, ClipperLib::ctIntersection);
  const std::vector<Loop> any = faceRegion(mortisePlate, ClipperLib::ctUnion);
  auto inside = [&](double low, double high) {
    std::vector<Loop> rects;
    for (const auto& [start, end] : spans)
      rects.push_back(footprint(tenonPlate, site, start - margin, end + margin, low, high));
    return areaAgainst(rects, whole, frame, true) < 1e-6;
  };
  auto clearBeyond = [&](double low, double high) {
    std::vector<Loop> rects;
    for (const auto& [start, end] : spans) rects.push_back(footprint(tenonPlate, site, start, end, low, high));
    return areaAgainst(rects, any, frame, false) < 1e-6;
  };
  if (inside(-margin, width + margin)) return 0;
  if (inside(-margin, width - kFlush) && clearBeyond(width + kFlush, width + kMortiseMargin)) return 1;
  if (inside(kFlush, width + margin) && clearBeyond(-kMortiseMargin, -kFlush)) return -1;
  return std::nullopt;
}

// The contact's extent along a direction, from a point.
std::pair<double, double> extentAlong(const Loop& region, const Vec3& origin, const Vec3& direction) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Vec3& p : region) {
    const double s = dot(minus(p, origin), direction);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return {lo, hi};
}

// The 2D region of a plate's faces after the cuts, as the loops of its bottom face (outline
// first); throws when the cuts split it.
std::vector<Loop> cutFace(const Plate& plate, const std::vector<Loop>& added, const std::vector<Loop>& removed) {
  const PlaneFrame frame(plate.bottom[0][0], plateThicknessAxis(plate));
  ClipperLib::Clipper grow;
  grow.AddPaths(clipperPaths(plate.bottom, frame), ClipperLib::ptSubject, true);
  grow.AddPaths(clipperPaths(added, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths grown;
  grow.Execute(ClipperLib::ctUnion, grown, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
  ClipperLib::Clipper cut;
  cut.StrictlySimple(true);
  cut.AddPaths(grown, ClipperLib::ptSubject, true);
  cut.AddPaths(clipperPaths(removed, frame), ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  cut.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  if (tree.ChildCount() != 1) {
    throwBadInput("", "the joints cut " + plateLabel(plate) + " into " + std::to_string(tree.ChildCount()) + " pieces");
  }
  const ClipperLib::PolyNode* outer = tree.Childs[0];
  const ExactVertices exact(frame, {&plate.bottom, &added, &removed});
  std::vector<Loop> loops;
  loops.push_back(exact.loop(outer->Contour));
  for (const ClipperLib::PolyNode* hole : outer->Childs) {
    if (hole->ChildCount() > 0) throwBadInput("", "the joints cut a loose piece inside " + plateLabel(plate));
    loops.push_back(exact.loop(hole->Contour));
  }
  return loops;
}

}  // namespace

std::vector<Vec3> TenonSite::exits() const {
  std::vector<Vec3> ways{negated(intoMortise)};
  if (openSide != 0) ways.push_back(scaled(across, openSide));
  return ways;
}

std::vector<std::pair<double, double>> tenonSpans(const std::vector<Plate>& plates, const TenonSite& site,
                                                  const JointCutOptions& options) {
  const double length = site.to - site.from;
  const double thickness = plateThickness(plates[site.tenonPlate]);
  const int count = options.tenonCount > 0 ? options.tenonCount : (length >= 8 * thickness ? 2 : 1);
  if (site.stagger != 0) {
    // 4 count + 1 equal pieces; this side's tenons in pieces 1, 5, 9, ... or 3, 7, 11, ...
    const double piece = length / (4 * count + 1);
    const double width = std::min(options.tenonWidth > 0 ? options.tenonWidth : piece, piece);
    if (width < 2 * kMortiseMargin) return {};
    // Pieces are counted the same way on both sides: along the edge's canonical direction.
    const bool reversed = dot(site.along, canonicalSign(site.along)) < 0;
    std::vector<std::pair<double, double>> spans;
    for (int j = 0; j < count; ++j) {
      const int index = 4 * j + (site.stagger > 0 ? 1 : 3);
      const double centre = site.from + piece * ((reversed ? 4 * count - index : index) + 0.5);
      spans.push_back({centre - width / 2, centre + width / 2});
    }
    std::sort(spans.begin(), spans.end());
    return spans;
  }
  const double width = options.tenonWidth > 0 ? options.tenonWidth : length / (2 * count + 1);
  const double pitch = length / count;
  // Tenons need room between them and at the ends: a tenon never wider than its share less a gap.
  if (width >= pitch - std::min(pitch / 3, 2 * kMortiseMargin)) return {};
  std::vector<std::pair<double, double>> spans;
  for (int j = 0; j < count; ++j) {
    const double centre = site.from + pitch * (j + 0.5);
    spans.push_back({centre - width / 2, centre + width / 2});
  }
  return spans;
}

void staggerOpposingSites(const std::vector<Plate>& plates, std::vector<std::optional<TenonSite>>* sites) {
  auto footprintBox = [&](const TenonSite& site) {
    const Plate& mortisePlate = plates[site.mortisePlate];
    const PlaneFrame frame(mortisePlate.bottom[0][0], plateThicknessAxis(mortisePlate));
    const Loop rect =
        footprint(plates[site.tenonPlate], site, site.from, site.to, 0, plateThickness(plates[site.tenonPlate]));
    std::array<double, 4> box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Vec3& p : rect) {
      const double x = dot(frame.offset(p), frame.u), y = dot(frame.offset(p), frame.v);
      box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    }
    return box;
  };
  for (size_t i = 0; i < sites->size(); ++i) {
    for (size_t j = i + 1; j < sites->size(); ++j) {
      std::optional<TenonSite>& a = (*sites)[i];
      std::optional<TenonSite>& b = (*sites)[j];
      if (!a || !b || a->mortisePlate != b->mortisePlate || dot(a->intoMortise, b->intoMortise) > -0.5) continue;
      const std::array<double, 4> p = footprintBox(*a), q = footprintBox(*b);
      if (p[2] <= q[0] + kTolerance || q[2] <= p[0] + kTolerance || p[3] <= q[1] + kTolerance ||
          q[3] <= p[1] + kTolerance)
        continue;
      const bool aFromBelow = dot(a->intoMortise, plateThicknessAxis(plates[a->mortisePlate])) > 0;
      a->stagger = aFromBelow ? 1 : -1;
      b->stagger = -a->stagger;
    }
  }
}

namespace {

// A square side of one prismatic plate standing on a face of another at a right angle, its whole
// thickness on the face: the geometry every edge joint needs (no tenons or housing chosen yet).
std::optional<TenonSite> squareEdgeSite(const std::vector<Plate>& plates, const PlateContact& contact) {
  const Vec3 axisA = plateThicknessAxis(plates[contact.a]), axisB = plateThicknessAxis(plates[contact.b]);
  const bool aOnFace = std::abs(dot(contact.normal, axisA)) > 1 - kSquare;
  const bool bOnFace = std::abs(dot(contact.normal, axisB)) > 1 - kSquare;
  if (aOnFace == bOnFace || std::abs(dot(axisA, axisB)) > kSquare) return std::nullopt;
  // Plates given by two faces may have mitred sides: the edge itself must be square (below), and
  // the other plate is cut only where it is whole (mortiseKind).
  TenonSite site;
  site.tenonPlate = aOnFace ? contact.b : contact.a;
  site.mortisePlate = aOnFace ? contact.a : contact.b;
  site.intoMortise = aOnFace ? negated(contact.normal) : contact.normal;
  const Plate& tenonPlate = plates[site.tenonPlate];
  const Loop& bottom = tenonPlate.bottom[0];
  const std::vector<Vec3> sideNormals = plateSideNormals(tenonPlate, 0);
  site.across = plateThicknessAxis(tenonPlate);
  const Vec3 middle = [&] {
    Vec3 sum{0, 0, 0};
    for (const Vec3& p : contact.region) sum = plus(sum, p);
    return scaled(sum, 1.0 / static_cast<double>(contact.region.size()));
  }();
  for (size_t k = 0; k < bottom.size(); ++k) {
    const size_t next = (k + 1) % bottom.size();
    if (dot(sideNormals[k], site.intoMortise) < 1 - kSquare) continue;
    if (std::abs(dot(minus(middle, bottom[k]), site.intoMortise)) > kTolerance) continue;
    if (!sideIsSquare(tenonPlate, k)) return std::nullopt;
    site.edge = static_cast<int>(k);
    site.along = normalized(minus(bottom[next], bottom[k]));
    const auto [regionStart, regionEnd] = extentAlong(contact.region, bottom[k], site.along);
    site.from = std::max(0.0, regionStart);
    site.to = std::min(norm(minus(bottom[next], bottom[k])), regionEnd);
    // The whole thickness of S must stand on F, or the tenon would hang beside the mortise.
    const auto [acrossStart, acrossEnd] = extentAlong(contact.region, bottom[k], site.across);
    if (acrossStart > kTolerance || acrossEnd < plateThickness(tenonPlate) - kTolerance) return std::nullopt;
    if (site.to - site.from < kShortestJoint) return std::nullopt;
    return site;
  }
  return std::nullopt;
}

// A sliding dovetail's section (paper Fig. 2, right), across the edge plate's thickness `across`
// (c, from its first face) and into the face plate (n, from its face): the tongue is `wide` at
// the housing's floor, n = depth, and narrower by the lean on each side at the face, n = 0, so it
// cannot be pulled out. The lean is 1 in 6 (a common dovetail slope); the floor a third of the way
// through the face plate (two housings from opposite faces leave a third between them), the
// tongue two thirds of the edge plate's thickness, centred.
struct DovetailSection {
  double centre = 0, wide = 0, narrow = 0, depth = 0;
};

constexpr double kDovetailSlope = 1.0 / 6;
// The housing stops this far (at least) before the contact's closed end: material for the stop.
constexpr double kDovetailStop = 10.0;

DovetailSection dovetailSection(const std::vector<Plate>& plates, const TenonSite& edge) {
  DovetailSection section;
  const double thickness = plateThickness(plates[edge.tenonPlate]);
  section.centre = thickness / 2;
  section.depth = plateThickness(plates[edge.mortisePlate]) / 3;  // housings from both faces fit
  section.wide = 2 * thickness / 3;
  section.narrow = section.wide - 2 * kDovetailSlope * section.depth;
  return section;
}

// The housing's extent along the edge: from the stop to the open end.
std::pair<double, double> housingSpan(const std::vector<Plate>& plates, const DovetailCut& cut) {
  const TenonSite& edge = cut.site.edge;
  const double stop = std::max(kDovetailStop, plateThickness(plates[edge.mortisePlate]));
  return cut.openEnd == 1 ? std::make_pair(edge.from + stop, edge.to + cut.site.reach[1])
                          : std::make_pair(edge.from - cut.site.reach[0], edge.to - stop);
}

// A point of the joint: `s` along the edge, `c` across the edge plate, `n` into the face plate.
Vec3 jointPoint(const std::vector<Plate>& plates, const TenonSite& edge, double s, double c, double n) {
  const Vec3 base = plates[edge.tenonPlate].bottom[0][edge.edge];
  return plus(base, plus(scaled(edge.along, s), plus(scaled(edge.across, c), scaled(edge.intoMortise, n))));
}

// A prism along the edge from s0 to s1 with the given section corners (c, n): a Plate whose two
// faces are its ends.
Plate prismAlongEdge(const std::vector<Plate>& plates, const TenonSite& edge, double s0, double s1,
                     const std::vector<std::array<double, 2>>& section) {
  Plate prism;
  Loop first, second;
  for (const auto& [c, n] : section) {
    first.push_back(jointPoint(plates, edge, s0, c, n));
    second.push_back(jointPoint(plates, edge, s1, c, n));
  }
  prism.bottom.push_back(first);
  prism.top.push_back(second);
  return prism;
}

// How far past the contact's start (end 0) or end (end 1) a housing strip, [low, high] across the
// edge plate, runs inside the face plate's outline before it leaves it. Both sides of the strip
// must leave at the same place (a square end; a slanted one would leave wood in the way or open
// the housing's side); nothing where they do not, or where the strip never leaves.
std::optional<double> stripExit(const std::vector<Plate>& plates, const TenonSite& edge, const Loop& outline,
                                const PlaneFrame& frame, int end, double low, double high) {
  constexpr double kSameExit = 0.01;  // mm
  const double sign = end == 1 ? 1 : -1, at = end == 1 ? edge.to : edge.from;
  auto planar = [&](const Vec3& p) { return std::array<double, 2>{dot(frame.offset(p), frame.u), dot(frame.offset(p), frame.v)}; };
  const Vec3 way = scaled(edge.along, sign);
  const std::array<double, 2> dir{dot(way, frame.u), dot(way, frame.v)};
  std::array<double, 2> exits{};
  for (int side = 0; side < 2; ++side) {
    const std::array<double, 2> p = planar(jointPoint(plates, edge, at, side == 0 ? low : high, 0));
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < outline.size(); ++k) {
      const std::array<double, 2> q0 = planar(outline[k]), q1 = planar(outline[(k + 1) % outline.size()]);
      const double ex = q1[0] - q0[0], ey = q1[1] - q0[1];
      const double denominator = dir[0] * ey - dir[1] * ex;
      if (std::abs(denominator) < 1e-12) continue;  // the side runs along the strip
      const double wx = q0[0] - p[0], wy = q0[1] - p[1];
      const double t = (wx * ey - wy * ex) / denominator, u = (wx * dir[1] - wy * dir[0]) / denominator;
      if (t > 1e-9 && u >= -1e-9 && u <= 1 + 1e-9) nearest = std::min(nearest, t);
    }
    exits[side] = nearest;
  }
  if (!std::isfinite(exits[0]) || !std::isfinite(exits[1]) || std::abs(exits[0] - exits[1]) > kSameExit)
    return std::nullopt;
  return std::min(exits[0], exits[1]);
}

}  // namespace

std::optional<TenonSite> tenonSiteOf(const std::vector<Plate>& plates, const PlateContact& contact,
                                     const JointCutOptions& options) {
  std::optional<TenonSite> site = squareEdgeSite(plates, contact);
  if (!site) return std::nullopt;
  const std::vector<std::pair<double, double>> spans = tenonSpans(plates, *site, options);
  if (spans.empty()) return std::nullopt;
  const std::optional<int> kind = mortiseKind(plates, *site, spans, options.clearance);
  if (!kind) return std::nullopt;
  site->openSide = *kind;
  return site;
}

std::vector<Vec3> DovetailSite::exits() const {
  std::vector<Vec3> ways;
  if (opens[0]) ways.push_back(negated(edge.along));
  if (opens[1]) ways.push_back(edge.along);
  return ways;
}

std::optional<DovetailSite> dovetailSiteOf(const std::vector<Plate>& plates, const PlateContact& contact) {
  const std::optional<TenonSite> edge = squareEdgeSite(plates, contact);
  if (!edge || !isPrism(plates[edge->tenonPlate]) || !isPrism(plates[edge->mortisePlate])) return std::nullopt;
  DovetailSite site;
  site.edge = *edge;
  const Plate& housingPlate = plates[edge->mortisePlate];
  const DovetailSection section = dovetailSection(plates, *edge);
  if (section.narrow < 2) return std::nullopt;  // mm: too thin a neck to mill
  const double stop = std::max(kDovetailStop, plateThickness(housingPlate));
  if (edge->to - edge->from < stop + kShortestJoint) return std::nullopt;
  const PlaneFrame frame(housingPlate.bottom[0][0], plateThicknessAxis(housingPlate));
  const double low = section.centre - section.wide / 2, high = section.centre + section.wide / 2;
  auto rectangle = [&](double s0, double s1) {
    return Loop{jointPoint(plates, *edge, s0, low, 0), jointPoint(plates, *edge, s1, low, 0),
                jointPoint(plates, *edge, s1, high, 0), jointPoint(plates, *edge, s0, high, 0)};
  };
  constexpr double kFlush = 0.01;  // mm
  // Open at an end, `reach` past the contact: the face plate's material ends there (nothing of it
  // just beyond), and the housing from the stop to there lies inside it.
  auto opensAt = [&](int end, double reach) {
    const double sign = end == 1 ? 1 : -1, at = (end == 1 ? edge->to : edge->from) + sign * reach;
    const Loop beyond = rectangle(std::min(at + sign * kFlush, at + sign * kMortiseMargin),
                                  std::max(at + sign * kFlush, at + sign * kMortiseMargin));
    const Loop housing = end == 1 ? rectangle(edge->from + stop, at - kFlush) : rectangle(at + kFlush, edge->to - stop);
    return areaAgainst({beyond}, housingPlate.bottom, frame, false) < 1e-6 &&
           areaAgainst({housing}, housingPlate.bottom, frame, true) < 1e-6;
  };
  for (int end = 0; end < 2; ++end) {
    site.opens[end] = opensAt(end, 0);
    if (site.opens[end]) continue;
    const std::optional<double> reach = stripExit(plates, *edge, housingPlate.bottom[0], frame, end, low, high);
    if (reach && *reach > kFlush && opensAt(end, *reach)) {
      site.opens[end] = true;
      site.reach[end] = *reach;
    }
  }
  if (!site.opens[0] && !site.opens[1]) return std::nullopt;
  return site;
}

std::vector<Vec3> dovetailFaceNormals(const std::vector<Plate>& plates, const DovetailCut& cut) {
  const TenonSite& edge = cut.site.edge;
  const DovetailSection section = dovetailSection(plates, edge);
  const double lean = (section.wide - section.narrow) / 2;
  const Vec3 exit = cut.openEnd == 1 ? edge.along : negated(edge.along);
  return {edge.intoMortise,
          normalized(minus(scaled(edge.across, -section.depth), scaled(edge.intoMortise, lean))),
          normalized(minus(scaled(edge.across, section.depth), scaled(edge.intoMortise, lean))), negated(exit)};
}

std::vector<SlotCut> halvedSlots(const std::vector<Plate>& plates, const PlateContact& crossing, int mover,
                                 const Vec3& d, double clearance) {
  const int other = crossing.a == mover ? crossing.b : crossing.a;
  const Vec3& line = crossing.edgeDirection;
  const double sign = dot(d, line) > 0 ? 1 : -1;
  const double middle = (crossing.crossingFrom + crossing.crossingTo) / 2;
  // Far enough past the crossing's ends to run out of the outline there (it ends with the crossing).
  const double out = crossing.crossingTo - crossing.crossingFrom + kMortiseMargin;
  auto slot = [&](int plate, int across, double towards) {
    const Vec3 axis = plateThicknessAxis(plates[across]);
    const double width = plateThickness(plates[across]);
    // From the middle of the crossing out past its end `towards` (+1: +line), across the other
    // plate's thickness (its first face is on crossingPoint's plane) plus the clearance.
    const double start = middle, end = towards > 0 ? crossing.crossingTo + out : crossing.crossingFrom - out;
    auto at = [&](double t, double w) { return plus(crossing.crossingPoint, plus(scaled(line, t), scaled(axis, w))); };
    return SlotCut{plate,
                   {at(start, -clearance / 2), at(end, -clearance / 2), at(end, width + clearance / 2),
                    at(start, width + clearance / 2)}};
  };
  // The mover's slot opens behind it (it slides off the other plate forwards); the other's ahead.
  return {slot(mover, other, -sign), slot(other, mover, sign)};
}

namespace {

// A sliding dovetail made real: the housing, a rectangle on the face plate's face cut through the
// face layer it enters (as deep as the dovetail, run out past the open end), the two lips that
// overhang the tongue there, and the tongue on the edge plate. The clearance narrows and shortens
// the tongue (the housing keeps its size, so the verified plates and the made ones share it).
struct DovetailPieces {
  Loop housing;
  bool fromFirstFace = true;  // the housing enters the face plate from its first face
  Plate tongue;
  std::vector<Plate> lips;
};

DovetailPieces dovetailPieces(const std::vector<Plate>& plates, const DovetailCut& cut, double clearance) {
  const TenonSite& edge = cut.site.edge;
  const DovetailSection d = dovetailSection(plates, edge);
  const auto [s0, s1] = housingSpan(plates, cut);
  const double runOut = kMortiseMargin + plateThickness(plates[edge.mortisePlate]);
  const double cut0 = cut.openEnd == 0 ? s0 - runOut : s0, cut1 = cut.openEnd == 1 ? s1 + runOut : s1;
  const double low = d.centre - d.wide / 2, high = d.centre + d.wide / 2;
  const double narrowLow = d.centre - d.narrow / 2, narrowHigh = d.centre + d.narrow / 2;
  DovetailPieces pieces;
  pieces.housing = {jointPoint(plates, edge, cut0, low, 0), jointPoint(plates, edge, cut1, low, 0),
                    jointPoint(plates, edge, cut1, high, 0), jointPoint(plates, edge, cut0, high, 0)};
  pieces.fromFirstFace = dot(edge.intoMortise, plateThicknessAxis(plates[edge.mortisePlate])) > 0;
  pieces.lips = {prismAlongEdge(plates, edge, s0, s1, {{low, 0}, {narrowLow, 0}, {low, d.depth}}),
                 prismAlongEdge(plates, edge, s0, s1, {{narrowHigh, 0}, {high, 0}, {high, d.depth}})};
  const double play = clearance / 2;
  // The tongue runs along the contact only; the housing may run on past it to the open end.
  const double t0 = cut.openEnd == 1 ? s0 + play : edge.from, t1 = cut.openEnd == 0 ? s1 - play : edge.to;
  pieces.tongue = prismAlongEdge(plates, edge, t0, t1,
                                 {{narrowLow + play, 0}, {narrowHigh - play, 0}, {high - play, d.depth - play},
                                  {low + play, d.depth - play}});
  return pieces;
}

// Do two cuts share wood of the plate? Cuts that meet along a slanted edge share a sliver as wide
// as Clipper's 1e-4 mm grid, whose area grows with the edge's length (3e-3 mm^2 along 60 mm):
// they run into each other only where they share more than a thousandth of a square millimetre of
// the plate and the shared region is wider than a micrometre on average (twice its area over its
// perimeter). Judged pair by pair, by the designer (footprintsOverlap) and the cut alike: a test
// on the sum of three cuts' areas against their union's refused 438 complete plans of the LIZARD
// (slivers at a corner of plate 24) whose steps the designer had let through.
bool cutsShareWood(const Plate& plate, const Loop& a, const Loop& b, const PlaneFrame& frame) {
  constexpr double kLeastArea = 1e-3, kLeastWidth = 1e-3;
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths({a}, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths({b}, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths shared;
  clipper.Execute(ClipperLib::ctIntersection, shared, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  if (shared.empty()) return false;
  std::vector<Loop> loops;
  double perimeter = 0;
  for (const ClipperLib::Path& path : shared) {
    Loop loop;
    for (const ClipperLib::IntPoint& point : path) loop.push_back(frame.fromClipper(point));
    for (size_t k = 0; k < loop.size(); ++k) perimeter += norm(minus(loop[(k + 1) % loop.size()], loop[k]));
    loops.push_back(loop);
  }
  const double area = areaAgainst(loops, plate.bottom, frame, false);
  return area > kLeastArea && 2 * area / perimeter > kLeastWidth;
}

// Cuts of different joints must not run into each other.
void requireApart(const Plate& plate, const std::vector<Loop>& cuts, const PlaneFrame& frame) {
  for (size_t i = 0; i < cuts.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (cutsShareWood(plate, cuts[i], cuts[j], frame)) {
        throwBadInput("", "the mortises and slots cut into " + plateLabel(plate) + " run into each other");
      }
    }
  }
}

// The point of a plate's second face across from `point` of its first: a vertex as given keeps
// its partner; a point on a side's first-face edge has its partner on that side's second-face
// edge straight across the side (a cut through a mitred side); any other
// point lies where the plate is whole (mortiseKind, mitreTenonOf) and is straight across.
//
// `wall`, when given, is the direction of the cut's edge that meets the side at `point` (in the
// face): the cut's wall stands straight up along it, so the partner is where that wall meets the
// side's second-face edge (a wall square to the side gives the same point as the rule above; an
// oblique one, as a mitre slide's groove run out past a corner, would twist the face otherwise).
Vec3 secondFacePartner(const Plate& plate, const Vec3& point, const Vec3* wall = nullptr) {
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    for (size_t k = 0; k < plate.bottom[l].size(); ++k) {
      if (norm(minus(plate.bottom[l][k], point)) < 1e-3) return plate.top[l][k];
    }
  }
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& bottom = plate.bottom[l];
    for (size_t k = 0; k < bottom.size(); ++k) {
      const size_t next = (k + 1) % bottom.size();
      const Vec3 edge = minus(bottom[next], bottom[k]);
      const double length = norm(edge);
      if (length < 1e-9) continue;
      const double t = dot(minus(point, bottom[k]), edge) / (length * length);
      if (t < -1e-9 || t > 1 + 1e-9) continue;
      if (norm(minus(point, plus(bottom[k], scaled(edge, t)))) > 1e-3) continue;
      // Across the side, square to its edges (they are parallel): the cuts that reach a mitred
      // side meet it with walls square to it (a mitre tenon's notch).
      const Vec3 along = scaled(edge, 1 / length);
      const Vec3 offset = minus(plate.top[l][k], bottom[k]);
      const Vec3 square = plus(point, minus(offset, scaled(along, dot(offset, along))));
      if (wall == nullptr) return square;
      // Where the wall's plane (along the cut's edge and the plate's axis) meets the second-face edge.
      const Vec3 wallNormal = cross(*wall, plateThicknessAxis(plate));
      const double rate = dot(along, wallNormal);
      if (norm(wallNormal) < 1e-9 || std::abs(rate) < 1e-6 * norm(wallNormal)) return square;
      return plus(square, scaled(along, dot(minus(point, square), wallNormal) / rate));
    }
  }
  return plus(point, scaled(plateThicknessAxis(plate), plateThickness(plate)));
}

// The side whose first-face edge holds `point` strictly between its vertices: its loop and first
// vertex, or none.
std::optional<std::pair<size_t, size_t>> sideHolding(const Plate& plate, const Vec3& point) {
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& bottom = plate.bottom[l];
    for (size_t k = 0; k < bottom.size(); ++k) {
      if (norm(minus(bottom[k], point)) < 1e-3) return std::nullopt;
    }
    for (size_t k = 0; k < bottom.size(); ++k) {
      const Vec3 edge = minus(bottom[(k + 1) % bottom.size()], bottom[k]);
      const double length = norm(edge);
      if (length < 1e-9) continue;
      const double t = dot(minus(point, bottom[k]), edge) / (length * length);
      if (t > 1e-9 && t < 1 - 1e-9 && norm(minus(point, plus(bottom[k], scaled(edge, t)))) <= 1e-3)
        return std::make_pair(l, k);
    }
  }
  return std::nullopt;
}

// At a vertex of a cut face that lies on one of the plate's sides: the direction of the cut's
// edge that leaves the side there (to the neighbour off that side's line), or none.
std::unique_ptr<Vec3> cutWallAt(const Plate& plate, const Loop& loop, size_t i) {
  const std::optional<std::pair<size_t, size_t>> side = sideHolding(plate, loop[i]);
  if (!side) return nullptr;
  const Loop& bottom = plate.bottom[side->first];
  const Vec3& a = bottom[side->second];
  const Vec3 along = normalized(minus(bottom[(side->second + 1) % bottom.size()], a));
  for (const size_t j : {(i + 1) % loop.size(), (i + loop.size() - 1) % loop.size()}) {
    const Vec3 offset = minus(loop[j], a);
    const bool onTheLine = norm(minus(offset, scaled(along, dot(offset, along)))) <= 1e-3;
    if (!onTheLine) return std::make_unique<Vec3>(minus(loop[j], loop[i]));
  }
  return nullptr;
}

// The plate's solid between levels [from, to] along its thickness axis (0 = its first face), its
// face cut by `added` and `removed`: a prism.
Plate layerOf(const Plate& plate, const std::vector<Loop>& added, const std::vector<Loop>& removed, double from,
              double to) {
  const Vec3 axis = plateThicknessAxis(plate);
  Plate layer;
  layer.id = plate.id;
  layer.name = plate.name;
  const bool prism = isPrism(plate);
  for (const Loop& loop : cutFace(plate, added, removed)) {
    Loop bottom, top;
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3& point = loop[i];
      bottom.push_back(plus(point, scaled(axis, from)));
      top.push_back(plus(point, scaled(axis, to)));
      if (!prism) top.back() = secondFacePartner(plate, point, cutWallAt(plate, loop, i).get());
    }
    layer.bottom.push_back(bottom);
    layer.top.push_back(top);
  }
  return layer;
}

}  // namespace

namespace {

// 2D points of a mitre tenon's section plane (through `middle`, across the edge): x along
// `across`, y along the mitre's normal into the pocket plate.
using Flat = std::array<double, 2>;

// The part of a convex polygon where a*x + b*y <= c (Sutherland-Hodgman, one half-plane).
std::vector<Flat> clipHalfPlane(const std::vector<Flat>& polygon, double a, double b, double c) {
  std::vector<Flat> out;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Flat& p = polygon[i];
    const Flat& q = polygon[(i + 1) % polygon.size()];
    const double sp = a * p[0] + b * p[1] - c, sq = a * q[0] + b * q[1] - c;
    if (sp <= 0) out.push_back(p);
    if ((sp <= 0) != (sq <= 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

struct MitreFrame {
  Vec3 origin, across, normal, line;
  Vec3 at(const Flat& q, double s) const {
    return plus(origin, plus(scaled(across, q[0]), plus(scaled(normal, q[1]), scaled(line, s))));
  }
};

MitreFrame mitreFrame(const MitreTenon& tenon) {
  return {tenon.middle, tenon.across, normalized(cross(tenon.line, tenon.across)), tenon.line};
}

// The tenon's section: its root on the mitre face, its tip `depth` along `into`, less `play` on
// its sides and tip (the clearance).
std::vector<Flat> tenonSection(const MitreTenon& tenon, const MitreFrame& frame, double play) {
  const Flat into{dot(tenon.into, frame.across), dot(tenon.into, frame.normal)};
  const double h = tenon.halfHeight - play, d = tenon.depth - play;
  return {{-h, 0}, {h, 0}, {h + d * into[0], d * into[1]}, {-h + d * into[0], d * into[1]}};
}

// A tenon whose way out is oblique to the edge (paper: mortise-and-tenon for an edge within
// 45..135 degrees of d) is the section swept along `into`, not along the edge: a section point
// `depth` along `into` also lies depth * (into . line) further along the edge. Its ends then
// contain `into` and never block the way out.
double shiftAlongEdge(const MitreTenon& tenon, const MitreFrame& frame, const Flat& q) {
  const double slope = dot(tenon.into, tenon.line);
  if (slope == 0) return 0;
  return slope * q[1] / dot(tenon.into, frame.normal);
}

// Half the notch's length along the edge: the tenon's, and the shift of its tip beyond it plus a
// margin of wood for the pocket's end walls when it is oblique.
double notchHalfWidth(const MitreTenon& tenon) {
  const double slope = std::abs(dot(tenon.into, tenon.line));
  return slope == 0 ? tenon.halfWidth : tenon.halfWidth + slope * tenon.depth + kMortiseMargin;
}

// In the pocket plate's plane, across the edge, away from the mitre into the plate.
Vec3 pocketInward(const std::vector<Plate>& plates, const MitreTenon& tenon) {
  const Vec3 inward = normalized(cross(plateThicknessAxis(plates[tenon.pocketPlate]), tenon.line));
  return dot(inward, mitreFrame(tenon).normal) < 0 ? negated(inward) : inward;
}

// The notch through the pocket plate, in its plane: from beyond the mitre to past the pocket.
Loop pocketNotch(const std::vector<Plate>& plates, const MitreTenon& tenon) {
  const Plate& pocket = plates[tenon.pocketPlate];
  const Vec3 inward = pocketInward(plates, tenon);
  const double out = -2 * (plateThickness(pocket) + tenon.depth), in = tenon.notchReach;
  auto at = [&](double s, double u) { return plus(tenon.middle, plus(scaled(tenon.line, s), scaled(inward, u))); };
  const double half = notchHalfWidth(tenon);
  return {at(-half, out), at(half, out), at(half, in), at(-half, in)};
}

// The wood between an oblique pocket's slanted end (at `pocketEnd` along the edge at its root,
// shifted along the edge as it deepens) and the plane square to the edge at `flat`: in the plane
// of the edge and the tenon's depth a triangle, swept across the edge over the tenon's height.
Plate pocketEndWedge(const MitreTenon& tenon, double pocketEnd, double flat) {
  const double slope = dot(tenon.into, tenon.line);
  const Vec3 deeper = minus(tenon.into, scaled(tenon.line, slope));  // into, less its part along the edge
  auto at = [&](double across, double t, double s) {
    return plus(tenon.middle, plus(scaled(tenon.across, across), plus(scaled(deeper, t), scaled(tenon.line, s))));
  };
  // (t, s) corners: the flat plane at the root and the tip, the slanted end at the root and the tip,
  // one of which lies on the flat plane.
  std::vector<std::pair<double, double>> corners{{0, flat}, {0, pocketEnd}, {tenon.depth, pocketEnd + slope * tenon.depth},
                                                 {tenon.depth, flat}};
  std::vector<std::pair<double, double>> triangle;
  for (const auto& corner : corners) {
    if (triangle.empty() || std::abs(triangle.back().second - corner.second) > 1e-12 ||
        triangle.back().first != corner.first)
      triangle.push_back(corner);
  }
  if (triangle.size() > 3 && std::abs(triangle.back().second - triangle.front().second) < 1e-12 &&
      triangle.back().first == triangle.front().first)
    triangle.pop_back();
  Plate wedge;
  Loop first, second;
  for (const auto& [t, s] : triangle) {
    first.push_back(at(-tenon.halfHeight, t, s));
    second.push_back(at(tenon.halfHeight, t, s));
  }
  wedge.bottom = {first};
  wedge.top = {second};
  return wedge;
}

// The pocket plate's wood in the notch, less the pocket: a prism along the edge, and for an
// oblique tenon the wood between the notch's ends and the pocket's slanted ends.
// The pocket plate's wood in a notch at its mitre, in the section across the edge: beyond the
// mitre, between its faces, up to the notch's end, with `pocketSection` (root corners [0] and [1]
// on the mitre, their tips [3] and [2]) bitten out of its edge on the mitre, exactly (no grid
// rounding: the pocket's walls must be parallel to the way its tenon or tongue moves, or the
// contacts computed from them would block it by a rounding error).
std::vector<Flat> woodAroundPocket(const std::vector<Plate>& plates, const MitreTenon& tenon,
                                   const std::vector<Flat>& pocketSection) {
  const Plate& pocket = plates[tenon.pocketPlate];
  const MitreFrame frame = mitreFrame(tenon);
  const Vec3 axis = plateThicknessAxis(pocket);
  const Vec3 inward = pocketInward(plates, tenon);
  const double big = 10 * (plateThickness(pocket) + tenon.depth + tenon.halfHeight + tenon.notchReach);
  std::vector<Flat> wood{{-big, -big}, {big, -big}, {big, big}, {-big, big}};
  const Flat a{dot(axis, frame.across), dot(axis, frame.normal)}, u{dot(inward, frame.across), dot(inward, frame.normal)};
  const double level = dot(minus(tenon.middle, pocket.bottom[0][0]), axis);  // the section's origin's height
  wood = clipHalfPlane(wood, 0, -1, 0);                                     // beyond the mitre: y >= 0
  wood = clipHalfPlane(wood, -a[0], -a[1], level);                          // above the first face
  wood = clipHalfPlane(wood, a[0], a[1], plateThickness(pocket) - level);   // below the second
  wood = clipHalfPlane(wood, u[0], u[1], tenon.notchReach);                 // to the notch's end
  std::vector<Flat> bitten;
  const double onMitre = 1e-9 * big;
  for (size_t i = 0; i < wood.size(); ++i) {
    const Flat& p = wood[i];
    const Flat& q = wood[(i + 1) % wood.size()];
    bitten.push_back(p);
    if (std::abs(p[1]) > onMitre || std::abs(q[1]) > onMitre) continue;
    // Along this edge from p to q: the root corner met first, its tip, the other tip, the other root.
    const bool rising = q[0] > p[0];
    const Flat& low = pocketSection[0];
    const Flat& high = pocketSection[1];
    if (rising) {
      bitten.insert(bitten.end(), {low, pocketSection[3], pocketSection[2], high});
    } else {
      bitten.insert(bitten.end(), {high, pocketSection[2], pocketSection[3], low});
    }
  }
  if (bitten.size() != wood.size() + 4) {
    throwBadInput("", "the pocket of a mitre joint does not lie on the mitre of " + plateLabel(pocket));
  }
  return bitten;
}

std::vector<Plate> pocketSurround(const std::vector<Plate>& plates, const MitreTenon& tenon) {
  const MitreFrame frame = mitreFrame(tenon);
  const std::vector<Flat> pocketSection = tenonSection(tenon, frame, 0);
  const std::vector<Flat> bitten = woodAroundPocket(plates, tenon, pocketSection);
  const double half = notchHalfWidth(tenon);
  Plate surround;
  Loop first, second;
  for (const Flat& q : bitten) {
    first.push_back(frame.at(q, -half));
    second.push_back(frame.at(q, half));
  }
  surround.bottom = {first};
  surround.top = {second};
  std::vector<Plate> pieces{surround};
  if (half == tenon.halfWidth) return pieces;
  // Between each end of the notch and the pocket's slanted end, the pocket's section is wood: a
  // prism square to the edge up to where the slant begins, then a wedge (solids have parallel
  // faces: the wedge's are its two sides across the edge).
  const double slant = dot(tenon.into, tenon.line) * tenon.depth;  // how far the tip runs along the edge
  for (const double end : {-1.0, 1.0}) {
    const double pocketEnd = end * tenon.halfWidth;
    const double straightTo = end < 0 ? pocketEnd + std::min(0.0, slant) : pocketEnd + std::max(0.0, slant);
    Plate straight;
    Loop atNotch, atSlant;
    for (const Flat& q : pocketSection) {
      atNotch.push_back(frame.at(q, end * half));
      atSlant.push_back(frame.at(q, straightTo));
    }
    straight.bottom = {atNotch};
    straight.top = {atSlant};
    pieces.push_back(straight);
    // A slant below a micrometre leaves no wedge worth a solid.
    if (std::abs(slant) > 1e-3) pieces.push_back(pocketEndWedge(tenon, pocketEnd, straightTo));
  }
  return pieces;
}

Plate mitreTenonSolid(const MitreTenon& tenon, double clearance) {
  const MitreFrame frame = mitreFrame(tenon);
  const double play = clearance / 2, half = tenon.halfWidth - play;
  Plate solid;
  Loop first, second;
  for (const Flat& q : tenonSection(tenon, frame, play)) {
    const double shift = shiftAlongEdge(tenon, frame, q);
    first.push_back(frame.at(q, -half + shift));
    second.push_back(frame.at(q, half + shift));
  }
  solid.bottom = {first};
  solid.top = {second};
  return solid;
}

// The plate across a contact from `plate`, for contacts where two plates touch (not crossings);
// the check every joint on a touching pair opens with.
std::optional<int> touchingPartnerOf(const PlateContact& contact, int plate) {
  if (contact.crossing || (contact.a != plate && contact.b != plate)) return std::nullopt;
  return contact.a == plate ? contact.b : contact.a;
}

// How many of the two plates have a face on the contact: 0 where they meet edge to edge (a
// mitre), 2 where they lie face to face (a lap), 1 for an edge on a face (T and L joints).
int facesOnContact(const std::vector<Plate>& plates, const PlateContact& contact) {
  int faces = 0;
  for (int plate : {contact.a, contact.b})
    faces += std::abs(dot(contact.normal, plateThicknessAxis(plates[plate]))) > 1 - kSquare ? 1 : 0;
  return faces;
}

}  // namespace

std::optional<MitreTenon> mitreTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                       const Vec3& into) {
  const std::optional<int> partner = touchingPartnerOf(contact, tenonPlate);
  // Edge to edge: neither plate's face lies on the contact (those are T joints, tenonSiteOf).
  if (!partner || facesOnContact(plates, contact) != 0) return std::nullopt;
  MitreTenon tenon;
  tenon.tenonPlate = tenonPlate;
  tenon.pocketPlate = *partner;
  const Vec3 normal = contact.a == tenonPlate ? contact.normal : negated(contact.normal);
  const Plate& pocket = plates[tenon.pocketPlate];
  tenon.line = normalized(contact.edgeDirection);
  tenon.into = normalized(into);
  // The paper's mortise-and-tenon: the edge within 45..135 degrees of the way out.
  if (std::abs(dot(tenon.into, tenon.line)) > std::sqrt(0.5) + 1e-9 || dot(tenon.into, normal) < 0.05) return std::nullopt;
  tenon.across = normalized(cross(normal, tenon.line));
  const auto [s0, s1] = extentAlong(contact.region, contact.region[0], tenon.line);
  const auto [x0, x1] = extentAlong(contact.region, contact.region[0], tenon.across);
  tenon.halfWidth = (s1 - s0) / 6;   // a third of the mitre's length
  tenon.halfHeight = (x1 - x0) / 8;  // a quarter of its height: room for the pocket in thin plates
  if (2 * tenon.halfWidth < kShortestJoint || 2 * tenon.halfHeight < 1) return std::nullopt;
  tenon.middle = plus(contact.region[0], plus(scaled(tenon.line, (s0 + s1) / 2), scaled(tenon.across, (x0 + x1) / 2)));
  // As deep as the pocket plate holds it with a margin of wood on both faces, at most its thickness.
  const Vec3 axis = plateThicknessAxis(pocket);
  const double thickness = plateThickness(pocket), rate = dot(tenon.into, axis);
  tenon.depth = thickness;
  for (const double side : {-1.0, 1.0}) {
    const double height = dot(minus(plus(tenon.middle, scaled(tenon.across, side * tenon.halfHeight)), pocket.bottom[0][0]), axis);
    if (height < kMortiseMargin || height > thickness - kMortiseMargin) return std::nullopt;
    if (rate > 1e-9) tenon.depth = std::min(tenon.depth, (thickness - kMortiseMargin - height) / rate);
    if (rate < -1e-9) tenon.depth = std::min(tenon.depth, (height - kMortiseMargin) / -rate);
  }
  constexpr double kShallowestPocket = 2.0;  // mm
  if (tenon.depth < kShallowestPocket) return std::nullopt;
  // An oblique tenon's notch runs further along the edge: it must stay on the mitre.
  if (notchHalfWidth(tenon) > (s1 - s0) / 2 - kMortiseMargin) {
    tenon.halfWidth -= notchHalfWidth(tenon) - ((s1 - s0) / 2 - kMortiseMargin);
    if (2 * tenon.halfWidth < kShortestJoint) return std::nullopt;
  }
  // The notch runs past the pocket and past the mitre (its cut ends where the plate is whole).
  const Vec3 inwardDirection = pocketInward(plates, tenon);
  const MitreFrame sectionFrame = mitreFrame(tenon);
  for (const Flat& q : tenonSection(tenon, sectionFrame, 0))
    tenon.notchReach = std::max(tenon.notchReach, dot(minus(sectionFrame.at(q, 0), tenon.middle), inwardDirection));
  double mitreReach = 0;  // where the mitre ends and the plate is whole again
  for (const Vec3& p : contact.region) mitreReach = std::max(mitreReach, dot(minus(p, tenon.middle), inwardDirection));
  tenon.notchReach = std::max(tenon.notchReach, mitreReach) + kMortiseMargin;
  // Past the mitre, the notch's end must lie in the pocket plate where it is whole (away from its
  // other sides), so that its cut ends in wood.
  auto at = [&](double s, double u) {
    return plus(tenon.middle, plus(scaled(tenon.line, s), scaled(inwardDirection, u)));
  };
  const double half = notchHalfWidth(tenon);
  const Loop end{at(-half, mitreReach), at(half, mitreReach), at(half, tenon.notchReach), at(-half, tenon.notchReach)};
  const PlaneFrame frame(pocket.bottom[0][0], axis);
  if (areaAgainst({end}, faceRegion(pocket, ClipperLib::ctIntersection), frame, true) > 1e-6) return std::nullopt;
  return tenon;
}

namespace {

// The slide seen as a pocket in the slide plate (the tongue plate holding the "tenon"): the frame,
// the inward direction and the wood around the groove are a mitre tenon's.
MitreTenon grooveView(const MitreSlide& slide) {
  MitreTenon view;
  view.tenonPlate = slide.tonguePlate;
  view.pocketPlate = slide.slidePlate;
  view.line = slide.line;
  view.into = slide.into;
  view.middle = slide.middle;
  view.across = slide.across;
  view.halfHeight = slide.halfHeight;
  view.depth = slide.depth;
  view.notchReach = slide.notchReach;
  return view;
}

// The tongue's section (root corners [0], [1] on the mitre, their tips [3], [2]), a dovetail:
// `depth` along `into`, wider at its tip along the root, less `play` all round (the clearance).
std::vector<Flat> slideSection(const MitreSlide& slide, double play) {
  const double ix = dot(slide.into, slide.across), iy = dot(slide.into, slide.mitreNormal);
  const double h = slide.halfHeight - play, d = slide.depth - play;
  const double tip = slide.halfHeight + slide.lean * slide.depth - play;
  return {{-h, 0}, {h, 0}, {d * ix + tip, d * iy}, {d * ix - tip, d * iy}};
}

// The notch through the slide plate, in its plane (MitreSlide::notch).
Loop slideNotch(const std::vector<Plate>&, const MitreSlide& slide) { return slide.notch; }

// A point of the slide plate's plane: s along the edge from the middle, u inward.
Vec3 at0(const MitreSlide& slide, const Vec3& inward, double s, double u) {
  return plus(slide.middle, plus(scaled(slide.line, s), scaled(inward, u)));
}

Plate prismAlongEdge(const MitreTenon& view, const std::vector<Flat>& section, double from, double to) {
  const MitreFrame frame = mitreFrame(view);
  Plate prism;
  Loop first, second;
  for (const Flat& q : section) {
    first.push_back(frame.at(q, from));
    second.push_back(frame.at(q, to));
  }
  prism.bottom = {first};
  prism.top = {second};
  return prism;
}

// Where the slide plate's other sides come within the notch's reach of its mitre, along the edge:
// the nearest such point behind the middle (s < 0) and ahead (s > 0), from both its faces.
std::pair<double, double> cornersAlongEdge(const Plate& plate, const MitreSlide& slide, const Vec3& inward,
                                           double mitreFrom, double mitreTo) {
  double behind = -HUGE_VAL, ahead = HUGE_VAL;
  for (const std::vector<Loop>* face : {&plate.bottom, &plate.top}) {
    for (const Loop& loop : *face) {
      for (size_t k = 0; k < loop.size(); ++k) {
        const Vec3 a = minus(loop[k], slide.middle), b = minus(loop[(k + 1) % loop.size()], slide.middle);
        const double sa = dot(a, slide.line), sb = dot(b, slide.line), ua = dot(a, inward), ub = dot(b, inward);
        // The mitre's own edges (along the line, between its outer and inner lines) do not count.
        const bool alongLine = std::abs(ua - ub) < 1e-6 * (1 + std::abs(sa - sb));
        if (alongLine && ua >= mitreFrom - 1e-3 && ua <= mitreTo + 1e-3) continue;
        // The part of the edge with u <= notchReach.
        double t0 = 0, t1 = 1;
        if (ua > slide.notchReach && ub > slide.notchReach) continue;
        if (ua > slide.notchReach) t0 = (slide.notchReach - ua) / (ub - ua);
        if (ub > slide.notchReach) t1 = (slide.notchReach - ua) / (ub - ua);
        for (const double t : {t0, t1}) {
          const double sv = sa + t * (sb - sa);
          if (sv < 0) behind = std::max(behind, sv);
          if (sv > 0) ahead = std::min(ahead, sv);
        }
      }
    }
  }
  return {behind, ahead};
}

}  // namespace

std::optional<MitreSlide> mitreSlideOf(const std::vector<Plate>& plates, const PlateContact& contact, int slidePlate,
                                       const Vec3& d) {
  const std::optional<int> partner = touchingPartnerOf(contact, slidePlate);
  // Edge to edge: neither face on the contact (those are T joints and laps).
  if (!partner || contact.region.size() < 3 || facesOnContact(plates, contact) != 0) return std::nullopt;
  MitreSlide slide;
  slide.slidePlate = slidePlate;
  slide.tonguePlate = *partner;
  const Plate& plate = plates[slidePlate];
  const Vec3 edge = normalized(contact.edgeDirection);
  if (std::abs(std::abs(dot(edge, normalized(d))) - 1) > 1e-12) return std::nullopt;  // along the edge only
  // The way out itself, and the mitre's normal made square to it: every face of the groove but its
  // stop then lies along d to rounding of doubles (the edge and d may differ by 1e-9).
  slide.line = normalized(d);
  const Vec3 normal = contact.a == slidePlate ? negated(contact.normal) : contact.normal;  // tongue -> slide plate
  slide.mitreNormal = normalized(minus(normal, scaled(slide.line, dot(normal, slide.line))));
  slide.across = normalized(cross(slide.mitreNormal, slide.line));
  slide.into = normalized(cross(plateThicknessAxis(plate), slide.line));
  if (dot(slide.into, slide.mitreNormal) < 0) slide.into = negated(slide.into);
  if (dot(slide.into, slide.mitreNormal) < 0.05) return std::nullopt;  // the mitre all but lies in the plate
  const auto [s0, s1] = extentAlong(contact.region, contact.region[0], slide.line);
  const auto [x0, x1] = extentAlong(contact.region, contact.region[0], slide.across);
  slide.middle = plus(contact.region[0], plus(scaled(slide.line, (s0 + s1) / 2), scaled(slide.across, (x0 + x1) / 2)));
  const double halfLength = (s1 - s0) / 2;
  slide.halfHeight = (x1 - x0) / 8;  // a quarter of the mitre's height, as a mitre tenon's root
  slide.lean = kDovetailSlope;
  if (2 * slide.halfHeight < 1) return std::nullopt;
  // As deep as the slide plate holds the groove with a millimetre of wood on both faces.
  const Vec3 axis = plateThicknessAxis(plate);
  const double thickness = plateThickness(plate);
  auto fits = [&](double depth) {
    slide.depth = depth;
    for (const Flat& q : slideSection(slide, 0)) {
      const Vec3 point = plus(slide.middle, plus(scaled(slide.across, q[0]), scaled(slide.mitreNormal, q[1])));
      const double height = dot(minus(point, plate.bottom[0][0]), axis);
      if (height < kMortiseMargin || height > thickness - kMortiseMargin) return false;
    }
    return true;
  };
  constexpr double kShallowestGroove = 2.0;  // mm
  double depth = thickness;
  while (depth >= kShallowestGroove && !fits(depth)) depth *= 0.8;
  if (depth < kShallowestGroove) return std::nullopt;
  // The notch runs past the groove and past the mitre.
  const MitreTenon view = grooveView(slide);
  const Vec3 inward = pocketInward(plates, view);
  const MitreFrame frame = mitreFrame(view);
  double mitreFrom = HUGE_VAL, mitreTo = -HUGE_VAL;  // the mitre's outer and inner lines
  for (const Vec3& p : contact.region) {
    mitreFrom = std::min(mitreFrom, dot(minus(p, slide.middle), inward));
    mitreTo = std::max(mitreTo, dot(minus(p, slide.middle), inward));
  }
  for (const Flat& q : slideSection(slide, 0))
    slide.notchReach = std::max(slide.notchReach, dot(minus(frame.at(q, 0), slide.middle), inward));
  slide.notchReach = std::max(slide.notchReach, mitreTo) + kMortiseMargin;
  // Along the edge: the wood around the groove only where the plate's other sides are clear of the
  // notch; the groove stopped a plate thickness (10 mm at least) short of the end ahead.
  const auto [behind, ahead] = cornersAlongEdge(plate, slide, inward, mitreFrom, mitreTo);
  slide.woodFrom = std::max(behind, -halfLength) + kMortiseMargin;
  slide.tongueFrom = slide.woodFrom;
  slide.tongueTo = std::min(halfLength - std::max(10.0, thickness), ahead - kMortiseMargin);
  constexpr double kShortestGroove = 10.0;  // mm
  if (slide.tongueTo - slide.woodFrom < kShortestGroove) return std::nullopt;
  const PlaneFrame planeFrame(plate.bottom[0][0], axis);
  // The notch: the band at the mitre from the groove's stop back past all of the plate, out
  // through its side behind the corner (the tongue leaves through it; where the band's inner edge
  // crosses that mitred side, the cut's wall meets it along the edge: secondFacePartner).
  double rearmost = 0;
  for (const std::vector<Loop>* face : {&plate.bottom, &plate.top})
    for (const Loop& loop : *face)
      for (const Vec3& p : loop) rearmost = std::min(rearmost, dot(minus(p, slide.middle), slide.line));
  slide.notchFrom = rearmost - 10;
  const double out = -2 * (thickness + slide.depth);
  slide.notch = {at0(slide, inward, slide.notchFrom, out), at0(slide, inward, slide.tongueTo, out),
                 at0(slide, inward, slide.tongueTo, slide.notchReach), at0(slide, inward, slide.notchFrom, slide.notchReach)};
  // The band's inner edge leaves the plate behind through one side on both faces (its wall meets
  // that side: secondFacePartner); where a face's outline turns between them, it would not.
  auto sideCrossedBehind = [&](const Loop& loop) {
    int side = -1;
    double nearest = -HUGE_VAL;
    for (size_t k = 0; k < loop.size(); ++k) {
      const Vec3 a = minus(loop[k], slide.middle), b = minus(loop[(k + 1) % loop.size()], slide.middle);
      const double ua = dot(a, inward), ub = dot(b, inward);
      if ((ua - slide.notchReach) * (ub - slide.notchReach) > 0 || ua == ub) continue;
      const double t = (slide.notchReach - ua) / (ub - ua);
      const double sv = dot(a, slide.line) + t * (dot(b, slide.line) - dot(a, slide.line));
      if (sv < slide.woodFrom && sv > nearest) {
        nearest = sv;
        side = static_cast<int>(k);
      }
    }
    return side;
  };
  if (sideCrossedBehind(plate.bottom[0]) != sideCrossedBehind(plate.top[0]) || sideCrossedBehind(plate.bottom[0]) < 0)
    return std::nullopt;
  // A plate whose outline comes back to the band behind (not convex there) would fall apart.
  {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(clipperPaths(plate.bottom, planeFrame), ClipperLib::ptSubject, true);
    clipper.AddPaths(clipperPaths({slide.notch}, planeFrame), ClipperLib::ptClip, true);
    ClipperLib::PolyTree left;
    clipper.Execute(ClipperLib::ctDifference, left, ClipperLib::pftEvenOdd, ClipperLib::pftNonZero);
    if (left.ChildCount() != 1) return std::nullopt;
  }
  // The notch's end past the mitre lies where the plate is whole, so that its cut ends in wood.
  auto at = [&](double s, double u) { return plus(slide.middle, plus(scaled(slide.line, s), scaled(inward, u))); };
  const Loop end{at(slide.woodFrom, mitreTo), at(slide.tongueTo, mitreTo), at(slide.tongueTo, slide.notchReach),
                 at(slide.woodFrom, slide.notchReach)};
  if (areaAgainst({end}, faceRegion(plate, ClipperLib::ctIntersection), planeFrame, true) > 1e-6) return std::nullopt;
  return slide;
}

std::vector<Vec3> mitreSlideFaceNormals(const MitreSlide& slide) {
  // In the section (x along `across`, y along the mitre's normal) the flanks run from the root
  // corners along (ix -+ lean, iy); their normals, from the slide plate into the tongue.
  const double ix = dot(slide.into, slide.across), iy = dot(slide.into, slide.mitreNormal);
  const Vec3 low = normalized(minus(scaled(slide.across, iy), scaled(slide.mitreNormal, ix - slide.lean)));
  const Vec3 high = normalized(plus(scaled(slide.across, -iy), scaled(slide.mitreNormal, ix + slide.lean)));
  return {negated(slide.mitreNormal), low, high, negated(slide.line)};
}

CutFootprint mitreSlideFootprint(const std::vector<Plate>& plates, const MitreSlide& slide) {
  return {slide.slidePlate, 3, slideNotch(plates, slide)};
}

Loop FaceTenon::footprint(double grow) const {
  auto at = [&](double s, double t) { return plus(origin, plus(scaled(u, s), scaled(v, t))); };
  return {at(s0 - grow, t0 - grow), at(s1 + grow, t0 - grow), at(s1 + grow, t1 + grow), at(s0 - grow, t1 + grow)};
}

std::optional<FaceTenon> faceTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                     const Vec3& d) {
  const std::optional<int> partner = touchingPartnerOf(contact, tenonPlate);
  // A lap: the contact lies on a face of both plates.
  if (!partner || contact.region.size() < 3 || facesOnContact(plates, contact) != 2) return std::nullopt;
  FaceTenon tenon;
  tenon.tenonPlate = tenonPlate;
  tenon.mortisePlate = *partner;
  const Plate& mortise = plates[tenon.mortisePlate];
  if (!isPrism(plates[tenonPlate]) || !isPrism(mortise)) return std::nullopt;
  tenon.out = contact.a == tenonPlate ? negated(contact.normal) : contact.normal;
  if (dot(normalized(d), tenon.out) < 1 - 1e-9) return std::nullopt;  // straight off the lap only
  tenon.u = normalized(contact.edgeDirection);
  if (std::abs(dot(tenon.u, tenon.out)) > kSquare) return std::nullopt;
  tenon.v = normalized(cross(tenon.out, tenon.u));
  tenon.origin = contact.region[0];
  const auto [s0, s1] = extentAlong(contact.region, tenon.origin, tenon.u);
  const auto [t0, t1] = extentAlong(contact.region, tenon.origin, tenon.v);
  // The middle third each way: wood all round the mortise, and room for other joints.
  tenon.s0 = s0 + (s1 - s0) / 3;
  tenon.s1 = s1 - (s1 - s0) / 3;
  tenon.t0 = t0 + (t1 - t0) / 3;
  tenon.t1 = t1 - (t1 - t0) / 3;
  if (tenon.s1 - tenon.s0 < kShortestJoint || tenon.t1 - tenon.t0 < kShortestJoint) return std::nullopt;
  tenon.depth = plateThickness(mortise) / 3;  // as deep as a dovetail's housing: both faces may hold one
  // The block inside the lap (a lap that is not a rectangle may not hold the middle third).
  const PlaneFrame frame(tenon.origin, tenon.out);
  if (areaAgainst({tenon.footprint(0)}, {contact.region}, frame, true) > 1e-6) return std::nullopt;
  return tenon;
}

std::vector<Vec3> faceTenonFaceNormals(const FaceTenon& tenon) {
  return {negated(tenon.out), tenon.u, negated(tenon.u), tenon.v, negated(tenon.v)};
}

// The block on the tenon plate: its footprint on the lap, into the mortise plate by the depth.
Plate faceTenonBlock(const FaceTenon& tenon) {
  Plate block;
  Loop onLap = tenon.footprint(0), inside;
  for (const Vec3& p : onLap) inside.push_back(plus(p, scaled(tenon.out, -tenon.depth)));
  block.bottom = {onLap};
  block.top = {inside};
  return block;
}

// The mortise plate's face the lap lies on: 0 its first, 1 its second.
int faceTenonMortiseFace(const std::vector<Plate>& plates, const FaceTenon& tenon) {
  return dot(tenon.out, plateThicknessAxis(plates[tenon.mortisePlate])) > 0 ? 1 : 0;
}

CutFootprint faceTenonFootprint(const std::vector<Plate>& plates, const FaceTenon& tenon) {
  return {tenon.mortisePlate, faceTenonMortiseFace(plates, tenon) == 0 ? 1 : 2, tenon.footprint(0)};
}

std::vector<Vec3> mitreTenonFaceNormals(const MitreTenon& tenon) {
  const MitreFrame frame = mitreFrame(tenon);
  Vec3 side = normalized(cross(tenon.into, tenon.line));
  // Its ends contain `into` (shiftAlongEdge): across the edge's direction less its part along into.
  const Vec3 end = normalized(minus(tenon.line, scaled(tenon.into, dot(tenon.into, tenon.line))));
  return {frame.normal, side, negated(side), end, negated(end)};
}

CutFootprint mitreTenonFootprint(const std::vector<Plate>& plates, const MitreTenon& tenon) {
  return {tenon.pocketPlate, 3, pocketNotch(plates, tenon)};
}

std::vector<CutFootprint> tenonFootprints(const std::vector<Plate>& plates, const TenonSite& site,
                                          const JointCutOptions& options) {
  std::vector<CutFootprint> footprints;
  for (const auto& [start, end] : tenonSpans(plates, site, options)) {
    footprints.push_back({site.mortisePlate, 3, mortiseOf(plates, site, start, end, options.clearance)});
  }
  return footprints;
}

CutFootprint dovetailFootprint(const std::vector<Plate>& plates, const DovetailCut& cut) {
  const DovetailPieces pieces = dovetailPieces(plates, cut, 0);
  return {cut.site.edge.mortisePlate, pieces.fromFirstFace ? 1 : 2, pieces.housing};
}

CutFootprint slotFootprint(const SlotCut& slot) { return {slot.plate, 3, slot.rectangle}; }

bool footprintsOverlap(const std::vector<Plate>& plates, const CutFootprint& a, const CutFootprint& b) {
  if (a.plate != b.plate || (a.faces & b.faces) == 0) return false;
  const Plate& plate = plates[a.plate];
  return cutsShareWood(plate, a.region, b.region, PlaneFrame(plate.bottom[0][0], plateThicknessAxis(plate)));
}

std::vector<Plate> cutTenonJoints(const std::vector<Plate>& plates, const std::vector<TenonSite>& sites,
                                  const JointCutOptions& options, const std::vector<SlotCut>& slots,
                                  const std::vector<DovetailCut>& dovetails,
                                  const std::vector<MitreTenon>& mitreTenons,
                                  const std::vector<FaceTenon>& faceTenons,
                                  const std::vector<MitreSlide>& mitreSlides) {
  std::vector<std::vector<Loop>> added(plates.size()), removed(plates.size());
  // Dovetail housings per plate and face (0: first face, 1: second), and the solids they attach.
  std::vector<std::array<std::vector<Loop>, 2>> housings(plates.size());
  std::vector<std::array<double, 2>> housingDepth(plates.size(), {0.0, 0.0});
  std::vector<std::vector<Plate>> attached(plates.size());
  for (const DovetailCut& cut : dovetails) {
    const int housingPlate = cut.site.edge.mortisePlate;
    DovetailPieces pieces = dovetailPieces(plates, cut, options.clearance);
    const int face = pieces.fromFirstFace ? 0 : 1;
    housings[housingPlate][face].push_back(pieces.housing);
    housingDepth[housingPlate][face] = dovetailSection(plates, cut.site.edge).depth;
    for (Plate& lip : pieces.lips) attached[housingPlate].push_back(std::move(lip));
    attached[cut.site.edge.tenonPlate].push_back(std::move(pieces.tongue));
  }
  for (const MitreTenon& tenon : mitreTenons) {
    removed[tenon.pocketPlate].push_back(pocketNotch(plates, tenon));
    for (Plate& piece : pocketSurround(plates, tenon)) attached[tenon.pocketPlate].push_back(std::move(piece));
    attached[tenon.tenonPlate].push_back(mitreTenonSolid(tenon, options.clearance));
  }
  for (const MitreSlide& slide : mitreSlides) {
    const MitreTenon view = grooveView(slide);
    removed[slide.slidePlate].push_back(slideNotch(plates, slide));
    attached[slide.slidePlate].push_back(
        prismAlongEdge(view, woodAroundPocket(plates, view, slideSection(slide, 0)), slide.woodFrom, slide.tongueTo));
    attached[slide.tonguePlate].push_back(
        prismAlongEdge(view, slideSection(slide, options.clearance / 2), slide.tongueFrom, slide.tongueTo - options.clearance / 2));
  }
  for (const FaceTenon& tenon : faceTenons) {
    // A blind mortise is a housing from the lap's face, as deep as the block (a dovetail's depth).
    const int face = faceTenonMortiseFace(plates, tenon);
    housings[tenon.mortisePlate][face].push_back(tenon.footprint(options.clearance / 2));
    housingDepth[tenon.mortisePlate][face] = tenon.depth;
    attached[tenon.tenonPlate].push_back(faceTenonBlock(tenon));
  }
  for (const SlotCut& slot : slots) removed[slot.plate].push_back(slot.rectangle);
  for (const TenonSite& site : sites) {
    for (const auto& [start, end] : tenonSpans(plates, site, options)) {
      added[site.tenonPlate].push_back(tenonOf(plates, site, start, end));
      removed[site.mortisePlate].push_back(mortiseOf(plates, site, start, end, options.clearance));
    }
  }
  std::vector<Plate> jointed = plates;
  for (size_t p = 0; p < plates.size(); ++p) {
    const Plate& plate = plates[p];
    const bool housed = !housings[p][0].empty() || !housings[p][1].empty();
    if (added[p].empty() && removed[p].empty() && !housed) {
      jointed[p].attached = std::move(attached[p]);
      continue;
    }
    const PlaneFrame frame(plate.bottom[0][0], plateThicknessAxis(plate));
    requireApart(plate, removed[p], frame);
    const double thickness = plateThickness(plate);
    // A plate with dovetail housings is its middle layer, with the layers at its faces that the
    // housings are cut through (their floor is the middle layer) attached, and the lips.
    const double first = housingDepth[p][0], second = thickness - housingDepth[p][1];
    jointed[p] = layerOf(plate, added[p], removed[p], first, second);
    for (int face = 0; face < 2; ++face) {
      if (housings[p][face].empty()) continue;
      std::vector<Loop> cuts = removed[p];
      cuts.insert(cuts.end(), housings[p][face].begin(), housings[p][face].end());
      requireApart(plate, cuts, frame);
      jointed[p].attached.push_back(face == 0 ? layerOf(plate, added[p], cuts, 0, first)
                                              : layerOf(plate, added[p], cuts, second, thickness));
    }
    for (Plate& solid : attached[p]) jointed[p].attached.push_back(std::move(solid));
  }
  return jointed;
}

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
    if (std::abs(twiceArea) < 1e-9) continue;  // edge-on: its solid is seen through its neighbours
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

bool meshCollidesAlong(const TriangleMesh& mover, const TriangleMesh& obstacle, const Vec3& d, double tolerance) {
  if (mover.vertices.empty() || obstacle.vertices.empty()) return false;
  // Boxes first: the obstacle must reach into the box the mover sweeps.
  for (int k = 0; k < 3; ++k) {
    double moverLo = HUGE_VAL, moverHi = -HUGE_VAL, lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const auto& p : mover.vertices) moverLo = std::min(moverLo, p[k]), moverHi = std::max(moverHi, p[k]);
    for (const auto& p : obstacle.vertices) lo = std::min(lo, p[k]), hi = std::max(hi, p[k]);
    if (d[k] > 1e-12) moverHi = HUGE_VAL;
    if (d[k] < -1e-12) moverLo = -HUGE_VAL;
    if (hi <= moverLo + tolerance || moverHi <= lo + tolerance) return false;
  }
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
