// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/plate_cuts.h"

#include <cmath>
#include <optional>
#include <utility>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/exact_vertices.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plate_shape.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

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
    throwBadInput("", "the joints cut " + geometry::plateName(plate) + " into " + std::to_string(tree.ChildCount()) + " pieces");
  }
  const ClipperLib::PolyNode* outer = tree.Childs[0];
  const ExactVertices exact(frame, {&plate.bottom, &added, &removed});
  std::vector<Loop> loops;
  loops.push_back(exact.loop(outer->Contour));
  for (const ClipperLib::PolyNode* hole : outer->Childs) {
    if (hole->ChildCount() > 0) throwBadInput("", "the joints cut a loose piece inside " + geometry::plateName(plate));
    loops.push_back(exact.loop(hole->Contour));
  }
  return loops;
}

// Do two cuts share wood of the plate? Cuts that meet along a slanted edge share a sliver as wide
// as Clipper's 1e-4 mm grid, whose area grows with the edge's length (3e-3 mm^2 along 60 mm):
// they run into each other only where they share more than a thousandth of a square millimetre of
// the plate and the shared region is wider than a micrometre on average (twice its area over its
// perimeter). Judged pair by pair, by the designer (footprintsOverlap) and the cut alike: a test on
// the sum of several cuts' areas against their union's would add up slivers at a corner and refuse
// complete plans whose steps the designer let through.
bool cutsShareWood(const Plate& plate, const Loop& a, const Loop& b, const PlaneFrame& frame) {
  constexpr double kLeastArea = tolerance::kLeastSharedAreaMm2, kLeastWidth = tolerance::kLeastSharedWidthMm;
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
        throwBadInput("", "the mortises and slots cut into " + geometry::plateName(plate) + " run into each other");
      }
    }
  }
}

// Does `point` lie on the segment from a to b (within kSamePointMm)? A segment of no length holds
// nothing.
bool liesOnSegment(const Vec3& point, const Vec3& a, const Vec3& b) {
  const Vec3 edge = minus(b, a);
  const double length = norm(edge);
  if (length < tolerance::kZeroLengthMm) return false;
  const double t = dot(minus(point, a), edge) / (length * length);
  if (t < -tolerance::kSegmentParameter || t > 1 + tolerance::kSegmentParameter) return false;
  return norm(minus(point, plus(a, scaled(edge, t)))) <= tolerance::kSamePointMm;
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
      if (norm(minus(plate.bottom[l][k], point)) < tolerance::kSamePointMm) return plate.top[l][k];
    }
  }
  for (size_t l = 0; l < plate.bottom.size(); ++l) {
    const Loop& bottom = plate.bottom[l];
    for (size_t k = 0; k < bottom.size(); ++k) {
      const size_t next = (k + 1) % bottom.size();
      if (!liesOnSegment(point, bottom[k], bottom[next])) continue;
      const Vec3 edge = minus(bottom[next], bottom[k]);
      const double length = norm(edge);
      // Across the side, square to its edges (they are parallel): the cuts that reach a mitred
      // side meet it with walls square to it (a mitre tenon's notch).
      const Vec3 along = scaled(edge, 1 / length);
      const Vec3 offset = minus(plate.top[l][k], bottom[k]);
      const Vec3 square = plus(point, minus(offset, scaled(along, dot(offset, along))));
      if (wall == nullptr) return square;
      // Where the wall's plane (along the cut's edge and the plate's axis) meets the second-face edge.
      const Vec3 wallNormal = cross(*wall, plateThicknessAxis(plate));
      const double rate = dot(along, wallNormal);
      if (norm(wallNormal) < tolerance::kZeroLengthMm || std::abs(rate) < tolerance::kSquareCosine * norm(wallNormal))
        return square;
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
      if (norm(minus(bottom[k], point)) < tolerance::kSamePointMm) return std::nullopt;
    }
    for (size_t k = 0; k < bottom.size(); ++k) {
      const Vec3 edge = minus(bottom[(k + 1) % bottom.size()], bottom[k]);
      const double length = norm(edge);
      if (length < tolerance::kZeroLengthMm) continue;
      const double t = dot(minus(point, bottom[k]), edge) / (length * length);
      if (t > tolerance::kSegmentParameter && t < 1 - tolerance::kSegmentParameter &&
          norm(minus(point, plus(bottom[k], scaled(edge, t)))) <= tolerance::kSamePointMm)
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
    const bool onTheLine = norm(minus(offset, scaled(along, dot(offset, along)))) <= tolerance::kSamePointMm;
    if (!onTheLine) return std::make_unique<Vec3>(minus(loop[j], loop[i]));
  }
  return nullptr;
}

