// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/halved.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/vec3.h"
#include "desia/tolerances.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

class SlotJointCut final : public JointCut {
 public:
  explicit SlotJointCut(const SlotCut& slot) : slot_(slot) {}
  void addTo(const std::vector<Plate>&, const JointCutOptions&, PlateCuts& cuts) const override {
    if (slot_.secondFace.empty())
      cuts.removed[slot_.plate].push_back(slot_.rectangle);
    else
      cuts.slanted[slot_.plate].push_back({slot_.rectangle, slot_.secondFace});
  }

 private:
  SlotCut slot_;
};

// The slot through `plate` where `across` passes through it at an angle, from `start` to `end`
// along the crossing line: at height h across the plate (0 on its first face, which holds the
// crossing point), a point s along `across` (in the plate, square to the line) lies
// h * cosine + s * rise into the other plate's slab; the slot keeps that within the slab widened
// by half the clearance on each side, so its walls lie in the other plate's face planes.
SlotCut slantedSlot(const std::vector<Plate>& plates, const PlateContact& crossing, int plate, int across,
                    double start, double end, double clearance) {
  const Vec3 axis = plateThicknessAxis(plates[plate]), otherAxis = plateThicknessAxis(plates[across]);
  const double thickness = plateThickness(plates[plate]), width = plateThickness(plates[across]);
  const double cosine = dot(axis, otherAxis);
  const Vec3 towards = normalized(minus(otherAxis, scaled(axis, cosine)));
  const double rise = dot(towards, otherAxis);
  auto at = [&](double h, double t, double depth) {
    const double s = (depth - h * cosine) / rise;
    return plus(crossing.crossingPoint,
                plus(scaled(axis, h), plus(scaled(crossing.edgeDirection, t), scaled(towards, s))));
  };
  auto face = [&](double h) {
    return Loop{at(h, start, -clearance / 2), at(h, end, -clearance / 2), at(h, end, width + clearance / 2),
                at(h, start, width + clearance / 2)};
  };
  return SlotCut{plate, face(0), face(thickness)};
}

}  // namespace

std::vector<SlotCut> halvedSlots(const std::vector<Plate>& plates, const PlateContact& crossing, int mover,
                                 const Vec3& d, const JointCutOptions& options) {
  const double clearance = options.clearance;
  const int other = crossing.a == mover ? crossing.b : crossing.a;
  const Vec3& line = crossing.edgeDirection;
  const double sign = dot(d, line) > 0 ? 1 : -1;
  const double middle = (crossing.crossingFrom + crossing.crossingTo) / 2;
  // Far enough past the crossing's ends to run out of the outline there: it ends with the
  // crossing, or tapers past it by at most the slot's width (halvedSlotsOpen), measured on the
  // core prism of a plate with bevelled sides, whose faces may reach as far again.
  const double widest = std::max(slotWidthOn(plates, crossing, crossing.a), slotWidthOn(plates, crossing, crossing.b));
  const double out = std::max(crossing.crossingTo - crossing.crossingFrom, 2 * widest) + options.woodMargin;
  auto slot = [&](int plate, int across, double towards) {
    const Vec3 axis = plateThicknessAxis(plates[across]);
    const double width = plateThickness(plates[across]);
    if (needsSlantedNotchWalls(plates, crossing)) {
      return slantedSlot(plates, crossing, plate, across, middle, towards > 0 ? crossing.crossingTo + out
                                                                             : crossing.crossingFrom - out,
                         clearance);
    }
    // From the middle of the crossing out past its end `towards` (+1: +line), across the other
    // plate's thickness (its first face is on crossingPoint's plane) plus the clearance.
    const double start = middle, end = towards > 0 ? crossing.crossingTo + out : crossing.crossingFrom - out;
    auto at = [&](double t, double w) { return plus(crossing.crossingPoint, plus(scaled(line, t), scaled(axis, w))); };
    return SlotCut{plate,
                   {at(start, -clearance / 2), at(end, -clearance / 2), at(end, width + clearance / 2),
                    at(start, width + clearance / 2)},
                   {}};
  };
  // The mover's slot opens behind it (it slides off the other plate forwards); the other's ahead.
  return {slot(mover, other, -sign), slot(other, mover, sign)};
}

double slotWidthOn(const std::vector<Plate>& plates, const PlateContact& crossing, int plate) {
  const int other = crossing.a == plate ? crossing.b : crossing.a;
  const Vec3 axis = plateThicknessAxis(plates[static_cast<size_t>(plate)]);
  const Vec3 otherAxis = plateThicknessAxis(plates[static_cast<size_t>(other)]);
  // The other's slab meets this plate's first and second faces in strips `width` wide, shifted
  // by thickness * cosine / rise against each other (slantedSlot's geometry).
  const double cosine = dot(axis, otherAxis);
  const double rise = std::sqrt(std::max(0.0, 1 - cosine * cosine));
  return (plateThickness(plates[static_cast<size_t>(other)]) +
          plateThickness(plates[static_cast<size_t>(plate)]) * std::abs(cosine)) /
         rise;
}

bool halvedSlotsOpen(const std::vector<Plate>& plates, const PlateContact& crossing, int mover, const Vec3& d) {
  const bool ahead = dot(d, crossing.edgeDirection) > 0;  // which end of the line d points to
  const int other = crossing.a == mover ? crossing.b : crossing.a;
  auto opens = [&](int plate, size_t end) {
    const bool isA = crossing.a == plate;
    if ((isA ? crossing.aOpens : crossing.bOpens)[end]) return true;
    return (isA ? crossing.aOverhang : crossing.bOverhang)[end] <= slotWidthOn(plates, crossing, plate);
  };
  return opens(mover, ahead ? 0 : 1) && opens(other, ahead ? 1 : 0);
}

