// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/mitre_tenon.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/joints/side_crossings.h"
#include "plate/plan_squaring.h"
#include "plate/plane_frame.h"
#include "plate/plate_shape.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

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
  return slope == 0 ? tenon.halfWidth : tenon.halfWidth + slope * tenon.depth + tenon.endWood;
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
    if (triangle.empty() || std::abs(triangle.back().second - corner.second) > tolerance::kRoundingMm ||
        triangle.back().first != corner.first)
      triangle.push_back(corner);
  }
  if (triangle.size() > 3 && std::abs(triangle.back().second - triangle.front().second) < tolerance::kRoundingMm &&
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
    if (std::abs(slant) > tolerance::kSamePointMm) pieces.push_back(pocketEndWedge(tenon, pocketEnd, straightTo));
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

class MitreTenonCut final : public JointCut {
 public:
  explicit MitreTenonCut(const MitreTenon& tenon) : tenon_(tenon) {}
  void addTo(const std::vector<Plate>& plates, const JointCutOptions& options, PlateCuts& cuts) const override {
    cuts.removed[tenon_.pocketPlate].push_back(pocketNotch(plates, tenon_));
    for (Plate& piece : pocketSurround(plates, tenon_)) cuts.attached[tenon_.pocketPlate].push_back(std::move(piece));
    cuts.attached[tenon_.tenonPlate].push_back(mitreTenonSolid(tenon_, options.clearance));
  }

 private:
  MitreTenon tenon_;
};

}  // namespace

MitreFrame mitreFrame(const MitreTenon& tenon) {
  return {tenon.middle, tenon.across, normalized(cross(tenon.line, tenon.across)), tenon.line};
}

// In the pocket plate's plane, across the edge, away from the mitre into the plate.
Vec3 pocketInward(const std::vector<Plate>& plates, const MitreTenon& tenon) {
  const Vec3 inward = normalized(cross(plateThicknessAxis(plates[tenon.pocketPlate]), tenon.line));
  return dot(inward, mitreFrame(tenon).normal) < 0 ? negated(inward) : inward;
}

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
  const double onMitre = tolerance::kRelativeRounding * big;
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
    throwBadInput("", "the pocket of a mitre joint does not lie on the mitre of " + geometry::plateName(pocket));
  }
  return bitten;
}

namespace {

// The tenon as deep as the pocket plate holds it with a margin of wood on both faces, at most the
// plate's thickness; false where its root itself comes within the margin of a face.
bool setPocketDepth(MitreTenon& tenon, const Plate& pocket, const JointCutOptions& options) {
  const Vec3 axis = plateThicknessAxis(pocket);
  const double thickness = plateThickness(pocket), rate = dot(tenon.into, axis);
  tenon.depth = thickness;
  for (const double side : {-1.0, 1.0}) {
    const double height = dot(minus(plus(tenon.middle, scaled(tenon.across, side * tenon.halfHeight)), pocket.bottom[0][0]), axis);
    if (height < options.woodMargin || height > thickness - options.woodMargin) return false;
    if (rate > tolerance::kDirection)
      tenon.depth = std::min(tenon.depth, (thickness - options.woodMargin - height) / rate);
    if (rate < -tolerance::kDirection) tenon.depth = std::min(tenon.depth, (height - options.woodMargin) / -rate);
  }
  return true;
}

// The notch runs past the pocket and past the mitre (its cut ends where the plate is whole). Past
// the mitre, its end must lie in the pocket plate where it is whole (away from its other sides),
// so that its cut ends in wood: false where it does not.
bool setNotchReach(MitreTenon& tenon, const std::vector<Plate>& plates, const PlateContact& contact,
                   const JointCutOptions& options) {
  const Plate& pocket = plates[tenon.pocketPlate];
  const Vec3 inwardDirection = pocketInward(plates, tenon);
  const MitreFrame sectionFrame = mitreFrame(tenon);
  for (const Flat& q : tenonSection(tenon, sectionFrame, 0))
    tenon.notchReach = std::max(tenon.notchReach, dot(minus(sectionFrame.at(q, 0), tenon.middle), inwardDirection));
  double mitreReach = 0;  // where the mitre ends and the plate is whole again
  for (const Vec3& p : contact.region) mitreReach = std::max(mitreReach, dot(minus(p, tenon.middle), inwardDirection));
  tenon.notchReach = std::max(tenon.notchReach, mitreReach) + options.woodMargin;
  auto at = [&](double s, double u) {
    return plus(tenon.middle, plus(scaled(tenon.line, s), scaled(inwardDirection, u)));
  };
  const double half = notchHalfWidth(tenon);
  const Loop end{at(-half, mitreReach), at(half, mitreReach), at(half, tenon.notchReach), at(-half, tenon.notchReach)};
  const PlaneFrame frame(pocket.bottom[0][0], plateThicknessAxis(pocket));
  return !(areaAgainst({end}, faceRegion(pocket, ClipperLib::ctIntersection), frame, true) > tolerance::kEmptyAreaMm2);
}

}  // namespace