// The partner on the second face of a cut face's vertex that a slanted cut made: its own
// vertex's partner, or where its wall (the plane of its first- and second-face edges) meets the
// second-face edge of the plate's side the vertex lies on; none for other vertices.
std::optional<Vec3> slantedPartner(const Plate& plate, const std::vector<std::array<Loop, 2>>& slanted,
                                   const Vec3& point) {
  for (const std::array<Loop, 2>& cut : slanted) {
    const Loop& first = cut[0];
    for (size_t k = 0; k < first.size(); ++k) {
      if (norm(minus(first[k], point)) < tolerance::kSamePointMm) return cut[1][k];
    }
  }
  const std::optional<std::pair<size_t, size_t>> side = sideHolding(plate, point);
  if (!side) return std::nullopt;
  const Vec3& top0 = plate.top[side->first][side->second];
  const Vec3& top1 = plate.top[side->first][(side->second + 1) % plate.top[side->first].size()];
  for (const std::array<Loop, 2>& cut : slanted) {
    const Loop& first = cut[0];
    for (size_t k = 0; k < first.size(); ++k) {
      const size_t next = (k + 1) % first.size();
      if (!liesOnSegment(point, first[k], first[next])) continue;
      const Vec3 edge = minus(first[next], first[k]);
      const Vec3 wallNormal = cross(edge, minus(cut[1][k], first[k]));
      const double rate = dot(minus(top1, top0), wallNormal);
      if (std::abs(rate) < tolerance::kSquareCosine * norm(wallNormal) * norm(minus(top1, top0))) continue;
      return plus(top0, scaled(minus(top1, top0), dot(minus(first[k], top0), wallNormal) / rate));
    }
  }
  return std::nullopt;
}

// The plate's solid between levels [from, to] along its thickness axis (0 = its first face), its
// face cut by `added`, `removed` and `slanted` (whose first-face outlines are among `removed`;
// only through the whole plate): a prism where nothing is slanted.
Plate layerOf(const Plate& plate, const std::vector<Loop>& added, const std::vector<Loop>& removed, double from,
              double to, const std::vector<std::array<Loop, 2>>& slanted = {}) {
  const Vec3 axis = plateThicknessAxis(plate);
  Plate layer;
  layer.id = plate.id;
  layer.name = plate.name;
  const bool prism = isPrism(plate) && slanted.empty();
  for (const Loop& loop : cutFace(plate, added, removed)) {
    Loop bottom, top;
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3& point = loop[i];
      bottom.push_back(plus(point, scaled(axis, from)));
      top.push_back(plus(point, scaled(axis, to)));
      if (prism) continue;
      const std::optional<Vec3> slantedTop = slanted.empty() ? std::nullopt : slantedPartner(plate, slanted, point);
      top.back() = slantedTop ? *slantedTop : secondFacePartner(plate, point, cutWallAt(plate, loop, i).get());
    }
    layer.bottom.push_back(bottom);
    layer.top.push_back(top);
  }
  return layer;
}

