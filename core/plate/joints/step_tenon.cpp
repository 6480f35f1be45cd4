// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/step_tenon.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

// The part of a convex section where a . p <= c (one half-plane of Sutherland-Hodgman).
Section keepBelow(const Section& section, const SectionPoint& a, double c) {
  Section kept;
  for (size_t i = 0; i < section.size(); ++i) {
    const SectionPoint& p = section[i];
    const SectionPoint& q = section[(i + 1) % section.size()];
    const double sp = a[0] * p[0] + a[1] * p[1] - c, sq = a[0] * q[0] + a[1] * q[1] - c;
    if (sp <= 0) kept.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      kept.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return kept;
}

double sectionArea(const Section& section) {
  double twice = 0;
  for (size_t i = 0; i < section.size(); ++i) {
    const SectionPoint& p = section[i];
    const SectionPoint& q = section[(i + 1) % section.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return std::abs(twice) / 2;
}

SectionPoint flat(const StepTenon& tenon, const Vec3& v) { return {dot(v, tenon.inward), dot(v, tenon.up)}; }

Vec3 at(const StepTenon& tenon, double x, double y, double s) {
  return plus(tenon.origin, plus(scaled(tenon.inward, x), plus(scaled(tenon.up, y), scaled(tenon.line, s))));
}

// Heights of a plate's two face planes along `axis`, from `origin`, lower first.
std::pair<double, double> faceHeights(const Plate& plate, const Vec3& origin, const Vec3& axis) {
  const double first = dot(minus(plate.bottom[0][0], origin), axis), second = dot(minus(plate.top[0][0], origin), axis);
  return {std::min(first, second), std::max(first, second)};
}

// A section swept along the edge from s0 to s1.
Plate prismAlongEdge(const StepTenon& tenon, const Section& section, double s0, double s1) {
  Loop first, second;
  for (const SectionPoint& q : section) {
    first.push_back(at(tenon, q[0], q[1], s0));
    second.push_back(at(tenon, q[0], q[1], s1));
  }
  return solidOf(first, second);
}

// Between the wall (x = wall + inset) and the mitre, from height y0 to y1, along the edge
// between s = from(x) and s = to(x) (straight in x): a solid whose faces are the two heights and
// whose sides are the wall, the mitre and the two ends.
template <typename From, typename To>
Plate betweenWallAndMitre(const StepTenon& tenon, double inset, double y0, double y1, From from, To to) {
  auto loopAt = [&](double y) {
    const double x0 = tenon.wall + inset, x1 = tenon.mitreAt(y);
    return Loop{at(tenon, x0, y, from(x0)), at(tenon, x1, y, from(x1)), at(tenon, x1, y, to(x1)),
                at(tenon, x0, y, to(x0))};
  };
  return solidOf(loopAt(y0), loopAt(y1));
}

// Where the tenon at side `side` (-1: towards -line, +1: towards +line) ends at x: its inner end
// (towards the middle) and its outer end, flaring outwards towards the root.
double innerEnd(const StepTenon& tenon, double side, double x) {
  return side * (tenon.gap / 2 + tenon.flare * (x - tenon.wall));
}
double outerEnd(const StepTenon& tenon, double side, double x) {
  return side * (tenon.halfWidth + tenon.flare * (x - tenon.wall));
}

Loop notchLoop(const StepTenon& tenon) {
  auto onPlane = [&](double s, double u) {
    return plus(tenon.origin, plus(scaled(tenon.line, s), scaled(tenon.notchInward, u)));
  };
  const double out = -tenon.notchReach, half = tenon.notchHalf;  // beyond the mitre, out of the plate
  return {onPlane(-half, out), onPlane(half, out), onPlane(half, tenon.notchReach), onPlane(-half, tenon.notchReach)};
}

class StepTenonCut final : public JointCut {
 public:
  explicit StepTenonCut(const StepTenon& tenon) : tenon_(tenon) {}
  void addTo(const std::vector<Plate>&, const JointCutOptions& options, PlateCuts& cuts) const override {
    cuts.removed[tenon_.pocketPlate].push_back(notchLoop(tenon_));
    for (Plate& piece : stepTenonPocketWood(tenon_)) cuts.attached[tenon_.pocketPlate].push_back(std::move(piece));
    for (Plate& piece : stepTenonSolids(tenon_, options.clearance / 2))
      cuts.attached[tenon_.tenonPlate].push_back(std::move(piece));
  }

 private:
  StepTenon tenon_;
};

double degreesBetweenPlanes(const Vec3& axisA, const Vec3& axisB) {
  return std::acos(std::min(1.0, std::abs(dot(axisA, axisB)))) * 180 / M_PI;
}

// A square wide enough to hold the joint's section, to clip from.
Section around(double size) { return {{-size, -size}, {size, -size}, {size, size}, {-size, size}}; }

// The highest point of a convex section on the line x = wall.
double heightAtWall(const Section& section, double wall) {
  double highest = -INFINITY;
  for (size_t i = 0; i < section.size(); ++i) {
    const SectionPoint& p = section[i];
    const SectionPoint& q = section[(i + 1) % section.size()];
    if ((p[0] - wall) * (q[0] - wall) > 0) continue;
    const double t = p[0] == q[0] ? 0 : (wall - p[0]) / (q[0] - p[0]);
    highest = std::max({highest, p[1] + t * (q[1] - p[1]), p[0] == q[0] ? q[1] : -INFINITY});
  }
  return highest;
}

// The section's frame and the two slabs; false where they do not overlap beyond the mitre.
bool setSection(StepTenon& tenon, const Plate& tenonSlab, const Plate& pocketSlab, double span) {
  const Vec3 upB = dot(plateThicknessAxis(pocketSlab), tenon.up) < 0 ? negated(plateThicknessAxis(pocketSlab))
                                                                      : plateThicknessAxis(pocketSlab);
  std::tie(tenon.floor, tenon.top) = faceHeights(tenonSlab, tenon.origin, tenon.up);
  const auto [bLow, bHigh] = faceHeights(pocketSlab, tenon.origin, upB);
  const SectionPoint b = flat(tenon, upB), m = flat(tenon, tenon.mitre);
  Section pocketSide = keepBelow(keepBelow(around(span), b, bHigh), {-b[0], -b[1]}, -bLow);
  pocketSide = keepBelow(pocketSide, {-m[0], -m[1]}, 0);  // beyond the mitre
  tenon.overlap = keepBelow(keepBelow(pocketSide, {0, 1}, tenon.top), {0, -1}, -tenon.floor);
  tenon.pocketWood = pocketSide;
  return tenon.overlap.size() >= 3 && sectionArea(tenon.overlap) > tolerance::kEmptyAreaMm2;
}

}  // namespace

double StepTenon::mitreAt(double y) const {
  const SectionPoint m = flat(*this, mitre);
  return root - m[1] * (y - floor) / m[0];
}

std::optional<StepTenon> stepTenonOf(const std::vector<Plate>& plates, const PlateContact& contact, int tenonPlate,
                                     const JointCutOptions& options) {
  const std::optional<int> partner = touchingPartnerOf(contact, tenonPlate);
  if (!partner || facesOnContact(plates, contact) != 0) return std::nullopt;  // edge to edge only
  const StepTenonSizes& sizes = options.stepTenon;
  const Plate& tenonSlab = plates[static_cast<size_t>(tenonPlate)];
  const Plate& pocketSlab = plates[static_cast<size_t>(*partner)];
  const Vec3 axisA = plateThicknessAxis(tenonSlab), axisB = plateThicknessAxis(pocketSlab);
  const double degrees = degreesBetweenPlanes(axisA, axisB);
  if (degrees < sizes.leastDegrees || degrees > sizes.mostDegrees) return std::nullopt;
  StepTenon tenon;
  tenon.tenonPlate = tenonPlate;
  tenon.pocketPlate = *partner;
  tenon.line = normalized(contact.edgeDirection);
  tenon.mitre = contact.a == tenonPlate ? contact.normal : negated(contact.normal);
  tenon.inward = normalized(cross(axisA, tenon.line));
  if (dot(tenon.inward, tenon.mitre) > 0) tenon.inward = negated(tenon.inward);
  tenon.notchInward = normalized(cross(axisB, tenon.line));
  if (dot(tenon.notchInward, tenon.mitre) < 0) tenon.notchInward = negated(tenon.notchInward);
  tenon.up = dot(axisA, tenon.notchInward) > 0 ? negated(axisA) : axisA;
  // The stretch: the middle share of the mitre along the edge, centred across it.
  const auto [s0, s1] = extentAlong(contact.region, contact.region[0], tenon.line);
  const Vec3 across = normalized(cross(tenon.mitre, tenon.line));
  const auto [x0, x1] = extentAlong(contact.region, contact.region[0], across);
  tenon.origin = plus(contact.region[0], plus(scaled(tenon.line, (s0 + s1) / 2), scaled(across, (x0 + x1) / 2)));
  const double span = 10 * (plateThickness(tenonSlab) + plateThickness(pocketSlab) + (x1 - x0));
  if (!setSection(tenon, tenonSlab, pocketSlab, span)) return std::nullopt;
  double farthest = tenon.overlap[0][0];  // x where the slabs part, and where the mitre meets the floor
  tenon.root = farthest;
  for (const SectionPoint& q : tenon.overlap) farthest = std::min(farthest, q[0]), tenon.root = std::max(tenon.root, q[0]);
  tenon.wall = tenon.root - sizes.reach.of(tenon.root - farthest);
  tenon.tenonTop = tenon.floor + sizes.height.of(heightAtWall(tenon.overlap, tenon.wall) - tenon.floor);
  tenon.halfWidth = sizes.width.of(s1 - s0) / 2;
  tenon.gap = sizes.gap.of(2 * tenon.halfWidth);
  tenon.flare = sizes.flare;
  tenon.notchHalf = tenon.halfWidth + tenon.flare * (tenon.root - tenon.wall) + options.woodMargin;
  const double eachTenon = tenon.halfWidth - tenon.gap / 2;
  if (eachTenon < options.shortestJoint || tenon.notchHalf > (s1 - s0) / 2 - options.woodMargin ||
      tenon.tenonTop - tenon.floor < options.shortestJoint / 2)
    return std::nullopt;
  // The notch runs past the pocket and the mitre's end in the pocket plate, by the margin and
  // the plate's thickness (where it is whole again).
  const SectionPoint u = flat(tenon, tenon.notchInward);
  for (const SectionPoint& q : tenon.overlap) tenon.notchReach = std::max(tenon.notchReach, u[0] * q[0] + u[1] * q[1]);
  for (const Vec3& p : contact.region)
    tenon.notchReach = std::max(tenon.notchReach, dot(minus(p, tenon.origin), tenon.notchInward));
  tenon.notchReach += options.woodMargin + plateThickness(pocketSlab);
  tenon.pocketWood = keepBelow(tenon.pocketWood, u, tenon.notchReach);
  return tenon;
}

std::vector<Plate> stepTenonSolids(const StepTenon& tenon, double play) {
  std::vector<Plate> solids;
  for (const double side : {-1.0, 1.0}) {
    auto inner = [&](double x) { return innerEnd(tenon, side, x) + side * play; };
    auto outer = [&](double x) { return outerEnd(tenon, side, x) - side * play; };
    solids.push_back(betweenWallAndMitre(tenon, play, tenon.floor + play, tenon.tenonTop, inner, outer));
  }
  return solids;
}

std::vector<Plate> stepTenonPocketWood(const StepTenon& tenon) {
  const double half = tenon.notchHalf;
  // Around the pocket, prisms along the edge: in front of its wall, beneath its floor, above the
  // tenon plate's slab.
  std::vector<Plate> wood;
  const Section front = keepBelow(tenon.pocketWood, {1, 0}, tenon.wall);
  const Section behind = keepBelow(tenon.pocketWood, {-1, 0}, -tenon.wall);
  const Section beneath = keepBelow(behind, {0, 1}, tenon.floor), above = keepBelow(behind, {0, -1}, -tenon.top);
  for (const Section* piece : {&front, &beneath, &above}) {
    if (piece->size() >= 3 && sectionArea(*piece) > tolerance::kEmptyAreaMm2)
      wood.push_back(prismAlongEdge(tenon, *piece, -half, half));
  }
  // Beside the tenons up to their tops (above them the pocket is open): outside each, and the
  // wedge between them.
  auto constant = [](double s) { return [s](double) { return s; }; };
  auto end = [&](double side, bool inner) {
    return [&tenon, side, inner](double x) { return inner ? innerEnd(tenon, side, x) : outerEnd(tenon, side, x); };
  };
  wood.push_back(betweenWallAndMitre(tenon, 0, tenon.floor, tenon.tenonTop, constant(-half), end(-1, false)));
  wood.push_back(betweenWallAndMitre(tenon, 0, tenon.floor, tenon.tenonTop, end(-1, true), end(1, true)));
  wood.push_back(betweenWallAndMitre(tenon, 0, tenon.floor, tenon.tenonTop, end(1, false), constant(half)));
  return wood;
}

std::vector<Vec3> stepTenonFaceNormals(const StepTenon& tenon) {
  // Each tenon's ends flare: from it into the pocket plate, its inner end's normal points to the
  // middle and towards the root (+inward), its outer end's outwards and towards the wall.
  std::vector<Vec3> normals{negated(tenon.inward), negated(tenon.up), tenon.mitre};
  for (const double side : {-1.0, 1.0}) {
    normals.push_back(normalized(plus(scaled(tenon.line, -side), scaled(tenon.inward, tenon.flare))));
    normals.push_back(normalized(plus(scaled(tenon.line, side), scaled(tenon.inward, -tenon.flare))));
  }
  return normals;
}

CutFootprint stepTenonFootprint(const StepTenon& tenon) { return {tenon.pocketPlate, 3, notchLoop(tenon)}; }

std::shared_ptr<const JointCut> jointCut(const StepTenon& tenon) { return std::make_shared<StepTenonCut>(tenon); }

namespace {

bool letsAlong(const std::vector<Vec3>& normals, const Vec3& d) {
  for (const Vec3& n : normals) {
    if (dot(d, n) > tolerance::kDirection) return false;
  }
  return true;
}

class StepTenonFamily final : public JointFamily {
 public:
  explicit StepTenonFamily(const JointSetting& setting) : JointFamily(setting) {
    const StepTenonSizes& sizes = options().stepTenon;
    requireShare(sizes.width, "stepTenon.width");
    requireShare(sizes.reach, "stepTenon.reach");
    requireShare(sizes.height, "stepTenon.height", true);
    requireShare(sizes.gap, "stepTenon.gap");
    requireAtLeast(sizes.flare, 0, "stepTenon.flare");
    requireAtLeast(sizes.leastDegrees, 1, "stepTenon.leastDegrees");
    requireAtLeast(sizes.mostDegrees, sizes.leastDegrees, "stepTenon.mostDegrees");
  }

  // The tenons on the mover (it leaves off the pocket along its axis), or on the other plate (the
  // mover's pocket leaves the tenons: the way out reversed).
  bool lets(int contact, int mover, const Vec3& d) const override { return tenonOf(contact, mover, d).has_value(); }

  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    const StepTenon tenon = *tenonOf(joint.contact, joint.mover, joint.direction);
    std::vector<Vec3> normals = stepTenonFaceNormals(tenon);
    if (tenon.tenonPlate != joint.mover) {
      for (Vec3& n : normals) n = negated(n);
    }
    return normals;
  }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    footprints.push_back(stepTenonFootprint(*tenonOf(joint.contact, joint.mover, joint.direction)));
  }

  void addCuts(const PlateJoint& joint, double, JointCutList& cuts) const override {
    cuts.push_back(jointCut(*tenonOf(joint.contact, joint.mover, joint.direction)));
  }

 private:
  std::optional<StepTenon> tenonOf(int contact, int mover, const Vec3& d) const {
    const PlateContact& touching = this->contact(contact);
    if (touching.crossing) return std::nullopt;
    std::optional<StepTenon> onMover = stepTenonOf(plates(), touching, mover, options());
    if (onMover && letsAlong(stepTenonFaceNormals(*onMover), d)) return onMover;
    const std::optional<int> other = touchingPartnerOf(touching, mover);
    if (!other) return std::nullopt;
    std::optional<StepTenon> onOther = stepTenonOf(plates(), touching, *other, options());
    if (onOther && letsAlong(stepTenonFaceNormals(*onOther), negated(d))) return onOther;
    return std::nullopt;
  }
};

}  // namespace

std::unique_ptr<JointFamily> makeStepTenonFamily(const JointSetting& setting) {
  return std::make_unique<StepTenonFamily>(setting);
}

}  // namespace desia