bool needsSlantedNotchWalls(const std::vector<Plate>& plates, const PlateContact& crossing) {
  const double cosine = dot(plateThicknessAxis(plates[static_cast<size_t>(crossing.a)]),
                            plateThicknessAxis(plates[static_cast<size_t>(crossing.b)]));
  // The notch walls follow the other plate's faces, leaning across the plate by its thickness
  // times the cosine; within the contact tolerance a wall square to the sheet is that wall (a CAD
  // file's 89.9994 degrees: 0.0002 mm across 18 mm), so a laser cuts it.
  const double thickness = std::max(plateThickness(plates[static_cast<size_t>(crossing.a)]),
                                    plateThickness(plates[static_cast<size_t>(crossing.b)]));
  return std::abs(cosine) * thickness > tolerance::kContactMm;
}

std::string slantedCrossingsNeedMilling(const PlateGraph& graph) {
  for (const PlateContact& contact : graph.contacts) {
    if (!contact.crossing || !needsSlantedNotchWalls(graph.plates, contact)) continue;
    const double cosine = std::min(1.0, std::abs(dot(graph.thicknessAxis[static_cast<size_t>(contact.a)],
                                                     graph.thicknessAxis[static_cast<size_t>(contact.b)])));
    char angle[32];
    const double degrees = std::acos(cosine) * 180 / M_PI;
    std::snprintf(angle, sizeof angle, "%.1f", degrees);
    // Off square by less than the rounding (a CAD file's 89.97 degrees): say so, not "90.0".
    if (std::string(angle) == "90.0") std::snprintf(angle, sizeof angle, "%.4f", degrees);
    return "the crossing of plates " + std::to_string(graph.plates[static_cast<size_t>(contact.a)].id) + " and " +
           std::to_string(graph.plates[static_cast<size_t>(contact.b)].id) + " at " + angle +
           " degrees needs slanted notch walls, which a laser cutting square to the sheet cannot make: mill them "
           "(joints 'milled')";
  }
  return "";
}

CutFootprint slotFootprint(const SlotCut& slot) {
  if (slot.secondFace.empty()) return {slot.plate, 3, slot.rectangle, FootprintKind::SlotRunningOut};
  // The second face's parallelogram seen along the axis is the first's shifted across the line
  // (vertices 0-1 and 2-3 are its sides along the line, at the other plate's two faces): the
  // union spans from the lower of the two first sides to the higher of the two second sides.
  const Loop& first = slot.rectangle;
  const Vec3 across = minus(first[3], first[0]);
  const Vec3 axis = normalized(cross(minus(first[1], first[0]), across));
  const Vec3 lift = minus(slot.secondFace[0], first[0]);
  const Vec3 shift = minus(lift, scaled(axis, dot(lift, axis)));
  const bool higher = dot(shift, across) > 0;
  const Vec3 low = higher ? Vec3{0, 0, 0} : shift, high = higher ? shift : Vec3{0, 0, 0};
  return {slot.plate, 3, {plus(first[0], low), plus(first[1], low), plus(first[2], high), plus(first[3], high)},
          FootprintKind::SlotRunningOut};
}

std::shared_ptr<const JointCut> jointCut(const SlotCut& slot) { return std::make_shared<SlotJointCut>(slot); }

namespace {

class HalvedFamily final : public JointFamily {
 public:
  using JointFamily::JointFamily;

  bool joinsCrossings() const override { return true; }

  // Along the crossing line, and where slots are cut, only where they can open (halvedSlotsOpen).
  // Any other direction would pull one plate through the other.
  bool lets(int crossing, int mover, const Vec3& d) const override {
    const PlateContact& contact = this->contact(crossing);
    if (!parallel(contact.edgeDirection, d)) return false;
    if (!makesJoints(realization())) return true;
    if (realization() == JointRealization::Cut && needsSlantedNotchWalls(plates(), contact)) return false;
    return halvedSlotsOpen(plates(), contact, mover, d);
  }

  // The planned model: the plates cross, so they have no faces on one another but the slots'.
  std::vector<Vec3> faceNormals(const PlateJoint& joint) const override {
    return plannedJointNormals(graph().thicknessAxis[static_cast<size_t>(joint.mover)], joint.direction);
  }
  bool keepsOtherContacts() const override { return false; }

  void addFootprints(const PlateJoint& joint, std::vector<CutFootprint>& footprints) const override {
    JointCutOptions unplayed = options();
    unplayed.clearance = 0;
    for (const SlotCut& slot : halvedSlots(plates(), contact(joint.contact), joint.mover, joint.direction, unplayed))
      footprints.push_back(slotFootprint(slot));
  }

  void addCuts(const PlateJoint& joint, double clearance, JointCutList& cuts) const override {
    JointCutOptions played = options();
    played.clearance = clearance;
    for (const SlotCut& slot : halvedSlots(plates(), contact(joint.contact), joint.mover, joint.direction, played))
      cuts.push_back(jointCut(slot));
  }
};

}  // namespace

std::unique_ptr<JointFamily> makeHalvedFamily(const JointSetting& setting) {
  return std::make_unique<HalvedFamily>(setting);
}

}  // namespace desia