// The plate with its own cuts: as it was (its solids replaced by the joints') when nothing is cut
// through or into it; else its face cut, and where it has housings, its middle layer with the
// layers at its faces that the housings are cut through attached (their floor is the middle
// layer), then the joints' solids.
Plate cutPlate(const Plate& plate, size_t p, PlateCuts& cuts) {
  const bool housed = !cuts.housings[p][0].empty() || !cuts.housings[p][1].empty();
  const std::vector<std::array<Loop, 2>>& slanted = cuts.slanted[p];
  if (cuts.added[p].empty() && cuts.removed[p].empty() && slanted.empty() && !housed) {
    Plate same = plate;
    same.attached = std::move(cuts.attached[p]);
    return same;
  }
  if (housed && !slanted.empty()) {
    throwBadInput("", "the joints would house " + geometry::plateName(plate) + " where a slanted slot runs through it");
  }
  const std::vector<Loop>& added = cuts.added[p];
  std::vector<Loop> removed = cuts.removed[p];
  for (const std::array<Loop, 2>& cut : slanted) removed.push_back(cut[0]);
  const PlaneFrame frame(plate.bottom[0][0], plateThicknessAxis(plate));
  requireApart(plate, removed, frame);
  const double thickness = plateThickness(plate);
  const double first = cuts.housingDepth[p][0], second = thickness - cuts.housingDepth[p][1];
  Plate jointed = layerOf(plate, added, removed, first, second, slanted);
  for (int face = 0; face < 2; ++face) {
    if (cuts.housings[p][face].empty()) continue;
    std::vector<Loop> through = removed;
    through.insert(through.end(), cuts.housings[p][face].begin(), cuts.housings[p][face].end());
    requireApart(plate, through, frame);
    jointed.attached.push_back(face == 0 ? layerOf(plate, added, through, 0, first)
                                         : layerOf(plate, added, through, second, thickness));
  }
  for (Plate& solid : cuts.attached[p]) jointed.attached.push_back(std::move(solid));
  return jointed;
}

}  // namespace

bool footprintsOverlap(const std::vector<Plate>& plates, const CutFootprint& a, const CutFootprint& b) {
  if (a.plate != b.plate || (a.faces & b.faces) == 0) return false;
  const bool underA = a.kind == FootprintKind::UnderAddedPiece, underB = b.kind == FootprintKind::UnderAddedPiece;
  if (underA && b.kind != FootprintKind::SlotRunningOut) return false;
  if (underB && a.kind != FootprintKind::SlotRunningOut) return false;
  const Plate& plate = plates[a.plate];
  return cutsShareWood(plate, a.region, b.region, PlaneFrame(plate.bottom[0][0], plateThicknessAxis(plate)));
}

CutFootprint woodUnderAddedPiece(int plate, const Vec3& side, const Vec3& along, const Vec3& outward, double start,
                                 double end) {
  constexpr double kDepthMm = 1;
  const Vec3 a = plus(side, scaled(along, start)), b = plus(side, scaled(along, end));
  const Vec3 inward = scaled(outward, -kDepthMm);
  return {plate, 3, {a, b, plus(b, inward), plus(a, inward)}, FootprintKind::UnderAddedPiece};
}

CutFootprint woodUnderPieceOnMitre(const std::vector<Plate>& plates, int plate, const Vec3& root, const Vec3& across,
                                   const Vec3& along, const Vec3& outward, double start, double end) {
  const Plate& onPlate = plates[static_cast<size_t>(plate)];
  const Vec3 axis = plateThicknessAxis(onPlate);
  // Down the mitre face to the first face: where the mitre's edge bounds the first face's outline.
  const double height = dot(minus(root, onPlate.bottom[0][0]), axis), climb = dot(across, axis);
  const Vec3 onFirstFace = std::abs(climb) > tolerance::kDirection ? minus(root, scaled(across, height / climb)) : root;
  Vec3 inPlane = minus(outward, scaled(axis, dot(outward, axis)));
  if (norm(inPlane) < tolerance::kDirection) {  // not a mitre of an edge-to-edge joint: square to the edge
    inPlane = cross(axis, along);
    if (dot(inPlane, outward) < 0) inPlane = negated(inPlane);
  }
  return woodUnderAddedPiece(plate, onFirstFace, along, normalized(inPlane), start, end);
}

PlateCuts::PlateCuts(size_t plateCount)
    : added(plateCount), removed(plateCount), slanted(plateCount), housings(plateCount), housingDepth(plateCount, {0.0, 0.0}),
      attached(plateCount) {}

std::vector<Plate> cutJoints(const std::vector<Plate>& plates, const JointCutList& joints,
                             const JointCutOptions& options) {
  PlateCuts cuts(plates.size());
  for (const std::shared_ptr<const JointCut>& joint : joints) joint->addTo(plates, options, cuts);
  std::vector<Plate> jointed;
  jointed.reserve(plates.size());
  for (size_t p = 0; p < plates.size(); ++p) jointed.push_back(cutPlate(plates[p], p, cuts));
  return jointed;
}

}  // namespace desia
