// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/halved.h"

#include "analysis/vec3.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

class SlotJointCut final : public JointCut {
 public:
  explicit SlotJointCut(const SlotCut& slot) : slot_(slot) {}
  void addTo(const std::vector<Plate>&, const JointCutOptions&, PlateCuts& cuts) const override {
    cuts.removed[slot_.plate].push_back(slot_.rectangle);
  }

 private:
  SlotCut slot_;
};

}  // namespace

std::vector<SlotCut> halvedSlots(const std::vector<Plate>& plates, const PlateContact& crossing, int mover,
                                 const Vec3& d, const JointCutOptions& options) {
  const double clearance = options.clearance;
  const int other = crossing.a == mover ? crossing.b : crossing.a;
  const Vec3& line = crossing.edgeDirection;
  const double sign = dot(d, line) > 0 ? 1 : -1;
  const double middle = (crossing.crossingFrom + crossing.crossingTo) / 2;
  // Far enough past the crossing's ends to run out of the outline there (it ends with the crossing).
  const double out = crossing.crossingTo - crossing.crossingFrom + options.woodMargin;
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

CutFootprint slotFootprint(const SlotCut& slot) { return {slot.plate, 3, slot.rectangle}; }

std::shared_ptr<const JointCut> jointCut(const SlotCut& slot) { return std::make_shared<SlotJointCut>(slot); }

namespace {

class HalvedFamily final : public JointFamily {
 public:
  using JointFamily::JointFamily;

  bool joinsCrossings() const override { return true; }

  // Along the crossing line, and where slots are cut, towards the side where the mover's outline
  // ends at the crossing ahead of it and the other's behind it (its slot opening behind it and
  // the other plate's ahead of it). Any other direction would pull one plate through the other.
  bool lets(int crossing, int mover, const Vec3& d) const override {
    const PlateContact& contact = this->contact(crossing);
    if (!parallel(contact.edgeDirection, d)) return false;
    if (!makesJoints(realization())) return true;
    const bool ahead = dot(d, contact.edgeDirection) > 0;  // which end of the line d points to
    const std::array<bool, 2>& moverOpens = contact.a == mover ? contact.aOpens : contact.bOpens;
    const std::array<bool, 2>& otherOpens = contact.a == mover ? contact.bOpens : contact.aOpens;
    return moverOpens[ahead ? 0 : 1] && otherOpens[ahead ? 1 : 0];
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