std::optional<MitreTenon> mitreTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                       const Vec3& into, const JointCutOptions& options,
                                       const std::vector<int>& crossers) {
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
  if (std::abs(dot(tenon.into, tenon.line)) > std::sqrt(0.5) + tolerance::kDirection ||
      dot(tenon.into, normal) < tolerance::kGlancingCosine)
    return std::nullopt;
  tenon.across = normalized(cross(normal, tenon.line));
  const auto [sideFrom, sideTo] = extentAlong(contact.region, contact.region[0], tenon.line);
  const auto [x0, x1] = extentAlong(contact.region, contact.region[0], tenon.across);
  const MitreTenonSizes& sizes = options.mitreTenon;
  // Beside the plates crossing both (side_crossings.h; the VDA corner's bars through its hexagons'
  // sides, whose slots are cut there): in the longest stretch they leave free, as far either side
  // of the mitre as the tenon on the whole mitre is wide (its pocket's notch reaches about as far).
  const double reach = sizes.width.of(sideTo - sideFrom) + options.woodMargin + options.clearance;
  const auto [s0, s1] = clearStretchOfSide(plates, crossers, contact.region[0], tenon.line, tenon.into, sideFrom,
                                           sideTo, reach, options.woodMargin + options.clearance);
  tenon.halfWidth = sizes.width.of(s1 - s0) / 2;
  tenon.halfHeight = sizes.height.of(x1 - x0) / 2;  // by default a quarter: room for the pocket in thin plates
  if (2 * tenon.halfWidth < options.shortestJoint || 2 * tenon.halfHeight < sizes.lowestRoot) return std::nullopt;
  tenon.middle = plus(contact.region[0], plus(scaled(tenon.line, (s0 + s1) / 2), scaled(tenon.across, (x0 + x1) / 2)));
  if (!setPocketDepth(tenon, pocket, options) || tenon.depth < sizes.shallowestPocket) return std::nullopt;
  // An oblique tenon's notch runs further along the edge: it must stay on the mitre.
  tenon.endWood = options.woodMargin;
  if (notchHalfWidth(tenon) > (s1 - s0) / 2 - options.woodMargin) {
    tenon.halfWidth -= notchHalfWidth(tenon) - ((s1 - s0) / 2 - options.woodMargin);
    if (2 * tenon.halfWidth < options.shortestJoint) return std::nullopt;
  }
  if (!setNotchReach(tenon, plates, contact, options)) return std::nullopt;
  return tenon;
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

std::shared_ptr<const JointCut> jointCut(const MitreTenon& tenon) { return std::make_shared<MitreTenonCut>(tenon); }

namespace {

class MitreTenonFamily final : public JointFamily {
 public:
  explicit MitreTenonFamily(const JointSetting& setting) : JointFamily(setting) {
    const MitreTenonSizes& sizes = options().mitreTenon;
    requireShare(sizes.width, "mitreTenon.width");
    requireShare(sizes.height, "mitreTenon.height");
    requireAtLeast(sizes.lowestRoot, 0, "mitreTenon.lowestRoot");
    requireAtLeast(sizes.shallowestPocket, 0, "mitreTenon.shallowestPocket");
    for (const PlateContact& contact : graph().contacts) crossers_.push_back(platesCrossingBoth(graph(), contact));
  }

  bool lets(int contact, int mover, const Vec3& d) const override {
    return mitreTenonOf(plates(), this->contact(contact), mover, negated(d), options(),
                        crossers_[static_cast<size_t>(contact)])
        .has_value();
  }

  // Straight away from a plate it meets at a mitre (a mitre tenon's way out; every touching
  // contact gives one), made square to the plates around it that it all but lies along: a
  // mitre's normal computed from its face is off by 5e-9, and a plate leaving so along another's
  // face would have its tenon's faces in that plate's pocket tilted by as much against every other
  // way out in that plane.
  void addWaysOut(int contact, int plate, std::vector<Vec3>& ways) const override {
    const PlateContact& touching = this->contact(contact);
    if (touching.crossing) return;
    std::vector<Vec3> axes{graph().thicknessAxis[plate]};
    for (int other : graph().neighbours[plate]) axes.push_back(graph().thicknessAxis[other]);
    ways.push_back(squaredToNearlySquare(touching.normal, axes));
  }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    return mitreTenonFaceNormals(tenonOf(joint));
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    const MitreTenon tenon = tenonOf(joint);
    footprints.push_back(mitreTenonFootprint(plates(), tenon));
    // The tenon stands on the mitre, along the edge: the wood under it.
    footprints.push_back(woodUnderPieceOnMitre(plates(), tenon.tenonPlate, tenon.middle, tenon.across, tenon.line,
                                               mitreFrame(tenon).normal, -tenon.halfWidth, tenon.halfWidth));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(tenonOf(joint)));
  }

 private:
  MitreTenon tenonOf(const PlateJoint& joint) const {
    return letJointSite(mitreTenonOf(plates(), contact(joint.contact), joint.mover, negated(joint.direction), options(),
                                     crossers_[static_cast<size_t>(joint.contact)]),
                        "mitre-tenon");
  }
  std::vector<std::vector<int>> crossers_;  // per contact: the plates crossing both of its plates
};

}  // namespace

std::unique_ptr<JointFamily> makeMitreTenonFamily(const JointSetting& setting) {
  return std::make_unique<MitreTenonFamily>(setting);
}

}  // namespace desia
